// The editor page's session with the real WASM module and IndexedDB (fake-indexeddb): "use in planner" saves
// the user's knowledge base with the authored file where the planner page restores it; a knowledge base
// that would not load is not saved; only the newest waiting check runs.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { IDBFactory } from "fake-indexeddb";
import { createKbPersistence, KbStore } from "../../src/app/kb-store";
import { localPlanner } from "../../src/author/draft-eval";
import { BUNDLED_NAME } from "../../src/author/merge";
import { createAuthorSession } from "../../src/author/session";
import { ROOT } from "../../src/planner/node";

const TOAST = ["# title: My toast", "//", "O\tbread\t1", "S\tsliced", "O\ttoaster\t0", "M\ttoast\t<Assumed>", "O\tmy toast\t1\t0", "S\ttoasted", "S\tcontains\t{bread}", ""].join("\n");
const bundled = async () => ({ name: BUNDLED_NAME, bytes: new Uint8Array(readFileSync(join(ROOT, "public/kb/default.foon"))) });

async function session() {
  const factory = new IDBFactory();
  const persistence = createKbPersistence(await KbStore.open(factory), null);
  return { factory, persistence, session: createAuthorSession({ planner: localPlanner(), persistence: Promise.resolve(persistence), bundled }) };
}

describe("the editor's session", () => {
  it("adds the authored file to the bundled knowledge base in the planner's IndexedDB record", async () => {
    const { factory, session: s } = await session();
    const { files, words } = await s.useInPlanner("toast.txt", TOAST);
    expect(files.map((f) => f.name)).toEqual([BUNDLED_NAME, "toast.txt"]);
    expect(words.labels).toContain("my toast");
    expect(words.motions).toContain("dice"); // the bundled knowledge base's motions too
    // what the planner page restores on its next start
    const restored = await createKbPersistence(await KbStore.open(factory), null).restore();
    expect(restored?.map((f) => f.name)).toEqual([BUNDLED_NAME, "toast.txt"]);
    expect(new TextDecoder().decode(restored![1]!.bytes)).toBe(TOAST);
    // a second version replaces the first
    const again = await s.useInPlanner("toast.txt", TOAST.replace("My toast", "My better toast"));
    expect(again.files.map((f) => f.name)).toEqual([BUNDLED_NAME, "toast.txt"]);
  });

  it("saves nothing when the text does not load", async () => {
    const { persistence, session: s } = await session();
    await expect(s.useInPlanner("toast.txt", TOAST.replace("O\tbread\t1", "O\tbread\tone"))).rejects.toThrow(/toast\.txt:3:9/);
    expect(await persistence.restore()).toBeNull();
  });

  it("runs only the newest of the checks waiting for the planner (a burst of keystrokes checks once)", async () => {
    const { session: s } = await session();
    const words = s.words(); // the planner is busy with this one
    const checks = [s.check("a.txt", TOAST), s.check("a.txt", `${TOAST}# 2\n`), s.check("a.txt", TOAST.replace("my toast", "our toast"))];
    const [first, second, third] = await Promise.all(checks);
    expect((await words).labels).toContain("tomato");
    expect([first, second]).toEqual([null, null]);
    expect(third?.preview?.goal.label).toBe("our toast");
  });
});
