// The query in the URL: edits push history entries (a burst of typing is one) once the page is idle,
// back/forward restore.
import { describe, expect, it, vi } from "vitest";
import { EMPTY_QUERY, type AppQuery } from "../../src/app/query";
import { Store } from "../../src/app/store";
import { syncQueryWithUrl } from "../../src/app/url-sync";

class FakeWindow {
  location = { pathname: "/app/", search: "", hash: "" };
  entries: string[] = ["/app/"];
  at = 0;
  private popListeners: (() => void)[] = [];
  history = {
    pushState: (_s: unknown, _t: string, url: string) => {
      this.entries = [...this.entries.slice(0, this.at + 1), url];
      this.at = this.entries.length - 1;
      this.go(url);
    },
    replaceState: (_s: unknown, _t: string, url: string) => {
      this.entries[this.at] = url;
      this.go(url);
    },
  };
  addEventListener(type: string, listener: () => void): void {
    if (type === "popstate") this.popListeners.push(listener);
  }
  removeEventListener(): void {
    this.popListeners = [];
  }
  back(): void {
    this.at -= 1;
    this.go(this.entries[this.at]!);
    for (const l of this.popListeners) l();
  }
  private go(url: string): void {
    const u = new URL(url, "http://x");
    this.location.pathname = u.pathname;
    this.location.search = u.search;
  }
}

const salad: AppQuery = { dish: "salad", ingredients: [{ object: "tomato", state: "diced" }], overrides: {} };
const soup: AppQuery = { dish: "soup", ingredients: [{ object: "carrot", state: "" }], overrides: {} };

describe("URL sync", () => {
  it("pushes a history entry per change, coalescing quick edits, and restores on back", () => {
    vi.useFakeTimers();
    const win = new FakeWindow();
    const store = new Store();
    const setQuery = (q: AppQuery): void => store.set({ query: q });
    syncQueryWithUrl(store, setQuery, win as unknown as Window);

    store.set({ query: salad });
    expect(win.location.search).toBe(""); // not in the edit's task: once the page is idle
    vi.advanceTimersByTime(0);
    expect(win.location.search).toBe("?dish=salad&i=tomato~diced");
    expect(win.entries).toHaveLength(2);
    // typing right after: the same entry
    store.set({ query: { ...salad, ingredients: [{ object: "tomato", state: "dic" }] } });
    store.set({ query: { ...salad, ingredients: [{ object: "tomato", state: "dice" }] } });
    vi.advanceTimersByTime(0);
    expect(win.entries).toEqual(["/app/", "/app/?dish=salad&i=tomato~dice"]);
    vi.advanceTimersByTime(5000);
    store.set({ query: soup });
    vi.advanceTimersByTime(0);
    expect(win.entries).toHaveLength(3);
    expect(win.location.search).toBe("?dish=soup&i=carrot");

    win.back();
    expect(store.state.query.dish).toBe("salad");
    expect(win.entries).toHaveLength(3); // restoring does not push
    win.back();
    expect(store.state.query).toEqual(EMPTY_QUERY);
    vi.useRealTimers();
  });
});
