// The FOON editor page: paste a recipe, draft it, fix an error the editor shows with line and column,
// use it in the planner, plan with it, reload — the authored text and the knowledge base are still there.
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser, Page } from "playwright-core";
import { launch, screenshot, watchErrors } from "./browser";
import { downloadOf, waitForPlan } from "./app-helpers";
import { lowContrast, unlabelledControls } from "./app-a11y";
import { setTrap } from "./payload-trap";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

const RECIPE = `Peanut Butter Banana Toast

Ingredients
- 2 slices bread
- 2 tablespoons peanut butter
- 1 banana, sliced
- 1 teaspoon honey

Steps
1. Toast the bread in the toaster.
2. Spread the peanut butter on the bread.
3. Top with the banana and drizzle with honey.
`;

const editor = (page: Page) => page.locator(".editor-host");
const text = (page: Page) => page.locator("textarea.code-input");

/** Waits until the page has checked the editor's current text (the check runs in the planner's worker). */
async function waitForCheck(page: Page): Promise<void> {
  await page.locator("#author[data-checked='yes']").waitFor();
}

const authorUrl = (): string => `${inject("baseUrl")}author.html`;

/** Pastes the recipe, drafts it and waits for the draft to be checked. */
async function draftRecipe(page: Page): Promise<void> {
  await page.getByRole("textbox", { name: "Recipe text" }).fill(RECIPE);
  await page.getByRole("button", { name: "Draft FOON from this recipe" }).click();
  await waitForCheck(page);
}

