// Nothing typed is lost: the editor's text, its file name and the pasted recipe are written to the
// browser's storage on every change (synchronously, so a crash or a closed tab right after a keystroke
// still finds it) and restored when the page opens again.

export const AUTOSAVE_KEY = "foon-planner-author";

export interface AuthorWork {
  /** The FOON text being written. */
  text: string;
  /** File name it is saved under in the knowledge base (`my-recipe.txt`). */
  name: string;
  /** The recipe text the draft was made from. */
  recipe: string;
}

/** The part of the Web Storage API used here (localStorage in the page, a Map in tests). */
export interface TextStorage {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
}

export const EMPTY_WORK: AuthorWork = { text: "", name: "my-recipe.txt", recipe: "" };

function isWork(value: unknown): value is AuthorWork {
  if (typeof value !== "object" || value === null) return false;
  const v = value as Record<string, unknown>;
  return typeof v.text === "string" && typeof v.name === "string" && typeof v.recipe === "string";
}

/** The saved work, or null when there is none or it is unreadable (never throws). */
export function restoreWork(storage: TextStorage): AuthorWork | null {
  try {
    const raw = storage.getItem(AUTOSAVE_KEY);
    if (raw === null) return null;
    const value: unknown = JSON.parse(raw);
    return isWork(value) ? value : null;
  } catch {
    return null;
  }
}

/** Saves the work; the reason when the browser refused (full, private mode), else null. */
export function saveWork(storage: TextStorage, work: AuthorWork): string | null {
  try {
    storage.setItem(AUTOSAVE_KEY, JSON.stringify(work));
    return null;
  } catch (e) {
    return e instanceof Error ? e.message : String(e);
  }
}
