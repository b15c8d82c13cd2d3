// Store, preferences and widget options.
import { describe, expect, it, vi } from "vitest";
import { DEFAULT_PREFS, loadPrefs, parsePrefs, resolveTheme, savePrefs } from "../../src/app/prefs";
import { Store } from "../../src/app/store";
import { parseTheme, parseView, widgetIngredients } from "../../src/widget/options";

describe("store", () => {
  it("notifies listeners with the new and previous state, until unsubscribed", () => {
    const store = new Store();
    const listener = vi.fn();
    const stop = store.subscribe(listener);
    store.set({ planning: true });
    expect(listener).toHaveBeenCalledTimes(1);
    expect(listener.mock.calls[0]![0].planning).toBe(true);
    expect(listener.mock.calls[0]![1].planning).toBe(false);
    stop();
    store.set({ planning: false });
    expect(listener).toHaveBeenCalledTimes(1);
  });
});

describe("preferences", () => {
  it("read back what was saved and fall back on anything malformed", () => {
    const data = new Map<string, string>();
    const storage = { getItem: (k: string) => data.get(k) ?? null, setItem: (k: string, v: string) => void data.set(k, v) };
    expect(loadPrefs(storage)).toEqual(DEFAULT_PREFS);
    savePrefs({ theme: "dark" }, storage);
    expect(loadPrefs(storage)).toEqual({ theme: "dark" });
    expect(parsePrefs("{not json")).toEqual(DEFAULT_PREFS);
    expect(parsePrefs(`{"theme":"purple"}`)).toEqual({ theme: "system" });
    expect(loadPrefs(null)).toEqual(DEFAULT_PREFS);
  });
  it("resolve the system theme", () => {
    expect(resolveTheme("system", true)).toBe("dark");
    expect(resolveTheme("system", false)).toBe("light");
    expect(resolveTheme("light", true)).toBe("light");
  });
});

describe("widget options", () => {
  it("read attributes with safe defaults", () => {
    expect(parseView("progress")).toBe("progress");
    expect(parseView("explain")).toBe("explain");
    expect(parseView("bogus")).toBe("all");
    expect(parseView(null)).toBe("all");
    expect(parseTheme("dark")).toBe("dark");
    expect(parseTheme(undefined)).toBe("system");
  });
  it("split ingredient phrases with the knowledge base's states, or take object~state as written", () => {
    expect(widgetIngredients("chopped chili pepper, whole tomato, cool whip", ["chopped", "whole"])).toEqual([
      { object: "chili pepper", state: "chopped" },
      { object: "tomato", state: "whole" },
      { object: "cool whip", state: "" },
    ]);
    expect(widgetIngredients("Sweet Pepper~Roasted", [])).toEqual([{ object: "sweet pepper", state: "roasted" }]);
    expect(widgetIngredients(undefined, [])).toEqual([]);
  });
});
