// `npm run bench:browser`: the built page (dist/, or BENCH_DIST) in headless Chromium from a local static
// server, cold (a fresh profile: nothing cached; its window opened first) and warm (the same profile again, its service worker in
// control, the parsed knowledge base cached), and the widget page the same way. Prints each load phase as the
// median over BENCH_ROUNDS visits (default 5) and where the knowledge base was loaded from (its files, the
// browser's cache or the build's snapshot), the download before the first plan in gzip bytes, and re-plans
// after an edit in the page: request to the views on screen drawn, its parts (each view's drawing, the plan
// and the planner's call in it) and request to the end of the next frame. Figures are printed, never asserted.

import { existsSync, readFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { gzipSync } from "node:zlib";
import type { Browser, Page, Request } from "playwright-core";
import { ROOT } from "../src/planner/node";
import { COPY_MEASURE } from "../src/app/page-planner";
import { launch } from "../tests/e2e/browser";
import { serveStatic } from "../tests/e2e/app-static-server";

const ROUNDS = Number(process.env.BENCH_ROUNDS ?? 5);
const PREFIX = "/bench/";
/** The built page: dist/, or another build (BENCH_DIST, a path from the repository) to compare with. */
const DIST = resolve(ROOT, process.env.BENCH_DIST ?? "dist");
const QUERY = "dish=salad&i=chili+pepper~chopped&i=tomato~whole&i=cool+whip";

/** What one visit measured, in ms after navigation start, and the files it fetched. */
interface Visit {
  phases: Record<string, number>;
  files: string[];
}

/** The phases in the order they are printed: each is the time its end was reached after navigation. */
const PHASES = ["domContentLoaded", "foon:wasm", "foon:kb download", "foon:embeddings download", "foon:kb load", "first plan"];

/**
 * Settles once the page marked its first plan. A plain expression rather than `waitForFunction`, whose
 * injected script (about 80 ms of parsing) would run on the page's thread during the load it measures.
 */
const FIRST_PLAN = `new Promise((resolve) => {
  const done = () => performance.getEntriesByName("foon:first-plan").length > 0;
  if (done()) return resolve();
  new PerformanceObserver((list, observer) => done() && (observer.disconnect(), resolve())).observe({ type: "mark" });
})`;

/**
 * How long a fresh context's tab shows a blank page before a cold visit: headless Chromium builds a new
 * window's own UI (its omnibox popup, a WebUI renderer: about 1.3 s of CPU) on the window's first
 * navigation, which on two cores took most of one from the page's first 700 ms.
 */
const WINDOW_SETTLE_MS = Number(process.env.BENCH_SETTLE_MS ?? 1500);

async function visit(page: Page, url: string): Promise<Visit> {
  // the worker's requests too (the WASM module, the knowledge base, the table), not the service worker's
  const requests: Request[] = [];
  const onRequest = (request: Request): void => {
    if (request.serviceWorker() === null) requests.push(request);
  };
  page.on("request", onRequest);
  await page.goto(url);
  await page.evaluate(FIRST_PLAN);
  page.off("request", onRequest);
  // the download is what the first plan waited for: what loads after it is on screen (the interactive task tree) is not
  const firstPlanAt = await page.evaluate(() => performance.timeOrigin + performance.getEntriesByName("foon:first-plan")[0]!.startTime);
  const fetched = requests.filter((r) => r.timing().startTime <= firstPlanAt).map((r) => new URL(r.url()).pathname);
  const phases = await page.evaluate(() => {
    const phases: Record<string, number> = {};
    const navigation = performance.getEntriesByType("navigation")[0] as PerformanceNavigationTiming | undefined;
    phases.domContentLoaded = navigation?.domContentLoadedEventEnd ?? -1;
    for (const m of performance.getEntriesByType("measure")) if (m.name.startsWith("foon:")) phases[m.name] = m.startTime + m.duration;
    phases["first plan"] = performance.getEntriesByName("foon:first-plan")[0]?.startTime ?? -1;
    // how long parsing and merging (or reading the cached knowledge base) and indexing took, and which it was
    const kbLoad = performance.getEntriesByName("foon:kb load")[0] as PerformanceMeasure | undefined;
    phases["kb load took"] = kbLoad?.duration ?? -1;
    // 0: parsed from its files, 1: the browser's cache, 2: the build's snapshot
    phases["kb from"] = ["files", "cache", "build"].indexOf((kbLoad?.detail as { from?: string } | undefined)?.from ?? "");
    return phases;
  });
  return { phases, files: fetched };
}

/**
 * One re-plan, in ms: request to views drawn, the drawing part of it (and each view's), the planner's own call
 * (on the page's thread once its copy is loaded), and request to the end of the next frame (the browser painted the DOM views, Cytoscape its
 * canvas).
 */
interface Replan {
  shown: number;
  /** The same figure as the status line printed it ("Shown in 3.1 ms"). */
  status: number;
  painted: number;
  drawn: number;
  views: Record<string, number>;
  planner: number;
}

/** Re-plans after editing the first ingredient's state, as the page measured them; each waits until every view has drawn. */
async function replans(page: Page, edits: number): Promise<Replan[]> {
  const state = page.locator(".ingredient-row .state").first();
  const times: Replan[] = [];
  for (let i = 0; i < edits; i++) {
    await page.evaluate(() => {
      performance.clearMeasures("foon:plan shown");
      delete (globalThis as { benchPainted?: number }).benchPainted;
    });
    await state.fill(i % 2 === 0 ? "diced" : "chopped");
    await page.waitForFunction(() => performance.getEntriesByName("foon:plan shown").length > 0);
    await page.locator(".plan-status[data-state='ready']").waitFor();
    await page.waitForFunction(() => (globalThis as { benchPainted?: number }).benchPainted !== undefined);
    times.push(
      await page.evaluate(() => {
        const drawn = performance.getEntriesByName("foon:plan drawn")[0] as PerformanceMeasure | undefined;
        const detail = (drawn?.detail ?? {}) as { views?: Record<string, number>; planner?: number };
        const shown = performance.getEntriesByName("foon:plan shown")[0]?.duration ?? NaN;
        const painted = (globalThis as { benchPainted?: number }).benchPainted ?? NaN;
        const status = Number(/Shown in ([\d.]+) ms/.exec(document.querySelector(".plan-status")?.textContent ?? "")?.[1] ?? NaN);
        return { shown, status, painted, drawn: drawn?.duration ?? NaN, views: detail.views ?? {}, planner: detail.planner ?? NaN };
      }),
    );
  }
  return times;
}

/**
 * Runs in the page before its scripts: when the page measures a plan shown, notes the time at the end of the
 * next frame (a task queued from the next animation frame runs after that frame's paint).
 */
function notePaintAfterShown(): void {
  const measure = performance.measure.bind(performance);
  performance.measure = ((...args: Parameters<Performance["measure"]>) => {
    const entry = measure(...args);
    if (args[0] === "foon:plan shown") {
      requestAnimationFrame(() => setTimeout(() => ((globalThis as { benchPainted?: number }).benchPainted = performance.now() - entry.startTime)));
    }
    return entry;
  }) as Performance["measure"];
}

const median = (xs: number[]): number => {
  const sorted = [...xs].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)] ?? NaN;
};

