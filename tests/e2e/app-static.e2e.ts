// The built app from a plain static server under a sub-path: the time to the first plan on a cold load,
// and offline reloads through the service worker (the network off, then the server gone).
import { mkdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { Browser } from "playwright-core";
import { ROOT } from "../../src/planner/node";
import { ARTEFACTS, launch, screenshot, watchErrors } from "./browser";
import { waitForPlan } from "./app-helpers";
import { serveStatic, type StaticServer } from "./app-static-server";

let browser: Browser;
let server: StaticServer;
beforeAll(async () => {
  browser = await launch();
  server = await serveStatic(join(ROOT, "dist"), "/courses/cooking/foon/");
});
afterAll(async () => {
  await browser?.close();
  await server?.close();
});

describe("static hosting", () => {
  it("plans from a sub-path, reports the cold time to first plan, and works offline afterwards", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    const page = await context.newPage();
    const errors = watchErrors(page);
    const query = "?dish=salad&i=chili+pepper~chopped&i=tomato~whole&i=cool+whip";
    await page.goto(`${server.url}${query}`);
    await waitForPlan(page);
    const timing = await page.evaluate(() => ({
      firstPlanMs: performance.getEntriesByName("foon:first-plan")[0]?.startTime ?? -1,
      domContentLoadedMs: performance.getEntriesByType("navigation")[0] instanceof PerformanceNavigationTiming
        ? (performance.getEntriesByType("navigation")[0] as PerformanceNavigationTiming).domContentLoadedEventEnd
        : -1,
    }));
    expect(timing.firstPlanMs).toBeGreaterThan(0);
    // the worker's load phases are on the page's timeline, each ending before the first plan
    // (the planner's copy on the page's thread is loaded once the page is idle after the first plan: not one of them)
    const phases = await page.evaluate(() => performance.getEntriesByType("measure").filter((m) => m.name.startsWith("foon:") && m.name !== "foon:page copy load").map((m) => ({ name: m.name, end: m.startTime + m.duration })));
    expect(phases.map((p) => p.name).sort()).toEqual(["foon:embeddings download", "foon:kb download", "foon:kb load", "foon:plan drawn", "foon:plan shown", "foon:wasm"]);
    for (const p of phases) expect(p.end).toBeLessThanOrEqual(timing.firstPlanMs + 1);
    // the status line says how long the plan took to show
    expect(await page.locator(".plan-status").textContent()).toMatch(/Shown in \d+\.\d ms \(planner \d+\.\d ms\)\.$/);
    mkdirSync(ARTEFACTS, { recursive: true });
    writeFileSync(join(ARTEFACTS, "timing.json"), `${JSON.stringify({ coldFirstPlanMs: Math.round(timing.firstPlanMs), domContentLoadedMs: Math.round(timing.domContentLoadedMs) })}\n`);
    // every request stayed under the sub-path
    const outside = await page.evaluate((prefix) => performance.getEntriesByType("resource").map((r) => new URL(r.name).pathname).filter((p) => !p.startsWith(prefix)), "/courses/cooking/foon/");
    expect(outside).toEqual([]);

    // the service worker takes control and precaches; then the network goes off
    await page.waitForFunction(() => navigator.serviceWorker.controller !== null, undefined, { timeout: 20_000 }).catch(async () => {
      await page.reload();
      await page.waitForFunction(() => navigator.serviceWorker.controller !== null);
    });
    expect(await page.evaluate(() => navigator.serviceWorker.controller?.scriptURL)).toBe(`${server.url}sw.js`);
    await page.evaluate(async () => {
      await navigator.serviceWorker.ready;
    });
    await context.setOffline(true);
    await page.reload();
    await waitForPlan(page);
    expect(await page.locator(".kb-status").getAttribute("data-state")).toBe("ready");
    await context.setOffline(false);

    // the server gone altogether: another query still plans, from the cache
    await server.close();
    await page.goto(`${server.url}?dish=soup&i=carrot~chopped&i=onion~diced`);
    await waitForPlan(page);
    expect(await page.locator(".plan-status").textContent()).toContain("soup");
    await page.locator(".cy canvas").first().waitFor();
    await screenshot(page, "app-offline");
    expect(errors.filter((e) => !/ERR_INTERNET_DISCONNECTED|ERR_CONNECTION_REFUSED|Failed to load resource/.test(e))).toEqual([]);
    await context.close();
  });
});
