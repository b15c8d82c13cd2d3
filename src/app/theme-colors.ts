// Colours the canvas/SVG views take from the page's CSS custom properties, so both themes apply to them.

export interface GraphColors {
  text: string;
  background: string;
  object: string;
  motion: string;
  edge: string;
  mark: string;
  select: string;
  line: string;
}

export function readColors(element: Element): GraphColors {
  const style = getComputedStyle(element);
  const v = (name: string, fallback: string): string => style.getPropertyValue(name).trim() || fallback;
  return {
    text: v("--fp-fg", "#1b1b1b"),
    background: v("--fp-bg", "#ffffff"),
    object: v("--fp-object", "#2e7d32"),
    motion: v("--fp-motion", "#c62828"),
    edge: v("--fp-edge", "#777777"),
    mark: v("--fp-mark", "#1565c0"),
    select: v("--fp-select", "#f9a825"),
    line: v("--fp-line", "#f9a825"),
  };
}