describe("the FOON editor", () => {
  it("drafts a recipe, shows and clears an error, plans with it, and keeps everything across a reload", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 }, acceptDownloads: true });
    const page = await context.newPage();
    const errors = watchErrors(page);
    await page.goto(authorUrl());
    await draftRecipe(page);
    const drafted = await text(page).inputValue();
    expect(drafted).toContain("# title: Peanut Butter Banana Toast");
    expect(drafted).toMatch(/^O\tpeanut butter banana toast\t1\t0$/m); // the goal node, dish class 0 (bread)
    expect(await editor(page).getAttribute("data-errors")).toBe("0");
    await page.locator(".panel-tree .cy[data-nodes]").waitFor();
    expect(Number(await page.locator(".panel-tree .cy").getAttribute("data-nodes"))).toBeGreaterThan(4);
    expect(await page.locator(".panel-steps li").count()).toBeGreaterThan(2);

    // a typo: the flag of an object line is not a number
    const lines = drafted.split("\n");
    const at = lines.findIndex((l) => l === "O\tbanana\t1");
    lines[at] = "O\tbanana\tyes";
    await text(page).fill(lines.join("\n"));
    await waitForCheck(page);
    expect(await editor(page).getAttribute("data-errors")).toBe("1");
    const shown = await page.locator(".diagnostics li[data-severity='error']").textContent();
    expect(shown).toContain(`line ${at + 1}, column 10`);
    expect(await page.getByRole("button", { name: "Use in planner" }).isDisabled()).toBe(true);

    // the error's place, clicked, puts the caret there: the user types the fix
    await page.locator(".diagnostics li[data-severity='error'] button").click();
    const caret = await text(page).evaluate((t: HTMLTextAreaElement) => t.selectionStart);
    expect(caret).toBe(lines.slice(0, at).join("\n").length + 1 + "O\tbanana\t".length);
    await page.keyboard.press("Shift+End");
    await page.keyboard.type("1");
    await waitForCheck(page);
    expect(await editor(page).getAttribute("data-errors")).toBe("0");
    expect(await text(page).inputValue()).toBe(drafted);

    // undo and redo, the editor's own (the page set the text, so the browser's undo would not know it)
    await page.keyboard.press("Control+z");
    await waitForCheck(page);
    expect(await editor(page).getAttribute("data-errors")).toBe("1");
    await page.keyboard.press("Control+Shift+z");
    await waitForCheck(page);
    expect(await editor(page).getAttribute("data-errors")).toBe("0");
    expect(await text(page).inputValue()).toBe(drafted);

    await page.getByRole("button", { name: "Use in planner" }).click();
    await page.locator(".use-status[data-state='saved']").waitFor();
    await page.getByRole("link", { name: "Plan with it" }).click();
    await waitForPlan(page);
    expect(await page.locator(".kb-status").getAttribute("data-source")).toBe("custom");
    expect(await page.locator(".panel-reference .goal-label").textContent()).toBe("Peanut Butter Banana Toast");

    await page.goto(authorUrl());
    await waitForCheck(page);
    expect(await text(page).inputValue()).toBe(drafted);
    expect(await page.getByRole("textbox", { name: "Recipe text" }).inputValue()).toBe(RECIPE);
    expect(await page.locator(".save-status").textContent()).toContain("restored");
    const file = await downloadOf(page, () => page.getByRole("button", { name: "Download .txt" }).click());
    expect([file.name, file.bytes.toString("utf8")]).toEqual(["peanut-butter-banana-toast.txt", drafted]);
    const bundle = await downloadOf(page, () => page.getByRole("button", { name: "Download knowledge base (.foon)" }).click());
    expect(bundle.bytes.toString("utf8")).toContain(`#@file peanut-butter-banana-toast.txt\n${drafted}`);
    expect(bundle.bytes.toString("utf8")).toContain("#@file s01-greek_salad.txt\n"); // the bundled knowledge base's files too
    await screenshot(page, "author");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("completes the knowledge base's words, types tabs, and keeps each keystroke when the tab is closed at once", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    const page = await context.newPage();
    const errors = watchErrors(page);
    await page.goto(authorUrl());
    await page.locator("#author[data-words='ready']").waitFor(); // the knowledge base's words are loaded
    await text(page).focus();
    await page.keyboard.type("# title: Quick dip");
    await page.keyboard.press("Enter");
    await page.keyboard.type("M");
    await page.keyboard.press("Tab"); // a tab character, not a move of the focus
    await page.keyboard.type("whis");
    await page.locator(".completions li[aria-selected='true']", { hasText: "whisk" }).waitFor();
    await page.keyboard.press("Enter");
    expect(await text(page).inputValue()).toBe("# title: Quick dip\nM\twhisk");
    await page.keyboard.type("\t<Assumed>");
    const typed = await text(page).inputValue();
    await page.close(); // at once: no wait for anything after the last keystroke

    const again = await context.newPage();
    await again.goto(authorUrl());
    await waitForCheck(again);
    expect(await text(again).inputValue()).toBe(typed);
    // the reader's own complaint about a motion without inputs, with its place
    expect(await again.locator(".diagnostics li[data-severity='error']").textContent()).toMatch(/line 2, column \d+: /);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("has labelled controls and AA contrast in both themes", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    const page = await context.newPage();
    const errors = watchErrors(page);
    await page.goto(authorUrl());
    await draftRecipe(page);
    expect(await page.evaluate(unlabelledControls)).toEqual([]);
    const text = "h1, h2, p, label, a, button, li, input";
    for (const theme of ["light", "dark"]) {
      await page.getByLabel("Theme").selectOption(theme);
      expect(await page.evaluate(lowContrast, { selector: text, min: 4.5 }), `contrast in the ${theme} theme`).toEqual([]);
    }
    expect(errors).toEqual([]);
    await context.close();
  });

  it("never lets two tabs overwrite each other's text: the newest is restored, the other offered", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    const [a, b] = [await context.newPage(), await context.newPage()];
    const errors = [...watchErrors(a), ...watchErrors(b)];
    for (const page of [a, b]) {
      await page.goto(authorUrl());
      await waitForCheck(page);
    }
    for (const [page, title] of [[a, "Tab A"], [b, "Tab B"]] as const) {
      await text(page).focus();
      await page.keyboard.type(`# title: ${title}`);
    }
    await a.keyboard.type(" again"); // A typed last
    await a.close();
    await b.close();

    const page = await context.newPage();
    await page.goto(authorUrl());
    await waitForCheck(page);
    expect(await text(page).inputValue()).toBe("# title: Tab A again");
    await page.getByText("Other texts saved in this browser (1)").click();
    expect(await page.locator(".other-works li").textContent()).toContain("Tab B");
    await page.locator(".other-works li").getByRole("button", { name: "Open" }).click();
    expect(await text(page).inputValue()).toBe("# title: Tab B");
    await page.getByRole("button", { name: "Undo" }).click();
    expect(await text(page).inputValue()).toBe("# title: Tab A again");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("shows a hostile recipe and FOON text as text: no element is made of it, no script runs", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    const page = await context.newPage();
    const errors = watchErrors(page);
    const { trap, settled } = await setTrap(page, errors);
    await page.goto(authorUrl());
    const hostile = "<img src=x onerror=\"window.xss=1\">";
    await page.getByRole("textbox", { name: "Recipe text" }).fill(`${hostile} salad\n- 1 ${hostile}\n1. Dice the ${hostile}.\n2. Frobnicate ${hostile}.`);
    await page.getByRole("button", { name: "Draft FOON from this recipe" }).click();
    await waitForCheck(page);
    expect(await text(page).inputValue()).toContain(`# title: ${hostile} salad`);
    expect(await page.locator(".diagnostics li[data-severity='confirm']").allTextContents()).toContainEqual(expect.stringContaining(hostile));
    await settled();
    expect(await page.locator("#author img").count()).toBe(0);
    expect(await trap()).toEqual({ xss: null, violations: [], dialogs: [] });
    expect(errors).toEqual([]);
    await context.close();
  });
});
