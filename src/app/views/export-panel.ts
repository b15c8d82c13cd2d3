// Keeping and sharing: the task tree as FOON text, JSON and PDDL, the progress lines as JSON, and the
// graph as PNG and SVG.

import type { ExportFormat } from "../../planner/types";
import { el } from "../dom";
import type { StateSource } from "../draw-schedule";
import type { AppState } from "../store";

export type DownloadFormat = ExportFormat | "png" | "svg";

export interface ExportActions {
  exportAs(format: DownloadFormat): void;
}

const BUTTONS: { format: DownloadFormat; text: string }[] = [
  { format: "foon", text: "FOON text" },
  { format: "json", text: "Plan JSON" },
  { format: "pddl", text: "PDDL" },
  { format: "progress", text: "Progress lines JSON" },
  { format: "png", text: "Graph PNG" },
  { format: "svg", text: "Graph SVG" },
];

export function mountExportPanel(host: HTMLElement, store: StateSource, actions: ExportActions): () => void {
  const buttons = BUTTONS.map(({ format, text }) => {
    const b = el("button", { type: "button", "data-format": format, text });
    b.addEventListener("click", () => actions.exportAs(format));
    return b;
  });
  host.replaceChildren(el("h2", { text: "Export" }), el("div", { class: "toolbar wrap", role: "group", "aria-label": "Downloads" }, ...buttons));
  const update = (state: AppState): void => {
    for (const b of buttons) b.disabled = state.plan === null;
  };
  update(store.state);
  return store.subscribe(update);
}
