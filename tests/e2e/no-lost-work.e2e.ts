// No lost work in the planner page: when the planner worker crashes, a new one takes over with the
// user's own knowledge base and the query is planned again, without a reload.
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser } from "playwright-core";
import { launch, screenshot } from "./browser";
import { waitForPlan } from "./app-helpers";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

const MY_KB = [
  "# title: My own toast",
  "//",
  "O\tbread\t1",
  "S\tsliced",
  "O\ttoaster\t0",
  "M\ttoast\t<Assumed>",
  "O\ttoast\t1\t0",
  "S\ttoasted",
  "S\tcontains\t{bread}",
  "",
].join("\n");

describe("no lost work", () => {
  it("restarts a crashed planner worker with the user's knowledge base and plans again", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    const page = await context.newPage();
    await page.goto(`${inject("baseUrl")}?dish=bread&i=bread~sliced`);
    await waitForPlan(page);
    await page.getByLabel(/Load your own FOON files/).setInputFiles([{ name: "mine.txt", mimeType: "text/plain", buffer: Buffer.from(MY_KB) }]);
    await page.locator(".kb-status[data-source='custom']").waitFor();
    await waitForPlan(page);
    expect(await page.locator(".panel-reference .goal-label").textContent()).toBe("My own toast");

    // the planner worker dies of an uncaught error (as when its WASM module traps outside a call)
    const worker = page.workers().find((w) => w.url().includes("planner"));
    expect(worker, page.workers().map((w) => w.url()).join(", ")).toBeDefined();
    const closed = new Promise<void>((resolve) => worker!.on("close", () => resolve()));
    await worker!.evaluate(() => {
      setTimeout(() => {
        throw new Error("simulated planner crash");
      }, 0);
    });
    await closed; // the page ended the crashed worker…
    // a new query is planned by a new worker, with the same (custom) knowledge base
    await page.evaluate(() => {
      history.pushState(null, "", `${location.pathname}?dish=bread&i=bread~sliced&i=butter~melted`);
      dispatchEvent(new PopStateEvent("popstate"));
    });
    await page.waitForFunction(() => document.querySelectorAll(".panel-substitutions tbody tr").length === 2, undefined, { timeout: 30_000 }).catch(async (e: unknown) => {
      throw new Error(`no new plan: ${await page.locator(".plan-status").textContent()} / ${page.url()} (${String(e)})`);
    });
    await waitForPlan(page);
    expect(await page.locator(".panel-reference .goal-label").textContent()).toBe("My own toast");
    expect(await page.locator(".kb-status").getAttribute("data-source")).toBe("custom");
    // …and planned with a new one
    const planners = page.workers().filter((w) => w.url().includes("planner"));
    expect(planners.length).toBe(1);
    expect(planners[0]).not.toBe(worker);
    await screenshot(page, "no-lost-work-worker-restart");
    await context.close();
  });
});
