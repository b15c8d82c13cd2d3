// The planner page in headless Chromium against the built dist/: asking by typing, the task tree canvas,
// progress lines, steps in sync with the selection, substitutes, knowledge-base files, exports, the URL,
// and themes. (Offline and sub-path serving: app-static.e2e.ts.)
import { mkdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Core } from "cytoscape";
import type { Browser, BrowserContext, Page } from "playwright-core";
import { ARTEFACTS, launch, screenshot, watchErrors } from "./browser";
import { downloadOf, painted, scrollToTools, waitForPlan } from "./app-helpers";
import { lowContrast, unlabelledControls } from "./app-a11y";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

async function fresh(): Promise<{ context: BrowserContext; page: Page; errors: string[] }> {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 }, acceptDownloads: true });
  const page = await context.newPage();
  page.on("dialog", (d) => {
    throw new Error(`unexpected dialog: ${d.message()}`);
  });
  return { context, page, errors: watchErrors(page) };
}

const stepsText = (page: Page): Promise<string[]> => page.locator(".steps li .step-text").allTextContents();

/** The query the selection tests start from. */
const SOUP = "?dish=soup&i=carrot~chopped&i=onion~diced";

/**
 * The motion nodes drawn on the graph canvas, in page coordinates: where Cytoscape placed them (it keeps its
 * instance on its container), not a search of the canvas's pixels.
 */
async function motionNodesOnScreen(page: Page): Promise<{ id: string; x: number; y: number }[]> {
  return page.locator(".cy").evaluate((container) => {
    const { cy } = (container as HTMLElement & { _cyreg: { cy: Core } })._cyreg;
    const box = container.getBoundingClientRect();
    return cy
      .nodes(".motion")
      .map((n) => ({ id: n.id(), x: box.left + n.renderedPosition().x, y: box.top + n.renderedPosition().y }))
      .filter((p) => p.x > box.left && p.x < box.right && p.y > box.top && p.y < box.bottom);
  });
}

