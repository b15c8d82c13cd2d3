// The embedding example page: two <foon-planner> widgets on one page, each in its own shadow root and
// worker, with their events, and no CSS leaking in or out.
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser } from "playwright-core";
import { launch, screenshot, watchErrors } from "./browser";
import { painted } from "./app-helpers";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

describe("embedding page", () => {
  it("shows two independent widgets that plan, emit events and keep their styles to themselves", async () => {
    const context = await browser.newContext({ viewport: { width: 1200, height: 900 } });
    const page = await context.newPage();
    const errors = watchErrors(page);
    await page.goto(new URL("embed.html", inject("baseUrl")).href);
    // Playwright's CSS locators pierce open shadow roots
    const salad = page.locator("foon-planner#salad");
    const soup = page.locator("foon-planner#soup");
    await salad.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
    await soup.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });

    expect(await page.evaluate(() => document.querySelectorAll("foon-planner").length)).toBe(2);
    expect(await page.evaluate(() => [...document.querySelectorAll("foon-planner")].every((w) => w.shadowRoot !== null))).toBe(true);
    // view="all": tree, progress, steps, substitutions; view="progress": the progress lines only
    await salad.locator(".cy canvas").first().waitFor(); // the graph view loads on its own
    expect(await salad.locator(".steps li").count()).toBeGreaterThan(2);
    expect(await salad.locator(".panel-substitutions tbody tr").count()).toBe(3);
    expect(await soup.locator(".progress-svg g.line").count()).toBeGreaterThan(0);
    expect(await soup.locator(".cy").count()).toBe(0);
    expect(await soup.locator(".steps").count()).toBe(0);
    // themes per widget
    expect(await salad.locator(".fp-theme").getAttribute("data-theme")).toBe("light");
    expect(await soup.locator(".fp-theme").getAttribute("data-theme")).toBe("dark");

    // events: one plan per widget, and a select with its step
    await page.locator("#log", { hasText: "#soup plan" }).waitFor();
    expect(await page.locator("#log").textContent()).toContain("#salad plan");
    await salad.locator(".steps li").nth(1).click();
    await page.locator("#log", { hasText: "#salad select" }).waitFor();

    // no leakage: the page's serif font stays outside, the app's styles stay inside
    expect(await page.evaluate(() => getComputedStyle(document.body).fontFamily)).toContain("Georgia");
    // only the page's own <style>, besides Cytoscape's one rule scoped to its own container class
    const sheets = await page.evaluate(() => [...document.styleSheets].map((s) => [...s.cssRules].map((r) => r.cssText).join(" ")));
    expect(sheets.filter((rules) => !/^\.__________cytoscape_container \{[^}]*\}$/.test(rules))).toHaveLength(1);
    expect(await salad.locator(".panel").first().evaluate((e) => getComputedStyle(e).fontFamily)).toContain("system-ui");

    // attributes re-plan: a new ingredient list
    await page.evaluate(() => document.getElementById("soup")?.setAttribute("ingredients", "chopped potato, sliced leek"));
    await soup.locator('.progress-svg g.line[data-ingredient="leek"]').waitFor();
    await painted(page);
    await screenshot(page, "widget-embed");

    // mount(): a handle that updates and destroys
    await page.getByRole("button", { name: "Mount a planner here" }).click();
    const mounted = page.locator("#mounted");
    await mounted.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
    expect(await mounted.locator(".steps li").count()).toBeGreaterThan(0);
    await page.getByRole("button", { name: "Update it: omelette" }).click();
    await page.locator("#log", { hasText: "#mounted plan: " }).filter({ hasText: "omelette" }).waitFor();
    await page.getByRole("button", { name: "Destroy it" }).click();
    expect(await page.evaluate(() => document.getElementById("mounted")?.shadowRoot?.childElementCount ?? -1)).toBe(0);
    // a knowledge base that is not there: an `error` event with the reason, and the message in the widget
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
