// Helpers shared by the app's end-to-end tests.
import { readFileSync } from "node:fs";
import type { Download, Page } from "playwright-core";

/** Waits until the planner shows a plan (or fails with the status text it shows instead). */
export async function waitForPlan(page: Page, root = ""): Promise<void> {
  const status = page.locator(`${root} .plan-status`.trim());
  await status.and(page.locator("[data-state='ready']")).waitFor({ timeout: 30_000 }).catch(async (e: unknown) => {
    throw new Error(`no plan: ${(await status.textContent()) ?? "no status"} (${String(e)})`);
  });
}

/**
 * Scrolls the export and knowledge-base tools into view and waits until the page has settled there: near the
 * screen, the Algorithm view just above them loads and the plan is made again with its trace. The view keeps
 * the height it had before loading, so the tools stay put meanwhile (explain.e2e.ts checks that); the wait
 * keeps a tool's effect apart from that re-plan.
 */
export async function scrollToTools(page: Page): Promise<void> {
  await page.locator(".panel-export").scrollIntoViewIfNeeded();
  await page.locator(".panel-explain[data-step]").waitFor({ timeout: 30_000 });
  await waitForPlan(page);
}

/** Clicks and returns the saved download's name and bytes. */
export async function downloadOf(page: Page, click: () => Promise<void>): Promise<{ name: string; bytes: Buffer }> {
  const [download]: [Download, void] = await Promise.all([page.waitForEvent("download"), click()]);
  const path = await download.path();
  return { name: download.suggestedFilename(), bytes: readFileSync(path) };
}

/**
 * Resolves once the page has drawn two more frames: Cytoscape draws on animation frames, so a screenshot taken
 * after shows the graph (screenshots are artefacts for people; no assertion rests on this).
 */
export async function painted(page: Page): Promise<void> {
  await page.evaluate(() => new Promise<void>((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => resolve()))));
}
