// The planner page in headless Chromium against the built dist/: asking by typing, the task tree canvas,
// progress lines, steps in sync with the selection, substitutes, knowledge-base files, exports, the URL,
// and themes. (Offline and sub-path serving: app-static.e2e.ts.)
import { mkdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser, BrowserContext, Page } from "playwright-core";
import { ARTEFACTS, launch, screenshot, watchErrors } from "./browser";
import { downloadOf, waitForPlan } from "./app-helpers";
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

describe("planner page", () => {
  it("plans a query typed in, and shows the tree canvas, progress lines and steps", async () => {
    const { context, page, errors } = await fresh();
    const base = inject("baseUrl");
    await page.goto(base);
    await waitForPlan(page); // the first example

    // a new query, typed
    await page.getByLabel("Dish type").selectOption("soup");
    while ((await page.locator(".ingredient-row").count()) > 0) await page.getByRole("button", { name: "Remove ingredient 1" }).click();
    await page.getByRole("button", { name: "Add ingredient" }).click();
    await page.getByLabel("Ingredient 1: object").pressSequentially("carrot");
    await page.getByLabel("Ingredient 1: state").pressSequentially("chopped");
    await page.getByRole("button", { name: "Add ingredient" }).click();
    await page.getByLabel("Ingredient 2: object").pressSequentially("onion");
    await page.getByLabel("Ingredient 2: state").pressSequentially("diced");
    await page.waitForFunction(() => document.querySelector(".plan-status")?.textContent?.startsWith("Task tree for soup") === true);
    await waitForPlan(page);

    expect(new URL(page.url()).search).toBe("?dish=soup&i=carrot~chopped&i=onion~diced");
    const canvas = page.locator(".cy");
    await page.locator(".cy canvas").first().waitFor(); // the graph view loads on its own
    expect(Number(await canvas.getAttribute("data-nodes"))).toBeGreaterThan(3);
    expect(await page.locator(".cy canvas").count()).toBeGreaterThan(0);
    expect(await page.locator(".progress-svg g.line").count()).toBeGreaterThan(0);
    expect(await page.locator('.progress-svg g.line[data-ingredient="carrot"]').count()).toBe(1);
    const steps = await stepsText(page);
    expect(steps.length).toBeGreaterThan(2);
    expect(steps.join(" ")).toContain("carrot");
    expect(await page.locator(".panel-substitutions tbody tr").count()).toBe(2);
    expect(await page.locator(".panel-reference .goal-label").textContent()).not.toBe("");

    // selecting a step highlights its unit in the progress lines; arrow keys move the selection
    const carrotStep = page.locator(".steps li", { hasText: "carrot" }).first();
    await carrotStep.click();
    expect(await carrotStep.getAttribute("aria-selected")).toBe("true");
    await page.locator('.progress-svg g.line.on-line[data-ingredient="carrot"]').waitFor();
    const carrotUnit = await carrotStep.getAttribute("data-unit");
    expect(await page.locator(".cy").getAttribute("data-selected")).toBe(`m:${carrotUnit}`); // the graph follows
    const before = Number(await page.locator('.steps li[aria-selected="true"]').getAttribute("data-unit"));
    await page.keyboard.press("ArrowDown");
    expect(Number(await page.locator('.steps li[aria-selected="true"]').getAttribute("data-unit"))).toBe(before + 1);
    expect(await page.evaluate(() => document.activeElement?.getAttribute("aria-selected"))).toBe("true");

    // clicking a motion node (a red square) on the graph canvas selects its step and progress line
    await page.locator(".steps li").last().click(); // a known selection first (drawn with an overlay, so not pure red)
    const lastUnit = await page.locator(".steps li").last().getAttribute("data-unit");
    await page.locator(".cy").scrollIntoViewIfNeeded();
    // Cytoscape redraws on animation frames: read the pixels once the selection's overlay is drawn
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(resolve, 200)))));
    // every red square's top-left corner (30 px apart at least), in screen coordinates
    const squares = await page.evaluate(() => {
      const motion = getComputedStyle(document.documentElement).getPropertyValue("--fp-motion").trim(); // "#rrggbb"
      const [r, g, b] = [1, 3, 5].map((i) => parseInt(motion.slice(i, i + 2), 16)) as [number, number, number];
      const found: { x: number; y: number }[] = [];
      for (const canvas of document.querySelectorAll<HTMLCanvasElement>(".cy canvas")) {
        const ctx = canvas.getContext("2d");
        if (ctx === null || canvas.width === 0) continue;
        const { data, width, height } = ctx.getImageData(0, 0, canvas.width, canvas.height);
        const box = canvas.getBoundingClientRect();
        for (let y = 0; y < height; y += 2) {
          for (let x = 0; x < width; x += 2) {
            const k = (y * width + x) * 4;
            if (Math.abs(data[k]! - r) < 8 && Math.abs(data[k + 1]! - g) < 8 && Math.abs(data[k + 2]! - b) < 8 && data[k + 3]! > 250) {
              // a few pixels inside the square's edge
              const point = { x: box.left + ((x + 3) * box.width) / width, y: box.top + ((y + 3) * box.height) / height };
              if (found.every((p) => Math.hypot(p.x - point.x, p.y - point.y) > 30)) found.push(point);
            }
          }
        }
      }
      return found;
    });
    expect(squares.length).toBeGreaterThan(1);
    // the first square that is not the selected unit's (the selected one is drawn with an overlay anyway)
    let moved = false;
    for (const square of squares.slice(0, 6)) {
      await page.mouse.click(square.x, square.y);
      moved = await page
        .waitForFunction(
          (last) => {
            const picked = document.querySelector<HTMLElement>(".cy")?.dataset.selected ?? "";
            return /^m:\d+$/.test(picked) && picked !== `m:${last}`;
          },
          lastUnit,
          { timeout: 3000 },
        )
        .then(() => true, () => false);
      if (moved) break;
    }
    expect(moved, "a tap on a motion node selects its unit").toBe(true);
    const tapped = (await page.locator(".cy").getAttribute("data-selected"))!.slice(2);
    expect(await page.locator('.steps li[aria-selected="true"]').getAttribute("data-unit")).toBe(tapped);

    // clicking a motion of a progress line selects its step
    await page.locator('.progress-svg g.line[data-ingredient="onion"] g.cell.motion').first().click();
    const selected = await page.locator('.steps li[aria-selected="true"] .step-text').textContent();
    expect(selected).toContain("onion");
    await screenshot(page, "app-typed-query");
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
    await page.getByRole("button", { name: "Move ingredient 3 up" }).click();
    await page.getByRole("button", { name: "Remove ingredient 4" }).click();
    await page.waitForURL((url) => url.searchParams.getAll("i").join("|") === "tomato~whole|cucumber~sliced|chili pepper~chopped");
    // focus stays on the moved row's button, for keyboard users
    expect(await page.evaluate(() => document.activeElement?.getAttribute("aria-label") ?? "")).toMatch(/^Remove ingredient|^Ingredient \d: object/);
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
    expect(new URL(page.url()).searchParams.get("sub")).toBe(`chili pepper~${choice}`);
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
    expect(new URL(page.url()).searchParams.get("mode")).toBe("most_reliable");
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
    await page.waitForTimeout(300);
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
