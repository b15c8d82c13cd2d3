// Markup injection: FOON files and queries whose labels, states, motions, containers, titles and dish type
// are HTML/SVG/script payloads. In headless Chromium against the built dist/: every payload is shown as
// text (steps, substitutions, progress lines and their tooltips, reference, the graph's SVG export), no
// element or event-handler attribute is created from them, no script runs (no dialog, no global set, no
// CSP violation reported), and the page's Content-Security-Policy blocks inline script.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser, Page } from "playwright-core";
import { ROOT } from "../../src/planner/node";
import { launch, screenshot, watchErrors } from "./browser";
import { downloadOf, scrollToTools, waitForPlan } from "./app-helpers";
import { setTrap, type PayloadTrap } from "./payload-trap";

// Payloads are in the normal form of the reader (lower case, no underscores), so they reach the page as
// written. Each would set `window.xss` (or open a dialog) if it ever became markup.
const LABEL = "<img src=x onerror=window.xss='label'>";
const STATE = `"><script>window.xss='state'</script>`;
const UTENSIL = "<svg onload=window.xss='utensil'>";
const CONTAINER = "<b onmouseover=window.xss='container'>bowl</b>";
const MOTION = `"><img src=x onerror=alert('motion')>`;
const TITLE = "<script>window.xss='title'</script>";
const QUERY_STATE = `'><svg onload=window.xss='query'>`;
const DISH = `"><iframe srcdoc="<script>parent.xss='dish'</script>">`;

const HOSTILE_KB = [
  `# title: ${TITLE}`,
  "//",
  `O\t${LABEL}\t1`,
  `S\t${STATE}`,
  `O\t${UTENSIL}\t0`,
  `S\tin\t[${CONTAINER}]`,
  `M\t${MOTION}\t<Assumed>`,
  "O\ttoast\t1\t0",
  "S\ttoasted",
  `S\tcontains\t{${LABEL},bread}`,
  "//",
  "O\tbread\t1",
  "S\tsliced",
  `O\t${UTENSIL}\t0`,
  "M\ttoast\t<Assumed>",
  "O\ttoast\t1\t0",
  "S\ttoasted",
  "S\tcontains\t{bread}",
  "",
].join("\n");

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

interface TrappedPage extends PayloadTrap {
  page: Page;
  errors: string[];
}

/** A page in a context of its own, trapped from before any script of the app runs. */
async function trappedPage(): Promise<TrappedPage> {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 }, acceptDownloads: true });
  const page = await context.newPage();
  const errors = watchErrors(page);
  return { page, errors, ...(await setTrap(page, errors)) };
}

/** Elements or event-handler attributes that can only have come from a payload. */
async function injectedMarkup(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const found: string[] = [];
    for (const e of Array.from(document.querySelectorAll("*"))) {
      for (const a of Array.from(e.attributes)) {
        if (a.name.toLowerCase().startsWith("on")) found.push(`<${e.localName} ${a.name}>`);
      }
    }
    for (const e of Array.from(document.querySelectorAll("main img, main iframe, main b, main script, script:not([src])"))) {
      found.push(`<${e.localName}> ${e.outerHTML.slice(0, 80)}`);
    }
    return found;
  });
}

