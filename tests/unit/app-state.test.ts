// Store, preferences, widget options and the knowledge-base vocabulary.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it, vi } from "vitest";
import { DEFAULT_PREFS, loadPrefs, parsePrefs, resolveTheme, savePrefs } from "../../src/app/prefs";
import { Store } from "../../src/app/store";
import { ROOT } from "../../src/planner/node";
import { scanVocabulary, titleFromFileName } from "../../src/planner/vocabulary";
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

describe("vocabulary of a knowledge base", () => {
  it("lists dish classes with recipe titles, labels and plain states of the bundle", () => {
    const bytes = readFileSync(join(ROOT, "public/kb/default.foon"));
    const vocab = scanVocabulary([{ name: "default.foon", bytes: new Uint8Array(bytes) }]);
    const salad = vocab.dishes.find((d) => d.name === "salad");
    expect(salad?.recipes).toContain("Greek salad");
    expect(vocab.titles["s01-greek_salad.txt"]).toBe("Greek salad");
    expect(vocab.labels).toContain("tomato");
    expect(vocab.states).toEqual(expect.arrayContaining(["whole", "diced", "chopped"]));
    expect(vocab.states.some((s) => s.includes("[") || s.includes("{"))).toBe(false);
  });
  it("titles a file without a title line by its name", () => {
    expect(titleFromFileName("0001-whipped_cream.txt")).toBe("whipped cream");
    expect(titleFromFileName("s01-greek_salad.txt")).toBe("greek salad");
    expect(titleFromFileName("0097-miso_soup-DONE.txt")).toBe("miso soup");
  });
  it("reads a plain file without a bundle marker", () => {
    const text = "# title: Toast\n//\nO\tbread\t1\nS\tsliced\nM\ttoast\t<Assumed>\nO\ttoast\t1\t0\nS\ttoasted\nS\ton\t[plate]\n";
    const vocab = scanVocabulary([{ name: "toast.txt", bytes: new TextEncoder().encode(text) }]);
    expect(vocab).toEqual({ dishes: [{ name: "bread", recipes: ["Toast"] }], labels: ["bread", "toast"], states: ["sliced", "toasted"], titles: { "toast.txt": "Toast" } });
  });
});
