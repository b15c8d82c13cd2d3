// The built demo page loads the WASM planner and the bundled knowledge base, and lists its statistics
// in the knowledge-base panel.
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser } from "playwright-core";
import { launch, screenshot, watchErrors } from "./browser";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

describe("demo page", () => {
  it("loads the knowledge base in WASM and shows its statistics", async () => {
    const page = await browser.newPage();
    const errors = watchErrors(page);
    await page.goto(inject("baseUrl"));
    await page.waitForSelector(".kb-status[data-state='ready']");
    const rows = await page.locator(".kb-stats tbody tr").count();
    expect(rows).toBeGreaterThan(5);
    const units = await page.locator(".kb-stats tbody tr", { hasText: "Functional units" }).last().locator("td").textContent();
    expect(Number(units)).toBeGreaterThan(0);
    await screenshot(page, "stats");
    expect(errors).toEqual([]);
  });
});
