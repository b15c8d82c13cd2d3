// The npm package as a user gets it: `npm pack` (which builds lib/ beside the built dist/), the tarball
// installed into a throwaway folder (no dependencies, so no network), then a query planned from plain Node
// and from a Vite app built with it (the planner API bundled, the widget served from the package's dist/).
import { execFileSync } from "node:child_process";
import { cpSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { build } from "vite";
import type { Browser } from "playwright-core";
import { ROOT } from "../../src/planner/node";
import { launch, screenshot, watchErrors } from "./browser";
import { serveStatic, type StaticServer } from "./app-static-server";

let work: string;
let app: string;
const QUERY = { id: "pkg", type: "salad", ingredients: [{ object: "tomato", state: "diced" }, { object: "chili pepper", state: "chopped" }] };

beforeAll(() => {
  work = mkdtempSync(join(tmpdir(), "foon-package-"));
  const packed = execFileSync("npm", ["pack", "--silent", "--pack-destination", work], { cwd: ROOT, encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
  const tarball = join(work, packed.trim().split("\n").pop() ?? "");
  app = join(work, "app");
  mkdirSync(app);
  writeFileSync(join(app, "package.json"), JSON.stringify({ name: "course-app", private: true, type: "module" }));
  execFileSync("npm", ["install", "--offline", "--no-audit", "--no-fund", "--no-package-lock", tarball], { cwd: app, stdio: "pipe" });
}, 180_000);
afterAll(() => {
  if (work !== undefined) rmSync(work, { recursive: true, force: true });
});

describe("the npm package", () => {
  it("plans a query in plain Node, with the bundled knowledge base and embedding table", () => {
    const script = `import { loadPlanner } from "foon-planner";
const planner = loadPlanner();
const plan = planner.plan({ query: ${JSON.stringify(QUERY)} });
console.log(JSON.stringify({ units: plan.units.length, type: plan.query.type, stats: planner.stats().units }));`;
    const out = JSON.parse(execFileSync("node", ["--input-type=module", "-e", script], { cwd: app, encoding: "utf8" })) as { units: number; type: string; stats: number };
    expect(out.type).toBe("salad");
    expect(out.units).toBeGreaterThan(2);
    expect(out.stats).toBeGreaterThan(100);
  });

  describe("in a Vite app", () => {
    let browser: Browser;
    let server: StaticServer;
    beforeAll(async () => {
      writeFileSync(
        join(app, "index.html"),
        `<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>course app</title></head><body>
<p id="api">planning…</p>
<foon-planner id="widget" dish-type="soup" ingredients="chopped carrot, diced onion" view="steps"></foon-planner>
<script type="module" src="/main.js"></script>
<script type="module" src="/foon-planner/foon-planner.js"></script>
</body></html>`,
      );
      writeFileSync(
        join(app, "main.js"),
        `import { initPlanner, FoonPlanner } from "foon-planner";
import kbUrl from "foon-planner/kb/default.foon?url";
import embeddingsUrl from "foon-planner/data/food-embeddings.bin?url";
const bytes = async (url) => new Uint8Array(await (await fetch(url)).arrayBuffer());
const out = document.getElementById("api");
try {
  await initPlanner();
  const planner = FoonPlanner.load([{ name: "default.foon", bytes: await bytes(kbUrl) }], await bytes(embeddingsUrl));
  const plan = planner.plan({ query: ${JSON.stringify(QUERY)} });
  out.dataset.units = String(plan.units.length);
  out.textContent = plan.query.type + ": " + plan.steps.join(" ");
} catch (e) {
  out.dataset.error = String(e);
}`,
      );
      // the README's way for the widget: the package's dist/ copied among the app's static files
      cpSync(join(app, "node_modules/foon-planner/dist"), join(app, "public/foon-planner"), { recursive: true });
      await build({ root: app, configFile: false, logLevel: "warn", build: { outDir: join(app, "out"), target: "es2022" } });
      server = await serveStatic(join(app, "out"), "/");
      browser = await launch();
    }, 120_000);
    afterAll(async () => {
      await browser?.close();
      await server?.close();
    });

    it("bundles the planner API (WASM found by the bundler) and serves the widget", async () => {
      const page = await browser.newPage();
      const errors = watchErrors(page);
      await page.goto(server.url);
      await page.locator("#api[data-units], #api[data-error]").waitFor({ timeout: 30_000 });
      expect(await page.locator("#api").getAttribute("data-error")).toBeNull();
      expect(Number(await page.locator("#api").getAttribute("data-units"))).toBeGreaterThan(2);
      expect(await page.locator("#api").textContent()).toMatch(/^salad: .*tomato/);
      const widget = page.locator("foon-planner#widget");
      await widget.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
      expect(await widget.locator(".steps li").count()).toBeGreaterThan(0);
      await screenshot(page, "package-vite-app");
      expect(errors).toEqual([]);
      await page.close();
    });
  });
});
