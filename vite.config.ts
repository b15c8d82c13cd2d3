import { defineConfig } from "vitest/config";

// Relative base: the built app works from any static sub-path and from file-less offline caches.
export default defineConfig({
  base: "./",
  build: {
    target: "es2022",
    outDir: "dist",
    assetsInlineLimit: 0, // keep the wasm, knowledge base and embedding table as separate cacheable files
  },
  worker: { format: "es" },
  server: { host: "127.0.0.1" },
  preview: { host: "127.0.0.1" },
  test: {
    include: ["tests/unit/**/*.test.ts"],
    environment: "node",
  },
});