describe("planner page", () => {
  it("makes re-plans with the planner's copy on the page's thread once it is loaded: the worker's plans", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}${SOUP}`);
    await waitForPlan(page);
    const fromWorker = await stepsText(page);
    // loaded once the page is idle after the first plan (a failed copy would leave every plan to the worker)
    await page.waitForFunction(() => performance.getEntriesByName("foon:page copy load").length > 0);
    const state = page.locator(".ingredient-row .state").first();
    await state.fill("diced");
    await waitForPlan(page);
    expect(await stepsText(page)).not.toEqual(fromWorker);
    await state.fill("chopped");
    await waitForPlan(page);
    expect(await stepsText(page)).toEqual(fromWorker);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("redraws only what a re-plan changed: the other progress lines keep their elements, the task tree its viewport", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}?dish=salad&i=chili+pepper~chopped&i=tomato~whole&i=cool+whip`);
    await waitForPlan(page);
    await page.locator(".cy canvas").first().waitFor();
    // the user's own zoom, and a mark on every line drawn now
    const viewport = await page.locator(".cy").evaluate((container) => {
      const { cy } = (container as HTMLElement & { _cyreg: { cy: Core } })._cyreg;
      cy.zoom(cy.zoom() * 0.8);
      for (const line of document.querySelectorAll(".progress-svg g.line")) (line as Element & { kept?: boolean }).kept = true;
      return { zoom: cy.zoom(), pan: cy.pan(), diced: cy.nodes('[label = "dice"]').length };
    });
    await page.locator(".ingredient-row .state").first().fill("diced");
    await waitForPlan(page);
    const after = await page.locator(".cy").evaluate((container) => {
      const { cy } = (container as HTMLElement & { _cyreg: { cy: Core } })._cyreg;
      const lines = [...document.querySelectorAll(".progress-svg g.line")].map((l) => [l.getAttribute("data-ingredient"), (l as Element & { kept?: boolean }).kept === true]);
      return { viewport: { zoom: cy.zoom(), pan: cy.pan(), diced: cy.nodes('[label = "dice"]').length }, lines: Object.fromEntries(lines) as Record<string, boolean>, diced: cy.nodes('[label = "dice"]').length };
    });
    expect(after.viewport).toEqual({ ...viewport, diced: viewport.diced + 1 }); // the new plan, in the same extent: not fitted again
    expect(after.lines["chili pepper"]).toBe(false);
    expect(after.lines["tomato"]).toBe(true);
    expect(await page.locator('.progress-svg g.line[data-ingredient="chili pepper"] g.cell.motion text.label').allTextContents()).toContain("dice");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("draws the first plan as a still task tree before Cytoscape is fetched, then the interactive one with the same nodes", async () => {
    const { context, page, errors } = await fresh();
    const fetched: string[] = [];
    page.on("request", (r) => fetched.push(new URL(r.url()).pathname));
    await page.goto(`${inject("baseUrl")}${SOUP}`);
    await page.waitForFunction(() => performance.getEntriesByName("foon:first-plan").length > 0);
    const atFirstPlan = [...fetched];
    // counted in one go: the interactive tree may replace the picture between two of the test's calls
    const stillNodes = await page.evaluate(() => document.querySelectorAll(".panel-tree .tree-preview svg :is(g.object, g.motion)").length);
    expect(stillNodes).toBeGreaterThan(3);
    expect(atFirstPlan.some((path) => path.includes("/tree-view-"))).toBe(false);
    await page.locator(".cy canvas").first().waitFor();
    expect(Number(await page.locator(".cy").getAttribute("data-nodes"))).toBe(stillNodes);
    expect(await page.locator(".tree-preview").count()).toBe(0);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("plans a query typed in, and shows it in the URL, the task tree, the progress lines, the steps and the substitutions", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(inject("baseUrl"));
    await waitForPlan(page); // the first example
    await page.getByLabel("Dish type").selectOption("soup");
    while ((await page.locator(".ingredient-row").count()) > 0) await page.getByRole("button", { name: "Remove ingredient 1" }).click();
    await page.getByRole("button", { name: "Add ingredient" }).click();
    await page.getByLabel("Ingredient 1: object").pressSequentially("carrot");
    await page.getByLabel("Ingredient 1: state").pressSequentially("chopped");
    await page.getByRole("button", { name: "Add ingredient" }).click();
    await page.getByLabel("Ingredient 2: object").pressSequentially("onion");
    await page.getByLabel("Ingredient 2: state").pressSequentially("diced");
    await waitForPlan(page); // each keystroke re-plans at once, so "ready" is the plan of the last one

    expect(await page.locator(".plan-status").textContent()).toMatch(/^Task tree for soup/);
    await page.waitForURL((url) => url.search === "?dish=soup&i=carrot~chopped&i=onion~diced"); // once the page is idle
    await page.locator(".cy canvas").first().waitFor(); // the graph view loads on its own
    expect(Number(await page.locator(".cy").getAttribute("data-nodes"))).toBeGreaterThan(3);
    expect(await page.locator('.progress-svg g.line[data-ingredient="carrot"]').count()).toBe(1);
    expect(await page.locator('.progress-svg g.line[data-ingredient="onion"]').count()).toBe(1);
    const steps = await stepsText(page);
    expect(steps.length).toBeGreaterThan(2);
    expect(steps.join(" ")).toContain("carrot");
    expect(await page.locator(".panel-substitutions tbody tr").count()).toBe(2);
    expect(await page.locator(".panel-reference .goal-label").textContent()).not.toBe("");
    await screenshot(page, "app-typed-query");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("highlights a selected step's unit on the graph and its progress line, and moves the selection with the arrow keys", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}${SOUP}`);
    await waitForPlan(page);
    expect(await page.locator(".progress-svg g.line.on-line").count()).toBe(0);
    const carrotStep = page.locator(".steps li", { hasText: "carrot" }).first();
    await carrotStep.click();
    expect(await carrotStep.getAttribute("aria-selected")).toBe("true");
    await page.locator('.progress-svg g.line.on-line[data-ingredient="carrot"]').waitFor();
    expect(await page.locator(".progress-svg g.line.on-line").count()).toBe(1);
    const unit = Number(await carrotStep.getAttribute("data-unit"));
    await page.locator(`.cy[data-selected="m:${unit}"]`).waitFor();
    await page.keyboard.press("ArrowDown");
    expect(await page.locator('.steps li[aria-selected="true"]').getAttribute("data-unit")).toBe(String(unit + 1));
    // a view the plan reached late draws the selection when the page is next idle: wait for the graph's own mark
    await page.locator(`.cy[data-selected="m:${unit + 1}"]`).waitFor();
    expect(await page.evaluate(() => document.activeElement?.getAttribute("data-unit"))).toBe(String(unit + 1));
    expect(errors).toEqual([]);
    await context.close();
  });

  it("selects a step when its motion node is clicked on the graph", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}${SOUP}`);
    await waitForPlan(page);
    await page.locator(".cy canvas").first().waitFor();
    await page.locator(".cy").scrollIntoViewIfNeeded();
    const motions = await motionNodesOnScreen(page);
    expect(motions.length).toBe(await page.locator(".steps li").count());
    const target = motions[1]!; // not the first, so a wrong pick (the first node, or none) shows
    await page.mouse.click(target.x, target.y);
    await page.locator(`.cy[data-selected="${target.id}"]`).waitFor();
    expect(await page.locator('.steps li[aria-selected="true"]').getAttribute("data-unit")).toBe(target.id.slice("m:".length));
    expect(errors).toEqual([]);
    await context.close();
  });

  it("selects a step when a motion on a progress line is clicked", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}${SOUP}`);
    await waitForPlan(page);
    expect(await page.locator('.steps li[aria-selected="true"]').count()).toBe(0);
    await page.locator('.progress-svg g.line[data-ingredient="onion"] g.cell.motion').first().click();
    await page.locator('.steps li[aria-selected="true"]').waitFor();
    expect(await page.locator('.steps li[aria-selected="true"] .step-text').textContent()).toContain("onion");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("takes a pasted list, reorders and removes rows, and plans FOON files dropped on the page", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}?dish=salad&i=tomato~whole`);
    await waitForPlan(page);
    await page.getByLabel("Paste a list (comma- or line-separated)").fill("chopped chili pepper, sliced cucumber\ncool whip");
    await page.getByRole("button", { name: "Add these" }).click();
    await page.waitForURL(/i=cool\+whip/);
    expect(new URL(page.url()).searchParams.getAll("i")).toEqual(["tomato~whole", "chili pepper~chopped", "cucumber~sliced", "cool whip"]);
    // focus follows the row, for keyboard users: the moved row's button, then the row in the removed one's place
    const focused = (): Promise<string> => page.evaluate(() => document.activeElement?.getAttribute("aria-label") ?? "");
    await page.getByRole("button", { name: "Move ingredient 3 up" }).click();
    expect(await focused()).toBe("Move ingredient 2 up");
    await page.getByRole("button", { name: "Remove ingredient 4" }).click();
    expect(await focused()).toBe("Ingredient 3: object");
    await page.waitForURL((url) => url.searchParams.getAll("i").join("|") === "tomato~whole|cucumber~sliced|chili pepper~chopped");
    await waitForPlan(page);

    // two FOON files dropped together are merged
    const recipe = (title: string, food: string, cls: number): string =>
      `# title: ${title}\n//\nO\t${food}\t1\nS\twhole\nO\tknife\t0\nS\tclean\nM\tslice\t<Assumed>\nO\t${food}\t1\nS\tsliced\nO\t${food} plate\t1\t${cls}\nS\tcontains\t{${food}}\n`;
    await page.evaluate(
      ([a, b]) => {
        const data = new DataTransfer();
        data.items.add(new File([a!], "pear.txt", { type: "text/plain" }));
        data.items.add(new File([b!], "fig.txt", { type: "text/plain" }));
        const target = document.querySelector(".foon-app")!;
        target.dispatchEvent(new DragEvent("dragover", { dataTransfer: data, bubbles: true, cancelable: true }));
        target.dispatchEvent(new DragEvent("drop", { dataTransfer: data, bubbles: true, cancelable: true }));
      },
      [recipe("Pear plate", "pear", 8), recipe("Fig plate", "fig", 8)],
    );
    await page.locator(".kb-status[data-source='custom']").waitFor();
    expect(await page.locator(".kb-status").textContent()).toContain("pear.txt, fig.txt");
    expect(await page.locator(".kb-stats tbody tr", { hasText: "Recipes" }).locator("td").textContent()).toBe("2");
    expect(await page.getByLabel("Dish type").locator("option", { hasText: "dessert (2)" }).count()).toBe(1);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("re-plans when another substitute is chosen, and keeps it in the URL", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}?dish=salad&i=chili+pepper~chopped&i=tomato~whole`);
    await waitForPlan(page);
    const row = page.locator('.panel-substitutions tr[data-object="chili pepper"]');
    const picker = row.locator("select.substitute");
    const options = (await picker.locator("option").evaluateAll((os) => os.map((o) => (o as HTMLOptionElement).value))).filter((v) => v !== "");
    expect(options.length).toBeGreaterThan(0);
    const before = await row.locator(".equivalent").textContent();
    // another equivalent than the planner's own
    const choice = options.find((o) => !(before ?? "").includes(o));
    expect(choice, `an alternative other than ${before}`).toBeDefined();
    await picker.selectOption(choice!);
    await page.locator('.panel-substitutions tr[data-object="chili pepper"] .badge', { hasText: "your choice" }).waitFor();
    await waitForPlan(page);
    const after = await page.locator('.panel-substitutions tr[data-object="chili pepper"] .equivalent').textContent();
    expect(after).toContain(choice);
    expect(after).not.toBe(before);
    expect(await page.locator('.panel-substitutions tr[data-object="chili pepper"] select.substitute').inputValue()).toBe(choice);
    await page.waitForURL((url) => url.searchParams.get("sub") === `chili pepper~${choice}`);
    await screenshot(page, "app-substitute");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("retrieves in the mode chosen under Retrieval, shows each step's robot figures, and keeps the mode in the URL", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}?dish=salad&i=chili+pepper~chopped&i=tomato~whole`);
    await waitForPlan(page);
    expect(await page.locator(".steps .robot-figures").count()).toBe(0); // the paper's heuristic: no robot view
    await page.getByLabel("Retrieval").selectOption("most_reliable");
    await page.locator(".robot-summary:not([hidden])").waitFor();
    await waitForPlan(page);
    const steps = await page.locator(".steps li").count();
    expect(await page.locator(".steps li .robot-figures[data-by='robot']").count()).toBe(steps);
    expect(await page.locator(".robot-summary").textContent()).toMatch(/^Robot: total motion cost [\d.]+, success [\d.]+%\.$/);
    await page.waitForURL((url) => url.searchParams.get("mode") === "most_reliable");
    await screenshot(page, "app-retrieval-mode");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("loads FOON files from the file input, shows errors with file and line, and switches back", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}?dish=bread&i=bread~sliced`);
    await waitForPlan(page);
    const hostile = "<img src=x onerror=alert(1)>";
    const toast = [
      "# title: Hostile toast",
      "//",
      "O\tbread\t1",
      "S\tsliced",
      `O\t${hostile}\t0`,
      "S\tclean",
      "M\ttoast\t<Assumed>",
      "O\ttoast\t1\t0",
      "S\ttoasted",
      "S\tcontains\t{bread}",
      "",
    ].join("\n");
    await page.getByLabel(/Load your own FOON files/).setInputFiles([{ name: "toast.txt", mimeType: "text/plain", buffer: Buffer.from(toast) }]);
    await page.locator(".kb-status[data-source='custom']").waitFor();
    expect(await page.locator(".kb-status").textContent()).toContain("toast.txt");
    await waitForPlan(page);
    expect(await page.locator(".panel-reference .goal-label").textContent()).toBe("Hostile toast");
    // the hostile label is text, never markup
    expect(await page.locator(".foon-app img").count()).toBe(0);
    expect(await page.locator(".panel-query datalist option", { hasText: "" }).evaluateAll((os) => os.some((o) => (o as HTMLOptionElement).value === "<img src=x onerror=alert(1)>"))).toBe(true);

    const broken = "//\nO\ttomato\t1\nS\t[bowl\nM\tdice\t<Assumed>\nO\ttomato\t1\nS\tdiced\n";
    await page.getByLabel(/Load your own FOON files/).setInputFiles([{ name: "broken.txt", mimeType: "text/plain", buffer: Buffer.from(broken) }]);
    await page.locator(".kb-error:not([hidden])").waitFor();
    expect(await page.locator(".kb-error").textContent()).toMatch(/broken\.txt:3/);
    expect(await page.locator(".kb-status").getAttribute("data-source")).toBe("custom"); // the previous one stays
    await screenshot(page, "app-kb-error");

    await scrollToTools(page);
    await page.getByRole("button", { name: "Use the bundled knowledge base" }).click();
    await page.locator(".kb-status[data-source='bundled']").waitFor();
    await waitForPlan(page);
    expect(await page.locator(".panel-reference .goal-label").textContent()).not.toBe("Hostile toast");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("exports the task tree (FOON, JSON, PDDL), the progress lines (JSON) and the graph (PNG, SVG)", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}?dish=salad&i=tomato~whole&i=cucumber~sliced`);
    await waitForPlan(page);
    await page.locator(".cy canvas").first().waitFor();
    await scrollToTools(page);
    const button = (name: string) => () => page.getByRole("button", { name, exact: true }).click();

    const foon = await downloadOf(page, button("FOON text"));
    expect(foon.name).toMatch(/\.txt$/);
    expect(foon.bytes.toString()).toMatch(/^\/\/$/m);
    expect(foon.bytes.toString()).toMatch(/^M\t/m);

    const json = await downloadOf(page, button("Plan JSON"));
    const plan = JSON.parse(json.bytes.toString()) as { format_version: number; units: unknown[] };
    expect(plan.format_version).toBe(1);
    expect(plan.units.length).toBeGreaterThan(0);

    const pddl = await downloadOf(page, button("PDDL"));
    expect(pddl.name).toMatch(/\.pddl$/);
    expect(pddl.bytes.toString()).toContain("(define");

    const progress = await downloadOf(page, button("Progress lines JSON"));
    expect(() => JSON.parse(progress.bytes.toString()) as unknown).not.toThrow();
    expect(progress.bytes.toString()).toContain("tomato");

    const png = await downloadOf(page, button("Graph PNG"));
    expect(png.bytes.subarray(0, 8).toString("hex")).toBe("89504e470d0a1a0a");
    const svg = await downloadOf(page, button("Graph SVG"));
    expect(svg.bytes.toString()).toContain("<svg");
    expect(svg.bytes.toString()).toContain("<circle");
    mkdirSync(join(ARTEFACTS, "downloads"), { recursive: true });
    for (const d of [foon, json, pddl, progress, png, svg]) writeFileSync(join(ARTEFACTS, "downloads", d.name), d.bytes);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("restores the query from the URL, with back and forward", async () => {
    const { context, page, errors } = await fresh();
    const base = inject("baseUrl");
    await page.goto(`${base}?dish=salad&i=tomato~diced&i=cucumber~sliced`);
    await waitForPlan(page);
    expect(await page.getByLabel("Dish type").inputValue()).toBe("salad");
    expect(await page.getByLabel("Ingredient 1: object").inputValue()).toBe("tomato");
    expect(await page.getByLabel("Ingredient 2: state").inputValue()).toBe("sliced");

    await page.getByRole("button", { name: /^Omelette/ }).click();
    await page.waitForURL(/dish=omelette/);
    await waitForPlan(page);
    await page.goBack();
    await page.waitForURL(/dish=salad/);
    await page.waitForFunction(() => (document.querySelector<HTMLInputElement>("input.object")?.value ?? "") === "tomato");
    await waitForPlan(page);
    expect(await page.locator(".plan-status").textContent()).toContain("salad");
    await page.goForward();
    await page.waitForURL(/dish=omelette/);
    await page.waitForFunction(() => (document.querySelector<HTMLInputElement>("input.object")?.value ?? "") === "egg");

    await page.reload();
    await waitForPlan(page);
    expect(await page.getByLabel("Ingredient 1: object").inputValue()).toBe("egg");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("remembers the theme, and shows both themes", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(inject("baseUrl"));
    await waitForPlan(page);
    await page.getByLabel("Theme").selectOption("light");
    expect(await page.locator("html").getAttribute("data-theme")).toBe("light");
    await screenshot(page, "app-light");
    await page.getByLabel("Theme").selectOption("dark");
    await page.reload();
    await waitForPlan(page);
    expect(await page.locator("html").getAttribute("data-theme")).toBe("dark");
    await painted(page);
    await screenshot(page, "app-dark");
    expect(errors).toEqual([]);
    await context.close();
  });

  it("has labelled controls, a visible focus ring and AA contrast in both themes", async () => {
    const { context, page, errors } = await fresh();
    await page.goto(`${inject("baseUrl")}?dish=salad&i=chili+pepper~chopped&i=tomato~whole`);
    await waitForPlan(page);
    expect(await page.evaluate(unlabelledControls)).toEqual([]);
    // Tab reaches the controls, and the focused one shows an outline
    for (let i = 0; i < 3; i++) await page.keyboard.press("Tab");
    const ring = await page.evaluate(() => {
      const e = document.activeElement;
      return e === null || e === document.body ? null : { tag: e.tagName, style: getComputedStyle(e).outlineStyle, width: parseFloat(getComputedStyle(e).outlineWidth) };
    });
    expect(ring).not.toBeNull();
    expect(ring!.style).not.toBe("none");
    expect(ring!.width).toBeGreaterThanOrEqual(2);
    const text = "h1, h2, h3, p, label, a, button, th, td, li, .badge, .reason, .chip, select, input";
    // the checker sees the page's text (no one reaches 21:1 everywhere)
    expect((await page.evaluate(lowContrast, { selector: text, min: 21 })).length).toBeGreaterThan(10);
    for (const theme of ["light", "dark"]) {
      await page.getByLabel("Theme").selectOption(theme);
      expect(await page.evaluate(lowContrast, { selector: text, min: 4.5 }), `contrast in the ${theme} theme`).toEqual([]);
    }
    expect(errors).toEqual([]);
    await context.close();
  });
});
