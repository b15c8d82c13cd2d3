// Build step (Node, used by vite.config.ts): after the bundle is written, fills the service worker's
// precache list and version with every file of dist/ it needs (not the starter KB's loose files, which
// the bundled default.foon already contains).

import { createHash } from "node:crypto";
import { readdirSync, readFileSync, statSync, writeFileSync } from "node:fs";
import { join, relative, sep } from "node:path";
import type { Plugin } from "vite";

function walk(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? walk(path) : [path];
  });
}

/** Files the offline app needs, relative to dist/ with "/" separators. */
export function precacheFiles(outDir: string): string[] {
  return walk(outDir)
    .map((path) => relative(outDir, path).split(sep).join("/"))
    .filter((path) => path !== "sw.js" && !path.endsWith(".map") && !path.startsWith("kb/starter/") && !path.endsWith(".md") && !path.endsWith(".sha256"))
    .sort();
}

export function serviceWorkerManifest(): Plugin {
  let outDir = "dist";
  return {
    name: "foon-service-worker-manifest",
    apply: "build",
    configResolved(config) {
      outDir = config.build.outDir;
    },
    writeBundle() {
      const swPath = join(outDir, "sw.js");
      const files = precacheFiles(outDir);
      const hash = createHash("sha256");
      for (const file of files) hash.update(file).update(readFileSync(join(outDir, file)));
      const version = hash.digest("hex").slice(0, 16);
      const manifest = Buffer.from(JSON.stringify(files)).toString("base64");
      const source = readFileSync(swPath, "utf8");
      if (!source.includes("__FOON_SW_MANIFEST__")) throw new Error("sw.js: manifest placeholder not found");
      writeFileSync(swPath, source.replace("__FOON_SW_MANIFEST__", manifest).replace("__FOON_SW_VERSION__", version));
    },
  };
}