/** The gzip bytes of every distinct file the visit fetched from dist/. */
function gzipBytes(files: string[]): { total: number; biggest: [string, number][] } {
  const sizes = new Map<string, number>();
  for (const path of files) {
    if (!path.startsWith(PREFIX)) continue;
    const file = join(DIST, path.endsWith("/") ? `${path.slice(PREFIX.length)}index.html` : path.slice(PREFIX.length));
    if (!sizes.has(file) && existsSync(file)) sizes.set(file, gzipSync(readFileSync(file), { level: 9 }).length);
  }
  const biggest = [...sizes].sort((a, b) => b[1] - a[1]).slice(0, 4).map(([f, n]): [string, number] => [f.slice(DIST.length + 1), n]);
  return { total: [...sizes.values()].reduce((a, b) => a + b, 0), biggest };
}

function report(name: string, visits: Visit[]): void {
  const line = PHASES.map((p) => `${p.replace("foon:", "")} ${median(visits.map((v) => v.phases[p] ?? NaN)).toFixed(0)}`).join(", ");
  const kbLoad = median(visits.map((v) => v.phases["kb load took"] ?? NaN)).toFixed(0);
  const from = ["files", "cache", "build"].map((f, i) => [f, visits.filter((v) => v.phases["kb from"] === i).length] as const).filter(([, n]) => n > 0);
  console.log(`  ${name} (median of ${visits.length}, ms after navigation to the end of each phase): ${line}; the kb load took ${kbLoad} (from ${from.map(([f, n]) => `${f} ${n}`).join(", ")} of ${visits.length})`);
}