describe("markup in FOON files and queries is text everywhere", () => {
  it("shows hostile labels, states, motions, containers, titles and queries as text, and runs nothing", async () => {
    const { page, trap, settled, errors } = await trappedPage();
    const search = new URLSearchParams();
    search.set("dish", DISH);
    search.append("i", `${LABEL}~${QUERY_STATE}`);
    search.append("i", "bread~sliced");
    await page.goto(`${inject("baseUrl")}?dish=bread&i=bread~sliced`);
    await waitForPlan(page);
    await page.getByLabel(/Load your own FOON files/).setInputFiles([{ name: "hostile.txt", mimeType: "text/plain", buffer: Buffer.from(HOSTILE_KB) }]);
    await page.locator(".kb-status[data-source='custom']").waitFor();
    // now the hostile query, through the URL the app keeps its query in
    await page.evaluate((s) => {
      history.pushState(null, "", `${location.pathname}?${s}`);
      dispatchEvent(new PopStateEvent("popstate"));
    }, search.toString());
    await page.waitForFunction((label) => Array.from(document.querySelectorAll(".steps li .step-text")).some((li) => li.textContent?.includes(label) === true), LABEL, { timeout: 30_000 });
    await waitForPlan(page);
    await page.locator(".cy canvas").first().waitFor();
    await settled();
    await screenshot(page, "injection-app");

    // shown as text: steps, substitutions, reference title, progress lines and their tooltips, the query editor
    const steps = (await page.locator(".steps li .step-text").allTextContents()).join("\n");
    expect(steps).toContain(LABEL);
    expect(steps).toContain(MOTION);
    expect(await page.locator(".panel-substitutions").textContent()).toContain(LABEL);
    expect(await page.locator(".panel-reference .goal-label").textContent()).toBe(TITLE);
    const progress = await page.locator(".progress-svg").evaluate((svg) => ({
      text: Array.from(svg.querySelectorAll("text")).map((t) => t.textContent ?? "").join("\n"),
      tooltips: Array.from(svg.querySelectorAll("title")).map((t) => t.textContent ?? "").join("\n"),
    }));
    expect(`${progress.text}\n${progress.tooltips}`).toContain(LABEL);
    expect(await page.getByLabel("Ingredient 1: object").inputValue()).toBe(LABEL);

    // nothing became markup, nothing ran, nothing even tried (a CSP violation would show an attempt)
    expect(await injectedMarkup(page)).toEqual([]);
    expect(await trap()).toEqual({ xss: null, violations: [], dialogs: [] });

    // the graph's SVG export: payloads escaped, a well-formed SVG with no element made from them
    await scrollToTools(page);
    const svg = await downloadOf(page, () => page.getByRole("button", { name: "Graph SVG", exact: true }).click());
    const text = svg.bytes.toString();
    expect(text).not.toContain("<img");
    expect(text).not.toContain("<script");
    const parsed = await page.evaluate((source) => {
      const doc = new DOMParser().parseFromString(source, "image/svg+xml");
      return {
        error: doc.querySelector("parsererror")?.textContent ?? null,
        elements: Array.from(doc.querySelectorAll("img, script, iframe, b, foreignObject")).map((e) => e.localName),
        handlers: Array.from(doc.querySelectorAll("*")).flatMap((e) => Array.from(e.attributes).filter((a) => a.name.startsWith("on")).map((a) => a.name)),
        titles: Array.from(doc.querySelectorAll("title")).map((t) => t.textContent ?? "").join("\n"),
      };
    }, text);
    expect(parsed.error).toBeNull();
    expect(parsed.elements).toEqual([]);
    expect(parsed.handlers).toEqual([]);
    expect(parsed.titles).toContain(LABEL);

    // the FOON export keeps the labels as FOON text, to be read back as the same labels
    const foon = (await downloadOf(page, () => page.getByRole("button", { name: "FOON text", exact: true }).click())).bytes.toString();
    expect(foon).toContain(`O\t${LABEL}\t`);

    expect(await trap()).toEqual({ xss: null, violations: [], dialogs: [] });
    expect(errors).toEqual([]);
    await page.context().close();
  });

  it("shows hostile query files as text in the evaluation workbench (batch table, rating view)", async () => {
    const dir = mkdtempSync(join(tmpdir(), "injection-queries-"));
    const id = "<img src=x onerror=window.xss='id'>";
    const file = join(dir, "hostile.json");
    writeFileSync(file, JSON.stringify({ id, type: "salad", ingredients: [{ object: LABEL, state: QUERY_STATE }, { object: "tomato", state: "sliced" }] }));
    const { page, trap, settled, errors } = await trappedPage();
    await page.goto(new URL("workbench.html", inject("baseUrl")).href);
    await page.waitForSelector("body[data-ready=true]");
    await page.fill("#rater", "<b onmouseover=window.xss='rater'>me</b>");
    await page.press("#rater", "Enter");
    await page.setInputFiles("#query-files", [file]);
    await page.click("#run-batch");
    await page.waitForSelector("#batch-status[data-state=done], #batch-status[data-state=failed]", { timeout: 60_000 });
    expect(await page.textContent("#batch-status")).toMatch(/^Done: 2 plans of 1 quer/);
    expect(await page.locator("#recipe-table tbody").textContent()).toContain(id);
    await page.goto(new URL("workbench.html#rate", inject("baseUrl")).href);
    await page.waitForSelector("body[data-ready=true]");
    await page.locator(".item").first().waitFor();
    expect(await page.locator(".recipe-title code").textContent()).toBe(id);
    expect((await page.locator(".item").allTextContents()).join("\n")).toContain(LABEL);
    await settled();
    await screenshot(page, "injection-workbench");
    expect(await injectedMarkup(page)).toEqual([]);
    expect(await trap()).toEqual({ xss: null, violations: [], dialogs: [] });
    expect(errors).toEqual([]);
    await page.context().close();
    rmSync(dir, { recursive: true, force: true });
  });

  it("serves every page with a Content-Security-Policy that blocks inline script", async () => {
    for (const name of ["index.html", "workbench.html", "embed.html", "author.html"]) {
      const html = readFileSync(join(ROOT, process.env.E2E_DIST ?? "dist", name), "utf8");
      const policy = /http-equiv="Content-Security-Policy"\s+content="([^"]+)"/.exec(html)?.[1] ?? "";
      const scriptSrc = /(?:^|;)\s*script-src ([^;]*)/.exec(policy)?.[1] ?? "";
      expect(scriptSrc, name).not.toBe("");
      expect(scriptSrc, name).not.toContain("'unsafe-inline'");
      expect(scriptSrc, name).not.toContain("'unsafe-eval'");
      expect(policy, name).toContain("object-src 'none'");
      expect(policy, name).toContain("base-uri 'self'");
      // no inline script in the built page itself (it would be blocked)
      expect(html, name).not.toMatch(/<script(?![^>]*\ssrc=)[^>]*>/);
    }

    const { page, trap } = await trappedPage();
    await page.goto(inject("baseUrl"));
    await waitForPlan(page);
    // what an injection would do: an inline <script>, an inline event handler, a javascript: URL
    await page.evaluate(() => {
      const s = document.createElement("script");
      s.textContent = "window.xss = 'inline script'";
      document.body.append(s);
      const img = document.createElement("img");
      img.setAttribute("onerror", "window.xss = 'inline handler'");
      img.src = "data:,not-an-image";
      document.body.append(img);
      const a = document.createElement("a");
      a.href = "javascript:window.xss='javascript url'";
      document.body.append(a);
      a.click();
    });
    // handled: each attempt reported (or one ran)
    await page.waitForFunction(() => {
      const w = window as unknown as { xss?: unknown; cspViolations: string[] };
      return w.cspViolations.length >= 3 || w.xss !== undefined;
    });
    const seen = await trap();
    expect(seen.xss).toBeNull();
    expect(seen.dialogs).toEqual([]);
    // each attempt was blocked by the policy, and reported once: the two scripts as elements, the handler as an attribute
    expect(seen.violations.map((v) => v.split(":")[0]).sort()).toEqual(["script-src-attr", "script-src-elem", "script-src-elem"]);
    await page.context().close();
  });
});
