// The embedding example page: two <foon-planner> widgets on one page, each in its own shadow root and
// worker, with their events, and no CSS leaking in or out.
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser, BrowserContext, Locator, Page } from "playwright-core";
import { launch, screenshot, watchErrors } from "./browser";
import { painted } from "./app-helpers";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

interface EmbedPage {
  context: BrowserContext;
  page: Page;
  errors: string[];
  /** The two widgets of the page; Playwright's CSS locators pierce their open shadow roots. */
  salad: Locator;
  soup: Locator;
}

/** The embedding example page, once both its widgets show a plan. */
async function embedPage(): Promise<EmbedPage> {
  const context = await browser.newContext({ viewport: { width: 1200, height: 900 } });
  const page = await context.newPage();
  const errors = watchErrors(page);
  await page.goto(new URL("embed.html", inject("baseUrl")).href);
  const salad = page.locator("foon-planner#salad");
  const soup = page.locator("foon-planner#soup");
  await salad.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
  await soup.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
  return { context, page, errors, salad, soup };
}

/** The lines of the page's event log. */
const logLines = (page: Page): Promise<string[]> => page.locator("#log div").allTextContents();

describe("embedding page", () => {
  it("shows each widget in its own shadow root, with the views and the theme its attributes ask for", async () => {
    const { context, page, errors, salad, soup } = await embedPage();
    expect(await page.evaluate(() => [...document.querySelectorAll("foon-planner")].map((w) => w.shadowRoot !== null))).toEqual([true, true]);
    // view="all": tree, progress, steps, substitutions; view="progress": the progress lines only
    await salad.locator(".cy canvas").first().waitFor(); // the graph view loads on its own
    expect(await salad.locator(".steps li").count()).toBeGreaterThan(2);
    expect(await salad.locator(".panel-substitutions tbody tr").count()).toBe(3);
    expect(await soup.locator(".progress-svg g.line").count()).toBeGreaterThan(0);
    expect(await soup.locator(".cy").count()).toBe(0);
    expect(await soup.locator(".steps").count()).toBe(0);
    expect(await salad.locator(".fp-theme").getAttribute("data-theme")).toBe("light");
    expect(await soup.locator(".fp-theme").getAttribute("data-theme")).toBe("dark");
    await painted(page);
    await screenshot(page, "widget-embed");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("sends one plan event per widget, and a select event with the step the user clicks", async () => {
    const { context, page, errors, salad } = await embedPage();
    await page.locator("#log div", { hasText: "#salad plan" }).waitFor();
    await page.locator("#log div", { hasText: "#soup plan" }).waitFor();
    const step = salad.locator(".steps li").nth(1);
    const stepText = (await step.locator(".step-text").textContent()) ?? "";
    await step.click();
    await page.locator("#log div", { hasText: "#salad select" }).waitFor();
    const lines = await logLines(page);
    expect(lines.filter((l) => l.includes(" plan: ")).map((l) => l.split(" ")[0]).sort()).toEqual(["#salad", "#soup"]);
    expect(lines.filter((l) => l.startsWith("#salad select"))).toEqual([`#salad select: ${stepText}`]);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("keeps the page's styles outside the widgets and the widgets' styles inside", async () => {
    const { context, page, errors, salad } = await embedPage();
    await salad.locator(".cy canvas").first().waitFor(); // Cytoscape adds its one stylesheet with the graph
    expect(await page.evaluate(() => getComputedStyle(document.body).fontFamily)).toContain("Georgia");
    // only the page's own <style>, besides Cytoscape's one rule scoped to its own container class
    const sheets = await page.evaluate(() => [...document.styleSheets].map((s) => [...s.cssRules].map((r) => r.cssText).join(" ")));
    expect(sheets.filter((rules) => !/^\.__________cytoscape_container \{[^}]*\}$/.test(rules))).toHaveLength(1);
    expect(await salad.locator(".panel").first().evaluate((e) => getComputedStyle(e).fontFamily)).toContain("system-ui");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("re-plans when the page changes a widget's ingredients attribute", async () => {
    const { context, page, errors, soup } = await embedPage();
    expect(await soup.locator('.progress-svg g.line[data-ingredient="leek"]').count()).toBe(0);
    await page.evaluate(() => document.getElementById("soup")?.setAttribute("ingredients", "chopped potato, sliced leek"));
    await soup.locator('.progress-svg g.line[data-ingredient="leek"]').waitFor();
    await soup.locator(".plan-status[data-state='ready']").waitFor();
    expect(await soup.locator(".progress-svg g.line").evaluateAll((lines) => lines.map((l) => l.getAttribute("data-ingredient")))).toEqual(
      expect.arrayContaining(["leek", "potato"]),
    );
    expect(await soup.locator('.progress-svg g.line[data-ingredient="carrot"]').count()).toBe(0);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("mounts a planner from script with mount(), and updates and destroys it through its handle", async () => {
    const { context, page, errors } = await embedPage();
    await page.getByRole("button", { name: "Mount a planner here" }).click();
    const mounted = page.locator("#mounted");
    await mounted.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
    expect(await mounted.locator(".steps li").count()).toBeGreaterThan(0);
    expect(await page.locator("#log div", { hasText: "#mounted plan: " }).allTextContents()).toEqual([expect.stringContaining(" for pizza ")]);
    await page.getByRole("button", { name: "Update it: omelette" }).click();
    await page.locator("#log div", { hasText: "#mounted plan: " }).filter({ hasText: "omelette" }).waitFor();
    await page.getByRole("button", { name: "Destroy it" }).click();
    expect(await page.evaluate(() => document.getElementById("mounted")?.shadowRoot?.childElementCount ?? -1)).toBe(0);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("sends an error event with the reason when its knowledge base is not there", async () => {
    const { context, page, errors } = await embedPage();
    const error = await page.evaluate(
      () =>
        new Promise<string>((resolve) => {
          const w = document.createElement("foon-planner");
          w.setAttribute("kb-url", "kb/missing.foon");
          w.setAttribute("ingredients", "whole tomato");
          w.addEventListener("error", (event) => {
            if (event instanceof CustomEvent) resolve((event.detail as { error: { message: string } }).error.message);
          });
          document.body.append(w);
        }),
    );
    expect(error).toMatch(/missing\.foon.*(404|not found)/);
    expect(errors.filter((e) => !e.includes("404"))).toEqual([]);
    await context.close();
  });
});