function reportDownload(name: string, visit: Visit): void {
  const { total, biggest } = gzipBytes(visit.files);
  console.log(`  ${name} download before the first plan: ${(total / 1000).toFixed(0)} kB gzip (${biggest.map(([f, n]) => `${f} ${(n / 1000).toFixed(0)} kB`).join(", ")}, …)`);
}

function reportReplans(replans: Replan[], copyLoad: number): void {
  const ms = (pick: (r: Replan) => number): string => `${median(replans.map(pick)).toFixed(1)} ms`;
  const shown = replans.map((r) => r.shown);
  // a view off screen draws after the plan is shown: its part is 0 in that re-plan
  const names = [...new Set(replans.flatMap((r) => Object.keys(r.views)))];
  const views = names.map((v) => `${v} ${ms((r) => r.views[v] ?? 0)}`).join(", ");
  console.log(
    `  re-plan after an edit (request to the views on screen drawn): median ${ms((r) => r.shown)}, max ${Math.max(...shown).toFixed(1)} ms over ${replans.length} ` +
      `(the status line showed a median of ${ms((r) => r.status)}); ` +
      `to the end of the next frame (painted) ${ms((r) => r.painted)}; ` +
      `medians of its parts: drawing the views ${ms((r) => r.drawn)} (${views || "none"}), the plan ${ms((r) => r.shown - r.drawn)} (the planner's call in it ${ms((r) => r.planner)}); ` +
      `the planner's copy on the page's thread loaded in ${copyLoad.toFixed(0)} ms (once the page was idle after the first plan)`,
  );
}

async function page(browser: Browser, url: string, edit: boolean): Promise<{ cold: Visit[]; warm: Visit[]; replan: Replan[]; copyLoad: number }> {
  const cold: Visit[] = [];
  const warm: Visit[] = [];
  let replan: Replan[] = [];
  let copyLoad = NaN;
  for (let round = 0; round < ROUNDS; round++) {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    await context.addInitScript(notePaintAfterShown);
    const tab = await context.newPage();
    await tab.goto("data:text/html,");
    await tab.waitForTimeout(WINDOW_SETTLE_MS);
    cold.push(await visit(tab, url));
    // re-plans as the user makes them: with the interactive task tree, loaded after the first plan
    if (round === 0 && edit) {
      await tab.locator(".cy canvas").first().waitFor();
      // and with the planner's copy on the page's thread, which makes re-plans once the page was idle after the first plan
      await tab.waitForFunction((name) => performance.getEntriesByName(name).length > 0, COPY_MEASURE, { timeout: 30_000 });
      copyLoad = await tab.evaluate((name) => performance.getEntriesByName(name)[0]!.duration, COPY_MEASURE);
      replan = await replans(tab, 20);
    }
    // warm: the service worker (when the page has one) controls the next visit
    await tab.evaluate(async () => {
      if ((await navigator.serviceWorker.getRegistration()) !== undefined) await navigator.serviceWorker.ready;
    });
    warm.push(await visit(tab, url));
    await context.close();
  }
  return { cold, warm, replan, copyLoad };
}

async function main(): Promise<void> {
  if (!existsSync(join(DIST, "index.html"))) throw new Error("dist/ is not built: run `npm run build` first");
  const browser = await launch();
  const server = await serveStatic(DIST, PREFIX);
  try {
    console.log(`foon-planner browser bench (headless Chromium, ${server.url}, ${ROUNDS} visits each)`);
    const app = await page(browser, `${server.url}?${QUERY}`, true);
    report("page, cold", app.cold);
    report("page, warm", app.warm);
    reportDownload("page", app.cold[0]!);
    reportReplans(app.replan, app.copyLoad);
    const widget = await page(browser, `${server.url}widget.html?${QUERY}`, false);
    report("widget, cold", widget.cold);
    report("widget, warm", widget.warm);
    reportDownload("widget", widget.cold[0]!);
  } finally {
    await server.close();
    await browser.close();
  }
}

main().catch((e: unknown) => {
  console.error(e instanceof Error ? e.message : e);
  process.exit(1);
});
