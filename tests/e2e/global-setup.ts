// Serves the built app (dist/, or $E2E_DIST) with Vite's preview server on 127.0.0.1 for the whole e2e run.
import { existsSync } from "node:fs";
import { join } from "node:path";
import { preview, type PreviewServer } from "vite";
import type { TestProject } from "vitest/node";
import { ROOT } from "../../src/planner/node";

let server: PreviewServer | undefined;

export async function setup(project: TestProject): Promise<void> {
  const dist = join(ROOT, process.env.E2E_DIST ?? "dist");
  if (!existsSync(join(dist, "index.html"))) throw new Error(`${dist} is missing: run \`npm run build\` before the e2e tests`);
  server = await preview({
    configFile: join(ROOT, "vite.config.ts"),
    logLevel: "warn",
    build: { outDir: dist },
    preview: { host: "127.0.0.1", port: 0, strictPort: false, open: false },
  });
  const url = server.resolvedUrls?.local[0];
  if (url === undefined) throw new Error("the preview server did not report its address");
  project.provide("baseUrl", url);
}

export async function teardown(): Promise<void> {
  await server?.close();
}

declare module "vitest" {
  export interface ProvidedContext {
    baseUrl: string;
  }
}
