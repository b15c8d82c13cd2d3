// The user's own knowledge base survives a reload (IndexedDB), two tabs learn of each other's choice
// (BroadcastChannel), and a full storage keeps the files in memory with an offer to download them. A reload
// loads the user's files from the browser's cache of the parsed knowledge base (the bundled one from the
// build's snapshot).
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser, BrowserContext, Page } from "playwright-core";
import { launch, screenshot, watchErrors } from "./browser";
import { downloadOf, scrollToTools, waitForPlan } from "./app-helpers";
import { KB_DB_NAME, KB_KEY, KB_STORE } from "../../src/app/kb-store";
import { CACHE_DB_NAME } from "../../src/worker/kb-cache";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

const kb = (title: string, dish: string): string =>
  [`# title: ${title}`, "//", "O\tbread\t1", "S\tsliced", "O\ttoaster\t0", "M\ttoast\t<Assumed>", `O\t${dish}\t1\t0`, "S\ttoasted", "S\tcontains\t{bread}", ""].join("\n");
const HOSTILE = "my <b>toast</b>.txt";
const QUERY = "?dish=bread&i=bread~sliced";

async function newPage(context: BrowserContext): Promise<{ page: Page; errors: string[] }> {
  const page = await context.newPage();
  page.on("dialog", (d) => {
    throw new Error(`unexpected dialog: ${d.message()}`);
  });
  return { page, errors: watchErrors(page) };
}

async function loadFile(page: Page, name: string, text: string): Promise<void> {
  await page.getByLabel(/Load your own FOON files/).setInputFiles([{ name, mimeType: "text/plain", buffer: Buffer.from(text) }]);
}

const goal = (page: Page): Promise<string | null> => page.locator(".panel-reference .goal-label").textContent();

/** Waits until the page's choice is in IndexedDB (the panel shows it at once; the write ends a moment
 * later, and a reload before that restores the previous choice). */
async function waitForSaved(page: Page, choice: "custom" | "bundled"): Promise<void> {
  await page.waitForFunction(
    async ([dbName, storeName, key, custom]) => {
      const db = await new Promise<IDBDatabase>((resolve, reject) => {
        const req = indexedDB.open(dbName);
        req.onsuccess = () => resolve(req.result);
        req.onerror = () => reject(req.error);
      });
      try {
        if (!db.objectStoreNames.contains(storeName)) return false;
        const saved = await new Promise<{ files: unknown[] | null } | undefined>((resolve, reject) => {
          const req = db.transaction(storeName).objectStore(storeName).get(key);
          req.onsuccess = () => resolve(req.result as { files: unknown[] | null } | undefined);
          req.onerror = () => reject(req.error);
        });
        return saved !== undefined && (saved.files !== null) === custom;
      } finally {
        db.close();
      }
    },
    [KB_DB_NAME, KB_STORE, KB_KEY, choice === "custom"] as const,
    { polling: 50 },
  );
}

/** Where the last knowledge base was loaded from: its files, the browser's cache of its snapshot, or the build's snapshot. */
const loadedFrom = (page: Page): Promise<unknown> =>
  page.evaluate(() => (performance.getEntriesByName("foon:kb load").at(-1) as PerformanceMeasure | undefined)?.detail?.from);

/** Waits until the planner has cached `n` parsed knowledge bases (it does so after their first plan). */
async function waitForCached(page: Page, n: number): Promise<void> {
  await page.waitForFunction(
    async ([dbName, n]) => {
      const db = await new Promise<IDBDatabase>((resolve, reject) => {
        const req = indexedDB.open(dbName);
        req.onsuccess = () => resolve(req.result);
        req.onerror = () => reject(req.error);
      });
      try {
        const names = [...db.objectStoreNames];
        if (names.length === 0) return false;
        const count = await new Promise<number>((resolve, reject) => {
          const req = db.transaction(names).objectStore(names[0]!).count();
          req.onsuccess = () => resolve(req.result);
          req.onerror = () => reject(req.error);
        });
        return count >= n;
      } finally {
        db.close();
      }
    },
    [CACHE_DB_NAME, n] as const,
    { polling: 50 },
  );
}

