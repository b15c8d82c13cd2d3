// Nothing typed is lost: the editor's text, its file name and the pasted recipe are written to the
// browser's storage on every change (synchronously, so a crash or a closed tab right after a keystroke
// still finds it) and restored when the page opens again. Each tab writes its own record, so two tabs
// never overwrite each other: the newest is restored, the others are offered (the newest few are kept).

export const AUTOSAVE_PREFIX = "foon-planner-author:";
/** Records kept: one per tab that wrote, the oldest dropped beyond this. */
export const AUTOSAVE_KEEP = 5;

export interface AuthorWork {
  /** The FOON text being written. */
  text: string;
  /** File name it is saved under in the knowledge base (`my-recipe.txt`). */
  name: string;
  /** The recipe text the draft was made from. */
  recipe: string;
}

export interface SavedWork extends AuthorWork {
  /** ms since the epoch. */
  savedAt: number;
}

/** The part of the Web Storage API used here (localStorage in the page, a Map in tests). */
export interface TextStorage {
  readonly length: number;
  key(index: number): string | null;
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
  removeItem(key: string): void;
}

/** Storage for the page's lifetime only: where the browser refuses localStorage (and in tests). */
export function memoryStorage(): TextStorage {
  const memory = new Map<string, string>();
  return {
    get length() {
      return memory.size;
    },
    key: (i) => [...memory.keys()][i] ?? null,
    getItem: (k) => memory.get(k) ?? null,
    setItem: (k, v) => void memory.set(k, v),
    removeItem: (k) => void memory.delete(k),
  };
}

export const EMPTY_WORK: AuthorWork = { text: "", name: "my-recipe.txt", recipe: "" };

function isSaved(value: unknown): value is SavedWork {
  if (typeof value !== "object" || value === null) return false;
  const v = value as Record<string, unknown>;
  return typeof v.text === "string" && typeof v.name === "string" && typeof v.recipe === "string" && typeof v.savedAt === "number";
}

function records(storage: TextStorage): { key: string; work: SavedWork }[] {
  const found: { key: string; work: SavedWork }[] = [];
  for (let i = 0; i < storage.length; i++) {
    const key = storage.key(i);
    if (key === null || !key.startsWith(AUTOSAVE_PREFIX)) continue;
    try {
      const value: unknown = JSON.parse(storage.getItem(key) ?? "");
      if (isSaved(value)) found.push({ key, work: value });
    } catch {
      // an unreadable record is skipped, never fatal
    }
  }
  return found.sort((a, b) => b.work.savedAt - a.work.savedAt);
}

/** The saved works, newest first (never throws). */
export function restoreWorks(storage: TextStorage): SavedWork[] {
  try {
    return records(storage).map((r) => r.work);
  } catch {
    return [];
  }
}

/** Saves this tab's work and drops the oldest records beyond the limit; the reason when the browser refused. */
export function saveWork(storage: TextStorage, tab: string, work: AuthorWork, now: number = Date.now()): string | null {
  try {
    storage.setItem(`${AUTOSAVE_PREFIX}${tab}`, JSON.stringify({ ...work, savedAt: now }));
    for (const old of records(storage).slice(AUTOSAVE_KEEP)) storage.removeItem(old.key);
    return null;
  } catch (e) {
    return e instanceof Error ? e.message : String(e);
  }
}
