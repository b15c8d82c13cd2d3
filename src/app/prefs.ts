// Preferences kept in local storage (the query itself lives in the URL). Storage may be unavailable
// (private windows, sandboxed iframes): then preferences just are not remembered.

export type ThemeChoice = "system" | "light" | "dark";

export interface Prefs {
  theme: ThemeChoice;
}

const KEY = "foon-planner.prefs.v1";
export const DEFAULT_PREFS: Prefs = { theme: "system" };

export function parsePrefs(text: string | null): Prefs {
  if (text === null) return DEFAULT_PREFS;
  try {
    const data: unknown = JSON.parse(text);
    if (typeof data !== "object" || data === null) return DEFAULT_PREFS;
    const theme = (data as { theme?: unknown }).theme;
    return { theme: theme === "light" || theme === "dark" || theme === "system" ? theme : "system" };
  } catch {
    return DEFAULT_PREFS;
  }
}

export function loadPrefs(storage: Pick<Storage, "getItem"> | null = safeStorage()): Prefs {
  return parsePrefs(storage?.getItem(KEY) ?? null);
}

export function savePrefs(prefs: Prefs, storage: Pick<Storage, "setItem"> | null = safeStorage()): void {
  try {
    storage?.setItem(KEY, JSON.stringify(prefs));
  } catch {
    // quota or disabled storage: not remembering is fine
  }
}

function safeStorage(): Storage | null {
  try {
    return typeof localStorage === "undefined" ? null : localStorage;
  } catch {
    return null;
  }
}

/** The theme to show: the user's choice, else the system's. */
export function resolveTheme(choice: ThemeChoice, systemDark: boolean): "light" | "dark" {
  return choice === "system" ? (systemDark ? "dark" : "light") : choice;
}
