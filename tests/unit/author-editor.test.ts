// The FOON editor's logic without a browser: undo/redo, autosave and restore, completion, line colouring,
// and how "use in planner" merges the authored file into the user's knowledge base.
import { describe, expect, it } from "vitest";
import { AUTOSAVE_KEEP, AUTOSAVE_PREFIX, memoryStorage, restoreWorks, saveWork } from "../../src/author/autosave";
import { applyCompletion, completeAt } from "../../src/author/complete";
import { EditHistory } from "../../src/author/history";
import { BUNDLED_NAME, cleanFileName, withAuthored } from "../../src/author/merge";
import { lineKind, motionsOf, tokenizeLine } from "../../src/author/tokens";
import { bundleText } from "../../src/planner/bundle";
import { encode } from "./helpers";

const at = (text: string) => ({ text, start: text.length, end: text.length });

describe("undo and redo", () => {
  it("undoes a word typed letter by letter in one step, and redoes it", () => {
    const h = new EditHistory(at(""));
    for (const text of ["t", "to", "tom"]) h.record(at(text), "type");
    expect(h.undo()?.text).toBe("");
    expect(h.redo()?.text).toBe("tom");
    expect(h.canRedo).toBe(false);
  });

  it("ends a typing step at whitespace and at a change of kind", () => {
    const h = new EditHistory(at(""));
    for (const text of ["O", "O\t", "O\tb", "O\tba"]) h.record(at(text), "type");
    h.record(at("O\tb"), "delete");
    expect(h.undo()?.text).toBe("O\tba");
    expect(h.undo()?.text).toBe("O\t");
    expect(h.undo()?.text).toBe("O");
  });

  it("keeps a replacement (a draft) as its own step and drops the redo branch on a new edit", () => {
    const h = new EditHistory(at("mine"));
    h.record(at("drafted"), "replace");
    expect(h.undo()?.text).toBe("mine");
    h.record(at("mine!"), "type");
    expect(h.canRedo).toBe(false);
    expect(h.undo()?.text).toBe("mine");
    expect(h.undo()).toBeNull();
  });
});

describe("autosave", () => {
  const work = { text: "O\ttomato\t1\n", name: "salsa.txt", recipe: "Salsa\n1. Dice the tomato." };

  it("restores exactly what was saved", () => {
    const storage = memoryStorage();
    expect(saveWork(storage, "tab-1", work, 1000)).toBeNull();
    expect(restoreWorks(storage)).toEqual([{ ...work, savedAt: 1000 }]);
  });

  it("keeps each tab's work apart, newest first, and drops the oldest beyond the limit", () => {
    const storage = memoryStorage();
    saveWork(storage, "a", { ...work, text: "from a" }, 1);
    saveWork(storage, "b", { ...work, text: "from b" }, 2);
    saveWork(storage, "a", { ...work, text: "from a, later" }, 3);
    expect(restoreWorks(storage).map((w) => w.text)).toEqual(["from a, later", "from b"]);
    for (let i = 0; i < AUTOSAVE_KEEP + 2; i++) saveWork(storage, `tab-${i}`, { ...work, text: `text ${i}` }, 10 + i);
    const kept = restoreWorks(storage);
    expect(kept).toHaveLength(AUTOSAVE_KEEP);
    expect(kept[0]!.text).toBe(`text ${AUTOSAVE_KEEP + 1}`);
  });

  it("says why when the browser refuses, and skips unreadable records", () => {
    const full = { ...memoryStorage(), setItem: () => {
      throw new Error("QuotaExceededError");
    } };
    expect(saveWork(full, "a", work)).toContain("QuotaExceededError");
    const storage = memoryStorage();
    storage.setItem(`${AUTOSAVE_PREFIX}x`, "{not json");
    storage.setItem(`${AUTOSAVE_PREFIX}y`, JSON.stringify({ text: 3 }));
    saveWork(storage, "z", work, 5);
    expect(restoreWorks(storage)).toEqual([{ ...work, savedAt: 5 }]);
  });
});

describe("completion", () => {
  const words = { labels: ["red onion", "tomato", "tomato sauce"], states: ["diced", "sliced"], motions: ["dice", "slice"] };

  it("offers the knowledge base's words of the line's kind, prefix matches first", () => {
    expect(completeAt("O\ttom", 5, words)?.options).toEqual(["tomato", "tomato sauce"]);
    expect(completeAt("O\toni", 5, words)?.options).toEqual(["red onion"]);
    expect(completeAt("S\tsl", 4, words)?.options).toEqual(["sliced"]);
    expect(completeAt("M\td", 3, words)?.options).toEqual(["dice"]);
  });

  it("offers nothing outside the name field", () => {
    expect(completeAt("O\ttomato\t1", 10, words)).toBeNull();
    expect(completeAt("# tom", 5, words)).toBeNull();
    expect(completeAt("O", 1, words)).toBeNull();
  });

  it("replaces the whole word, also the part after the caret", () => {
    const text = "O\ttoma\t1";
    const c = completeAt(text, 5, words)!;
    expect(applyCompletion(text, c, "tomato")).toEqual({ text: "O\ttomato\t1", caret: 8 });
  });
});

describe("line colouring", () => {
  it("tells the kinds of lines apart and keeps the text exactly", () => {
    expect(["O\ttomato\t1", "S\tin\t[bowl]", "M\tdice\t<Assumed>", "//", "# title: x", "# confirm: guess", "X\t?"].map(lineKind)).toEqual([
      "object",
      "state",
      "motion",
      "separator",
      "comment",
      "confirm",
      "other",
    ]);
    const line = "S\tin\t[bowl]";
    expect(tokenizeLine(line).map((t) => t.text).join("")).toBe(line);
    expect(motionsOf("M\tslice\t<A>\nO\tx\t1\nM\tdice\t<A>\nM\tslice\t<A>")).toEqual(["dice", "slice"]);
  });
});

describe("use in planner", () => {
  const authored = { name: "salsa.txt", bytes: encode("# title: Salsa\n") };
  const bundled = async () => ({ name: BUNDLED_NAME, bytes: encode("#@file a.txt\n# title: A\n") });

  it("adds the file to the bundled knowledge base when the user has none", async () => {
    expect((await withAuthored(null, bundled, authored)).map((f) => f.name)).toEqual([BUNDLED_NAME, "salsa.txt"]);
  });

  it("replaces an earlier version of the same file and keeps the user's other files", async () => {
    const saved = [{ name: "mine.txt", bytes: encode("x") }, { name: "salsa.txt", bytes: encode("old") }];
    const files = await withAuthored(saved, bundled, authored);
    expect(files.map((f) => f.name)).toEqual(["mine.txt", "salsa.txt"]);
    expect(files[1]).toBe(authored);
  });

  it("exports one bundle in which a bundled file keeps its own file marks", async () => {
    const text = bundleText(await withAuthored(null, bundled, authored));
    expect(text).toBe("#@file a.txt\n# title: A\n#@file salsa.txt\n# title: Salsa\n");
  });

  it("names files so the knowledge base can hold them", () => {
    expect(cleanFileName(" my/salsa ")).toBe("my-salsa.txt");
    expect(cleanFileName("salsa.TXT")).toBe("salsa.txt");
    expect(cleanFileName("")).toBe("my-recipe.txt");
  });
});
