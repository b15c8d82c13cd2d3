// The user's knowledge base in IndexedDB (fake-indexeddb): write-through, restore, forgetting, refusing
// stale saves, full storage, and news between two tabs over a (fake) BroadcastChannel.
import { afterEach, describe, expect, it, vi } from "vitest";
import { IDBFactory, IDBObjectStore } from "fake-indexeddb";
import { createKbPersistence, KbStore, StaleSaveError, type KbChannel, type KbMessage } from "../../src/app/kb-store";
import { StorageError } from "../../src/eval/storage";

const file = (name: string, text: string) => ({ name, bytes: new TextEncoder().encode(text) });

/** Channels joined like BroadcastChannels of one name: a message reaches every other one. */
function channels(n: number): KbChannel[] {
  const all: KbChannel[] = [];
  for (let i = 0; i < n; i++) {
    const channel: KbChannel = {
      onmessage: null,
      postMessage(message: KbMessage) {
        for (const other of all) if (other !== channel) queueMicrotask(() => other.onmessage?.(new MessageEvent("message", { data: message })));
      },
      close() {},
    };
    all.push(channel);
  }
  return all;
}

afterEach(() => vi.restoreAllMocks());

describe("knowledge-base store", () => {
  it("saves, restores and forgets the user's files, with increasing versions", async () => {
    const factory = new IDBFactory();
    const store = await KbStore.open(factory);
    expect(await store.load()).toBeNull();
    const first = await store.save([file("a.txt", "A"), file("<b>.txt", "B")], 1000);
    expect(first.version).toBe(1);
    store.close();

    const reopened = createKbPersistence(await KbStore.open(factory), null);
    const restored = await reopened.restore();
    expect(restored?.map((f) => f.name)).toEqual(["a.txt", "<b>.txt"]);
    expect(new TextDecoder().decode(restored![1]!.bytes)).toBe("B");
    const cleared = await reopened.save(null, 2000);
    expect(cleared.version).toBe(2);
    expect(await reopened.restore()).toBeNull();
  });

  it("never clobbers a newer save", async () => {
    const store = await KbStore.open(new IDBFactory());
    await store.save([file("new.txt", "N")], 5000);
    const stale = await store.save([file("old.txt", "O")], 4000).catch((e: unknown) => e);
    expect(stale).toBeInstanceOf(StaleSaveError);
    expect((stale as StaleSaveError).current.files?.[0]?.name).toBe("new.txt");
    expect((await store.load())?.files?.[0]?.name).toBe("new.txt");
  });

  it("reports a full storage as a quota error and keeps the previous save", async () => {
    const store = await KbStore.open(new IDBFactory());
    await store.save([file("kept.txt", "K")], 1);
    vi.spyOn(IDBObjectStore.prototype, "put").mockImplementation(() => {
      throw new DOMException("The quota has been exceeded.", "QuotaExceededError");
    });
    const error = await store.save([file("big.txt", "B")], 2).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(StorageError);
    expect((error as StorageError).quota).toBe(true);
    vi.restoreAllMocks();
    expect((await store.load())?.files?.[0]?.name).toBe("kept.txt");
  });

  it("without IndexedDB every save fails with the reason, and restore finds nothing to restore", async () => {
    const persistence = createKbPersistence(null, null, "private mode");
    await expect(persistence.save([file("a.txt", "A")])).rejects.toThrow(/private mode/);
    await expect(persistence.restore()).rejects.toBeInstanceOf(StorageError);
  });

  it("tells the other tab of a new save, once, and not the saving tab", async () => {
    const factory = new IDBFactory();
    const [c1, c2] = channels(2);
    const tab1 = createKbPersistence(await KbStore.open(factory), c1!);
    const tab2 = createKbPersistence(await KbStore.open(factory), c2!);
    const seen1: number[] = [];
    const seen2: (string[] | null)[] = [];
    tab1.onRemoteChange((s) => seen1.push(s.version));
    tab2.onRemoteChange((s) => seen2.push(s.files?.map((f) => f.name) ?? null));
    await tab1.save([file("mine.txt", "M")], 10);
    await vi.waitFor(() => expect(seen2).toEqual([["mine.txt"]]));
    await tab2.save(null, 20);
    await vi.waitFor(() => expect(seen1).toEqual([2]));
    expect(seen2).toEqual([["mine.txt"]]);
    // a late save of an older choice is refused, and tells the caller what is newer
    await expect(tab1.save([file("late.txt", "L")], 15)).rejects.toBeInstanceOf(StaleSaveError);
    expect(await tab2.restore()).toBeNull();
  });
});
