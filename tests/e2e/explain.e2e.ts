// The Algorithm view in headless Chromium: the widget page with view=explain steps through a plan with
// the keyboard, one step per key, from Alg. 1 to the final task tree; on the planner page it loads when
// scrolled to, and its last step draws the same tree as the task-tree view. Loading there moves nothing
// below it, on a desktop and on a phone.
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser, BrowserContextOptions, Locator, Page } from "playwright-core";
import { launch, screenshot, watchErrors } from "./browser";
import { painted, waitForPlan } from "./app-helpers";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

const QUERY = "dish=salad&i=tomato~sliced&i=cucumber~sliced&i=lettuce~chopped";

const DESKTOP: BrowserContextOptions = { viewport: { width: 1200, height: 1000 } };
const PHONE: BrowserContextOptions = { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true };

async function load(path: string, device = DESKTOP): Promise<{ page: Page; errors: string[] }> {
  const context = await browser.newContext(device);
  const page = await context.newPage();
  const errors = watchErrors(page);
  await page.goto(new URL(path, inject("baseUrl")).href);
  await waitForPlan(page);
  return { page, errors };
}

/** The view once it is scrolled to (on the planner page it is far down) and shows a step. */
async function scrollToView(page: Page): Promise<Locator> {
  await page.locator(".panel-explain").scrollIntoViewIfNeeded();
  const view = page.locator(".panel-explain[data-step]");
  await view.waitFor({ timeout: 30_000 });
  return view;
}

/** Presses `key` on the view and waits for it to show step `expected`. */
async function press(page: Page, view: Locator, key: string, expected: number): Promise<void> {
  await view.press(key);
  await page.locator(`.panel-explain[data-step="${expected}"]`).waitFor();
}

describe("Algorithm view", () => {
  it("steps through the plan with the keyboard and ends showing the final task tree", async () => {
    const { page, errors } = await load(`widget.html?${QUERY}&view=explain`);
    const view = await scrollToView(page);
    expect(await page.locator(".panel").count()).toBe(1); // only the Algorithm view
    const total = Number(await view.getAttribute("data-steps"));
    expect(total).toBeGreaterThan(4);
    expect(await view.getAttribute("data-phase")).toBe("goal");
    expect(await view.locator(".explain-caption").textContent()).toMatch(/^Algorithm 1 compares/);
    expect(await view.getByRole("link").textContent()).toBe("Section III-A, Algorithm 1");

    const seen = new Set<string>();
    let nodes = 0;
    for (let step = 1; step < total; step++) {
      await press(page, view, "ArrowRight", step);
      const phase = (await view.getAttribute("data-phase")) ?? "";
      // a picture of the first step of each phase, for the eye (test-results/e2e/)
      if (!seen.has(phase)) await screenshot(page, `explain-${phase}`);
      seen.add(phase);
      const now = Number(await view.locator(".explain-graph").getAttribute("data-nodes"));
      // the search tree only grows while Alg. 2 runs
      if (phase === "retrieval") expect(now).toBeGreaterThanOrEqual(nodes);
      nodes = now;
      expect(((await view.locator(".explain-caption").textContent()) ?? "").length).toBeGreaterThan(20);
    }
    expect([...seen]).toEqual(["retrieval", "modification", "pruning", "final"]);
    expect(await view.locator(".explain-caption").textContent()).toMatch(/^The task tree: \d+ functional unit/);
    expect(await view.getByRole("button", { name: "Next step" }).isDisabled()).toBe(true);
    expect(nodes).toBeGreaterThan(3);

    // back one step, Home to the start, End to the final tree again
    await press(page, view, "ArrowLeft", total - 2);
    await press(page, view, "Home", 0);
    // in the notes on a step, up and down scroll them instead of stepping
    await view.locator(".explain-notes").press("ArrowDown");
    expect(await view.getAttribute("data-step")).toBe("0");
    await press(page, view, "End", total - 1);

    // play runs on from the start by itself; pause stops it
    await view.getByRole("button", { name: "▶ Play" }).click();
    await page.locator('.panel-explain[data-step="1"]').waitFor();
    await view.getByRole("button", { name: "❚❚ Pause" }).click();
    expect(await view.getByRole("button", { name: "▶ Play" }).getAttribute("aria-pressed")).toBe("false");
    expect(errors).toEqual([]);
  });

  it("draws, at its last step on the planner page, the tree the task-tree view shows", async () => {
    const { page, errors } = await load(`?${QUERY}`);
    // off screen, a re-plan after an edit skips the trace and the view shows no steps (it is not even loaded)
    await page.evaluate(() => performance.clearMeasures("foon:plan shown"));
    await page.locator(".ingredient-row .state").first().fill("diced");
    await page.waitForFunction(() => performance.getEntriesByName("foon:plan shown").length > 0);
    expect(await page.locator(".panel-explain").getAttribute("data-steps")).toBeNull();
    // scrolled to, it catches up with the plan the task-tree view shows
    const view = await scrollToView(page);
    const total = Number(await view.getAttribute("data-steps"));
    await press(page, view, "End", total - 1);
    const tree = page.locator(".panel-tree .cy");
    await page.locator(".panel-tree .cy canvas").first().waitFor();
    expect(await view.locator(".explain-graph").getAttribute("data-nodes")).toBe(await tree.getAttribute("data-nodes"));
    expect(await view.locator(".explain-graph").getAttribute("data-edges")).toBe(await tree.getAttribute("data-edges"));
    expect(errors).toEqual([]);
  });
});

