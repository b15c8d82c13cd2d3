// `npm run build:package` (and `npm pack`, through prepack): the npm package's lib/ beside the built web
// app in dist/ (run `npm run build` first). lib/index.js is the planner API for bundlers and browsers,
// lib/node.js the same for Node with the package's own files; the WASM module sits beside them, where the
// wasm-bindgen glue looks for it (`new URL("foon_wasm_bg.wasm", import.meta.url)`, which bundlers follow);
// lib/types/ holds the declarations. Package layout and exports: package.json, README "Embed it".

import { execFileSync } from "node:child_process";
import { copyFileSync, existsSync, rmSync } from "node:fs";
import { join } from "node:path";
import { build } from "vite";
import { ROOT, WASM_PATH } from "../src/planner/node";

const LIB = join(ROOT, "lib");

for (const needed of ["dist/foon-planner.js", "dist/widget.html", "dist/kb/default.foon"]) {
  if (!existsSync(join(ROOT, needed))) throw new Error(`${needed} is missing: run \`npm run build\` before packing`);
}
rmSync(LIB, { recursive: true, force: true });

// An SSR build: Vite leaves `new URL(…, import.meta.url)` as written (a client build would move the files).
await build({
  configFile: false,
  root: ROOT,
  publicDir: false,
  logLevel: "warn",
  build: {
    ssr: true,
    outDir: LIB,
    emptyOutDir: false,
    target: "es2022",
    minify: false,
    rolldownOptions: {
      input: { index: join(ROOT, "src/planner/index.ts"), node: join(ROOT, "src/package/node.ts") },
      external: [/^node:/],
      preserveEntrySignatures: "strict",
      output: { format: "es", entryFileNames: "[name].js", chunkFileNames: "[name]-[hash].js" },
    },
  },
  ssr: { noExternal: true },
});
copyFileSync(WASM_PATH, join(LIB, "foon_wasm_bg.wasm"));
execFileSync(join(ROOT, "node_modules/.bin/tsc"), ["-p", join(ROOT, "scripts/tsconfig.package.json")], { stdio: "inherit" });
console.error(`${LIB}: index.js, node.js, foon_wasm_bg.wasm, types/`);
