import { fileURLToPath } from "node:url";
import { defineConfig } from "vitest/config";
import { serviceWorkerManifest } from "./src/worker/sw-build.ts";

const here = (path: string): string => fileURLToPath(new URL(path, import.meta.url));

/** Entries with a fixed name at the top of dist/: the service worker (its scope is its folder) and the widget. */
const STABLE_ENTRIES = new Set(["sw", "foon-planner"]);

// Pages live in src/ (the project's top level stays as fixed); static assets in public/.
// Relative base: the built app works from any static sub-path and offline.
export default defineConfig({
  root: here("src"),
  publicDir: here("public"),
  base: "./",
  plugins: [serviceWorkerManifest()],
  build: {
    target: "es2022",
    outDir: here("dist"),
    emptyOutDir: true,
    assetsInlineLimit: 0, // keep the wasm, knowledge base and embedding table as separate cacheable files
    rollupOptions: {
      input: {
        main: here("src/index.html"),
        embed: here("src/embed.html"),
        workbench: here("src/workbench.html"),
        author: here("src/author.html"),
        "widget-page": here("src/widget.html"),
        // the embeddable widget keeps a stable name at the top, for pages on other hosts to link to
        "foon-planner": here("src/widget/index.ts"),
        // the service worker keeps a fixed name at the top (its scope is the folder it is served from)
        sw: here("src/worker/service-worker.ts"),
      },
      // foon-planner.js keeps its exports (mount, ...); the pages' entries have none
      preserveEntrySignatures: "exports-only",
      output: {
        entryFileNames: (chunk) => (STABLE_ENTRIES.has(chunk.name) ? `${chunk.name}.js` : "assets/[name]-[hash].js"),
      },
    },
  },
  worker: { format: "es" },
  server: { host: "127.0.0.1" },
  preview: { host: "127.0.0.1" },
  test: {
    root: here("."),
    include: ["tests/unit/**/*.test.ts"],
    environment: "node",
  },
});