/**
 * Sums the page's layout shifts from now on, as its own PerformanceObserver scores them (Core Web Vitals:
 * above 0.1 is "needs improvement"). Every shift counts, those the browser marks as just after input too:
 * the test gives none, and with touch emulated Chromium marks so the shifts after a scroll made by script.
 */
async function watchLayoutShift(page: Page): Promise<() => Promise<number>> {
  const handle = await page.evaluateHandle(() => {
    interface LayoutShift extends PerformanceEntry {
      value: number;
    }
    let score = 0;
    const add = (entries: PerformanceEntryList): void => {
      for (const e of entries as LayoutShift[]) score += e.value;
    };
    const observer = new PerformanceObserver((list) => add(list.getEntries()));
    observer.observe({ type: "layout-shift" });
    return () => {
      add(observer.takeRecords());
      return score;
    };
  });
  return () => handle.evaluate((total) => total());
}

describe("Algorithm view loading on the planner page", () => {
  it.each([
    ["a desktop", DESKTOP],
    ["a phone", PHONE],
  ])("moves nothing below it on %s: the export button a user aims at stays where it was", async (_, device) => {
    const { page, errors } = await load(`?${QUERY}`, device);
    const foonText = page.getByRole("button", { name: "FOON text", exact: true });
    expect(await page.locator(".panel-explain").getAttribute("data-step")).toBeNull(); // not drawn yet
    const shift = await watchLayoutShift(page);
    // where the user sees the button (a phone's visual viewport may sit below the layout viewport) the moment
    // the scroll lands, before the view above it has had a chance to load
    const aimed = await foonText.evaluate((button) => {
      button.scrollIntoView({ block: "center" });
      return button.getBoundingClientRect().top - (visualViewport?.offsetTop ?? 0);
    });
    await page.locator(".panel-explain[data-step]").waitFor({ timeout: 30_000 });
    await waitForPlan(page);
    await painted(page);
    expect(await foonText.evaluate((button) => button.getBoundingClientRect().top - (visualViewport?.offsetTop ?? 0))).toBe(aimed);
    expect(await shift()).toBeLessThan(0.1);
    await screenshot(page, `explain-loaded-${device.isMobile === true ? "phone" : "desktop"}`);
    expect(errors).toEqual([]);
  });
});
