// Embedding from another origin, as a course author would: dist/ served once on one 127.0.0.1 port (with the
// CORS header static hosts send), course pages with a strict Content-Security-Policy on another port, which
// embed the planner by script tag (two widgets and mount()) and by iframe. The planner's host was visited
// first, so the demo's offline service worker is installed there and must not get in the way.
import { createHash } from "node:crypto";
import { mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { Browser, BrowserContext, Page } from "playwright-core";
import { ROOT } from "../../src/planner/node";
import { launch, screenshot, watchErrors } from "./browser";
import { serveStatic, type StaticServer } from "./app-static-server";

let browser: Browser;
let context: BrowserContext;
let planner: StaticServer;
let course: StaticServer;
let pages: string;

const CYTOSCAPE_STYLE_HASH = `sha256-${createHash("sha256").update(".__________cytoscape_container { position: relative; }").digest("base64")}`;

/** The CSP of the README's "Embed it" section, for a planner hosted at `host`. */
const csp = (host: string): string =>
  [
    "default-src 'none'",
    `script-src 'self' ${host} 'wasm-unsafe-eval'`,
    `worker-src blob: ${host}`,
    `connect-src ${host}`,
    `frame-src ${host}`,
    // the one rule Cytoscape adds to the page's head (or 'unsafe-inline')
    `style-src 'self' '${CYTOSCAPE_STYLE_HASH}'`,
    "img-src data:",
  ].join("; ");

function coursePage(title: string, body: string): string {
  const host = new URL(planner.url).origin;
  return `<!doctype html><html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="${csp(host)}">
<link rel="icon" href="data:,"><title>${title}</title><script src="events.js"></script></head><body><h1>${title}</h1>${body}</body></html>`;
}

// A classic script, before anything else: records CSP violations, the widgets' events and the frames' messages
// on the page itself (attributes and a list the test reads), and fits each frame to the height it reports.
const EVENTS_JS = `
window.violations = [];
window.frameMessages = [];
document.addEventListener("securitypolicyviolation", (e) => violations.push(e.violatedDirective + " " + e.blockedURI));
const count = (el, name) => { el.dataset[name] = String(Number(el.dataset[name] || 0) + 1); };
for (const type of ["plan", "select", "error"]) {
  document.addEventListener(type, (e) => {
    const w = e.target;
    if (w.localName !== "foon-planner") return;
    count(w, type);
    if (type === "plan") w.dataset.dish = e.detail.plan.query.type;
  });
}
window.addEventListener("message", (e) => {
  const m = e.data;
  if (typeof m !== "object" || m === null || m.source !== "foon-planner") return;
  const frame = [...document.querySelectorAll("iframe")].find((f) => f.contentWindow === e.source);
  if (frame === undefined) return;
  frameMessages.push({ origin: e.origin, frame: m.frame, type: m.type, dish: m.type === "plan" ? m.detail.plan.query.type : null });
  count(frame, m.type);
  if (m.type === "resize") frame.style.height = m.detail.height + "px";
  if (m.type === "plan") frame.dataset.units = String(m.detail.plan.units.length);
});
`;

beforeAll(async () => {
  browser = await launch();
  planner = await serveStatic(join(ROOT, "dist"), "/planner/", { "access-control-allow-origin": "*" });
  pages = mkdtempSync(join(tmpdir(), "foon-course-"));
  course = await serveStatic(pages, "/course/");
  const script = `${planner.url}foon-planner.js`;
  writeFileSync(join(pages, "events.js"), EVENTS_JS);
  writeFileSync(
    join(pages, "mount.js"),
    `import { mount } from ${JSON.stringify(script)};
mount(document.getElementById("mounted"), { dishType: "omelette", ingredients: "whole egg, chopped spinach", view: "steps" }, {
  onPlan: ({ plan }) => { document.getElementById("mounted").dataset.dish = plan.query.type; },
});`,
  );
  writeFileSync(
    join(pages, "script.html"),
    coursePage(
      "Lesson 4 (script tag)",
      `<script type="module" src="${script}"></script><script type="module" src="mount.js"></script>
<foon-planner id="salad" dish-type="salad" ingredients="chopped chili pepper, whole tomato" view="all" theme="light"></foon-planner>
<foon-planner id="soup" dish-type="soup" ingredients="chopped carrot, diced onion" view="progress" kb-url="${planner.url}kb/default.foon"></foon-planner>
<div id="mounted"></div>`,
    ),
  );
  const frame = (id: string, query: string): string =>
    `<iframe id="${id}" title="${id}" width="100%" height="50" frameborder="0" src="${planner.url}widget.html?${query}&id=${id}&origin=${encodeURIComponent(new URL(course.url).origin)}"></iframe>`;
  writeFileSync(
    join(pages, "iframe.html"),
    coursePage(
      "Lesson 5 (iframe)",
      frame("f-salad", "dish=salad&i=chili+pepper~chopped&i=tomato~whole&view=progress&theme=dark") +
        frame("f-soup", "ingredients=chopped+carrot,+diced+onion&dish=soup&view=steps"),
    ),
  );

  // the planner's own demo, visited first: its service worker installs and controls the planner's host
  context = await browser.newContext({ viewport: { width: 1200, height: 900 } });
  const demo = await context.newPage();
  await demo.goto(`${planner.url}?dish=salad&i=tomato~whole`);
  await demo.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
  await demo.waitForFunction(() => navigator.serviceWorker.controller !== null, undefined, { timeout: 20_000 }).catch(async () => {
    await demo.reload();
    await demo.waitForFunction(() => navigator.serviceWorker.controller !== null);
  });
  await demo.close();
});
afterAll(async () => {
  await context?.close();
  await browser?.close();
  await planner?.close();
  await course?.close();
  if (pages !== undefined) rmSync(pages, { recursive: true, force: true });
});

async function violations(page: Page): Promise<string[]> {
  return page.evaluate(() => (window as unknown as { violations: string[] }).violations);
}

describe("embedding from another origin", () => {
  it("script tag: two isolated widgets and mount() plan under a strict CSP, with their events", async () => {
    const page = await context.newPage();
    const errors = watchErrors(page);
    await page.goto(`${course.url}script.html`);
    const salad = page.locator("foon-planner#salad");
    const soup = page.locator("foon-planner#soup");
    await salad.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
    await soup.locator(".plan-status[data-state='ready']").waitFor({ timeout: 30_000 });
    await page.locator("#mounted[data-dish='omelette']").waitFor({ timeout: 30_000 });
    expect(await page.locator("#mounted").locator(".steps li").count()).toBeGreaterThan(0);

    // each widget its own plan, views and theme; `plan` events reach the page
    await page.locator("foon-planner#salad[data-dish='salad'][data-plan]").waitFor();
    await page.locator("foon-planner#soup[data-dish='soup'][data-plan]").waitFor();
    await salad.locator(".cy canvas").first().waitFor();
    expect(await salad.locator(".steps li").count()).toBeGreaterThan(2);
    expect(await soup.locator(".progress-svg g.line").count()).toBeGreaterThan(0);
    expect(await soup.locator(".steps").count()).toBe(0);
    expect(await salad.locator(".fp-theme").getAttribute("data-theme")).toBe("light");
    // one worker per widget, each started through a same-origin bootstrap of the planner host's script
    const workers = page.workers().map((w) => w.url());
    expect(workers.filter((url) => url.startsWith(`blob:${new URL(course.url).origin}/`))).toHaveLength(3);

    // isolation: a new ingredient list re-plans the soup only
    const saladPlans = await salad.getAttribute("data-plan");
    await page.evaluate(() => document.getElementById("soup")?.setAttribute("ingredients", "chopped potato, sliced leek"));
    await soup.locator('.progress-svg g.line[data-ingredient="leek"]').waitFor();
    expect(await salad.getAttribute("data-plan")).toBe(saladPlans);
    expect(await salad.locator('.progress-svg g.line[data-ingredient="leek"]').count()).toBe(0);
    // a select event with its step
    await salad.locator(".steps li").nth(1).click();
    await page.locator("foon-planner#salad[data-select]").waitFor();

    await screenshot(page, "embed-cross-origin-script");
    expect(await violations(page)).toEqual([]);
    expect(errors).toEqual([]);
    await page.close();
  });

  it("iframe: widget.html plans from its URL parameters and posts its events and height to the parent", async () => {
    const page = await context.newPage();
    const errors = watchErrors(page);
    await page.goto(`${course.url}iframe.html`);
    const salad = page.locator("iframe#f-salad");
    const soup = page.locator("iframe#f-soup");
    await page.locator("iframe#f-salad[data-plan][data-resize]").waitFor({ timeout: 30_000 });
    await page.locator("iframe#f-soup[data-plan][data-resize]").waitFor({ timeout: 30_000 });
    // the planner inside, as asked: progress lines only, dark; steps only
    const saladFrame = page.frameLocator("iframe#f-salad");
    await saladFrame.locator(".plan-status[data-state='ready']").waitFor();
    expect(await saladFrame.locator(".progress-svg g.line").count()).toBeGreaterThan(0);
    expect(await saladFrame.locator(".steps").count()).toBe(0);
    expect(await saladFrame.locator(".fp-theme").getAttribute("data-theme")).toBe("dark");
    expect(await page.frameLocator("iframe#f-soup").locator(".steps li").count()).toBeGreaterThan(0);

    // messages name their frame and come from the planner's origin; each frame planned its own dish
    type Message = { origin: string; frame: string; type: string; dish: string | null };
    const messages = await page.evaluate(() => (window as unknown as { frameMessages: Message[] }).frameMessages);
    const plans = messages.filter((m) => m.type === "plan");
    expect(new Set(plans.map((m) => `${m.frame}:${m.dish}`))).toEqual(new Set(["f-salad:salad", "f-soup:soup"]));
    expect(new Set(messages.map((m) => m.origin))).toEqual(new Set([new URL(planner.url).origin]));
    // auto-height: the frame was fitted to its content (it started at 50px)
    const fitted = await soup.evaluate((f: HTMLIFrameElement) => ({ height: f.getBoundingClientRect().height, content: f.contentDocument === null }));
    expect(fitted.content).toBe(true); // cross-origin: the parent cannot read the frame, only its messages
    expect(fitted.height).toBeGreaterThan(200);
    // a click inside a frame reaches the parent as a select message
    await page.frameLocator("iframe#f-soup").locator(".steps li").first().click();
    await page.locator("iframe#f-soup[data-select]").waitFor();
    expect(await salad.getAttribute("data-select")).toBeNull();

    await screenshot(page, "embed-cross-origin-iframe");
    expect(await violations(page)).toEqual([]);
    expect(errors).toEqual([]);
    await page.close();
  });
});