describe("the user's knowledge base persists", () => {
  it("is restored after a reload and forgotten after switching back to the bundled one", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    const { page, errors } = await newPage(context);
    await page.goto(`${inject("baseUrl")}${QUERY}`);
    await waitForPlan(page);
    expect(await loadedFrom(page)).toBe("build"); // the bundled knowledge base: the snapshot shipped with it
    await loadFile(page, HOSTILE, kb("My own toast", "toast"));
    await page.locator(".kb-status[data-source='custom']").waitFor();
    await waitForPlan(page);
    expect(await goal(page)).toBe("My own toast");
    expect(await loadedFrom(page)).toBe("files");
    await waitForSaved(page, "custom");
    await waitForCached(page, 1);

    // restored from the browser's cache of the parsed files, with the same plan
    await page.reload();
    await page.locator(".kb-status[data-source='custom']").waitFor();
    await waitForPlan(page);
    expect(await loadedFrom(page)).toBe("cache");
    expect(await page.locator(".kb-notice").textContent()).toBe("Your knowledge base (1 file) restored.");
    expect(await page.locator(".kb-status").textContent()).toContain(HOSTILE); // as text, not markup
    expect(await page.locator(".panel-kb b").count()).toBe(0);
    expect(await goal(page)).toBe("My own toast");
    await screenshot(page, "kb-persist-restored");

    await scrollToTools(page);
    await page.getByRole("button", { name: "Use the bundled knowledge base" }).click();
    await page.locator(".kb-status[data-source='bundled']").waitFor();
    await waitForSaved(page, "bundled");
    await page.reload();
    await page.locator(".kb-status[data-source='bundled']").waitFor();
    await waitForPlan(page);
    expect(await page.locator(".kb-notice").isHidden()).toBe(true);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("tells a second tab when the first one loads or clears its knowledge base", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
    const { page: one, errors } = await newPage(context);
    const { page: two } = await newPage(context);
    await one.goto(`${inject("baseUrl")}${QUERY}`);
    await two.goto(`${inject("baseUrl")}${QUERY}`);
    await waitForPlan(one);
    await waitForPlan(two);

    await loadFile(one, "pear.txt", kb("Tab one toast", "toast"));
    await one.locator(".kb-status[data-source='custom']").waitFor();
    await two.locator(".kb-status[data-source='custom']").waitFor();
    await waitForPlan(two);
    expect(await two.locator(".kb-notice").textContent()).toBe("Your knowledge base (1 file) was loaded in another tab; it is loaded here too.");
    expect(await goal(two)).toBe("Tab one toast");
    await screenshot(two, "kb-persist-other-tab");

    // the second tab's later choice wins in both, and survives a reload of the first
    await loadFile(two, "fig.txt", kb("Tab two toast", "toast"));
    await one.waitForFunction(() => document.querySelector(".panel-reference .goal-label")?.textContent === "Tab two toast", undefined, { timeout: 30_000 });
    await one.reload();
    await waitForPlan(one);
    expect(await goal(one)).toBe("Tab two toast");

    await scrollToTools(two);
    await two.getByRole("button", { name: "Use the bundled knowledge base" }).click();
    await one.locator(".kb-status[data-source='bundled']").waitFor();
    expect(await one.locator(".kb-notice").textContent()).toMatch(/Another tab switched back to the bundled knowledge base/);
    expect(errors).toEqual([]);
    await context.close();
  });

  it("keeps working in memory when the storage is full, and offers the files for download", async () => {
    const context = await browser.newContext({ viewport: { width: 1400, height: 1000 }, acceptDownloads: true });
    await context.addInitScript(() => {
      IDBObjectStore.prototype.put = function put(): IDBRequest<IDBValidKey> {
        throw new DOMException("The quota has been exceeded.", "QuotaExceededError");
      };
    });
    const { page } = await newPage(context);
    await page.goto(`${inject("baseUrl")}${QUERY}`);
    await waitForPlan(page);
    const text = kb("Unsaved toast", "toast");
    await loadFile(page, HOSTILE, text);
    await page.locator(".kb-unsaved:not([hidden])").waitFor();
    await waitForPlan(page);
    expect(await goal(page)).toBe("Unsaved toast"); // still planning with it
    expect(await page.locator(".kb-unsaved").textContent()).toMatch(/won't survive a reload \(.*quota/i);
    await scrollToTools(page);
    const button = page.getByRole("button", { name: `Download ${HOSTILE}` });
    const file = await downloadOf(page, () => button.click());
    expect(file.name).toBe(HOSTILE.replace(/[<>]/g, "_").replace(/\//g, "_"));
    expect(file.bytes.toString()).toBe(text);
    await screenshot(page, "kb-persist-quota");
    await context.close();
  });
});
