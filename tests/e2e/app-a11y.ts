// In-page checks of the accessibility basics (run with page.evaluate): every form control has a label,
// and text meets WCAG AA contrast (4.5:1) against the background it is drawn on.

export interface ContrastFailure {
  text: string;
  ratio: number;
}

/** Runs in the page: form controls without an accessible name, as short descriptions. */
export function unlabelledControls(): string[] {
  return [...document.querySelectorAll<HTMLElement>("input:not([type=hidden]), select, textarea")]
    .filter((e) => {
      const control = e as HTMLInputElement;
      const labelled = (control.labels?.length ?? 0) > 0 || e.hasAttribute("aria-label") || e.hasAttribute("aria-labelledby");
      return !labelled;
    })
    .map((e) => e.outerHTML.slice(0, 80));
}

/** Runs in the page: text elements whose contrast with their background is below `min`. */
export function lowContrast({ selector, min }: { selector: string; min: number }): ContrastFailure[] {
  type Rgba = [number, number, number, number];
  const parse = (value: string): Rgba => {
    const numbers = (value.match(/[\d.]+/g) ?? []).map(Number);
    if (value.startsWith("color(srgb")) return [numbers[0]! * 255, numbers[1]! * 255, numbers[2]! * 255, numbers[3] ?? 1];
    return [numbers[0] ?? 0, numbers[1] ?? 0, numbers[2] ?? 0, numbers[3] ?? 1];
  };
  const over = (top: Rgba, bottom: Rgba): Rgba => {
    const a = top[3];
    return [top[0] * a + bottom[0] * (1 - a), top[1] * a + bottom[1] * (1 - a), top[2] * a + bottom[2] * (1 - a), 1];
  };
  const background = (e: Element | null): Rgba => {
    const layers: Rgba[] = [];
    for (let n: Element | null = e; n !== null; n = n.parentElement ?? ((n.getRootNode() as ShadowRoot).host ?? null)) {
      const c = parse(getComputedStyle(n).backgroundColor);
      if (c[3] > 0) layers.push(c);
      if (c[3] >= 1) break;
    }
    return layers.reduceRight<Rgba>((acc, layer) => over(layer, acc), [255, 255, 255, 1]);
  };
  const luminance = ([r, g, b]: Rgba): number => {
    const f = (v: number): number => {
      const s = v / 255;
      return s <= 0.03928 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
    };
    return 0.2126 * f(r) + 0.7152 * f(g) + 0.0722 * f(b);
  };
  const failures: ContrastFailure[] = [];
  for (const e of document.querySelectorAll<HTMLElement>(selector)) {
    if (e.offsetParent === null || (e.textContent ?? "").trim() === "" || (e as HTMLButtonElement).disabled) continue;
    const bg = background(e);
    const fg = over(parse(getComputedStyle(e).color), bg);
    const [l1, l2] = [luminance(fg), luminance(bg)].sort((a, b) => b - a) as [number, number];
    const ratio = (l1 + 0.05) / (l2 + 0.05);
    if (ratio < min) failures.push({ text: `${e.tagName.toLowerCase()}.${e.className}: ${(e.textContent ?? "").trim().slice(0, 30)}`, ratio: Math.round(ratio * 100) / 100 });
  }
  return failures;
}
