// Light and dark themes: the system's by default, the user's choice remembered in local storage.

import { loadPrefs, resolveTheme, savePrefs, type ThemeChoice } from "./prefs";

/** Applies the theme to `target` (an element carrying `.fp-theme`) and follows system changes. */
export function applyTheme(target: HTMLElement, choice: ThemeChoice, onChange?: () => void): () => void {
  const media = window.matchMedia("(prefers-color-scheme: dark)");
  const apply = (): void => {
    target.dataset.theme = resolveTheme(choice, media.matches);
    onChange?.();
  };
  apply();
  media.addEventListener("change", apply);
  return () => media.removeEventListener("change", apply);
}

/** Wires a theme <select> (system / light / dark) to the page's theme and the saved preference. */
export function bindThemePicker(select: HTMLSelectElement, target: HTMLElement, onChange?: () => void): void {
  const prefs = loadPrefs();
  select.value = prefs.theme;
  let stop = applyTheme(target, prefs.theme, onChange);
  select.addEventListener("change", () => {
    const choice = (["system", "light", "dark"] as const).find((c) => c === select.value) ?? "system";
    savePrefs({ ...loadPrefs(), theme: choice });
    stop();
    stop = applyTheme(target, choice, onChange);
  });
}
