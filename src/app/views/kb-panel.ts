// The knowledge-base panel: statistics of the loaded FOON, loading your own FOON `.txt` files at runtime
// (drop them on the page or pick them; they are merged in WASM), errors with file and line, and the way
// back to the bundled knowledge base.

import type { Stats } from "../../planner/types";
import { el, plural, uid } from "../dom";
import type { StateSource } from "../draw-schedule";
import type { AppState } from "../store";

export interface KnowledgeBaseActions {
  loadFiles(files: File[]): void;
  useBundled(): void;
  /** Downloads one of the user's files (by index), when the browser could not save them. */
  downloadFile(index: number): void;
}

function statsRows(stats: Stats): [string, string][] {
  return [
    ["Recipes (subgraphs)", String(stats.subgraphs)],
    ["Functional units", String(stats.units)],
    ["Object nodes", String(stats.object_nodes)],
    ["Labels", String(stats.labels)],
    ["States", String(stats.states)],
    ["Motions", String(stats.motions)],
    ["Goal nodes", String(stats.goal_nodes)],
  ];
}

export function mountKnowledgeBasePanel(host: HTMLElement, store: StateSource, actions: KnowledgeBaseActions, dropTarget: HTMLElement): () => void {
  const inputId = uid("kb-files");
  const status = el("p", { class: "kb-status", role: "status" });
  const error = el("p", { class: "kb-error", role: "alert" });
  const notice = el("p", { class: "kb-notice", role: "status" });
  const unsavedText = el("p", {});
  const unsavedFiles = el("ul", { class: "kb-unsaved-files" });
  const unsaved = el("div", { class: "kb-unsaved", role: "alert" }, unsavedText, unsavedFiles);
  const input = el("input", { id: inputId, type: "file", multiple: true, accept: ".txt,.foon,text/plain", class: "kb-input" });
  const bundled = el("button", { type: "button", class: "kb-bundled", text: "Use the bundled knowledge base" });
  const body = el("tbody");
  host.replaceChildren(
    el("h2", { text: "Knowledge base" }),
    status,
    notice,
    unsaved,
    error,
    el(
      "div",
      { class: "field kb-load" },
      el("label", { for: inputId, text: "Load your own FOON files (.txt; one or many, merged), or drop them on the page" }),
      input,
    ),
    bundled,
    el("table", { class: "kb-stats" }, el("caption", { class: "muted small", text: "Universal FOON after merging" }), body),
  );

  input.addEventListener("change", () => {
    const files = [...(input.files ?? [])];
    input.value = "";
    if (files.length > 0) actions.loadFiles(files);
  });
  bundled.addEventListener("click", () => actions.useBundled());

  // dropping files anywhere on the app loads them
  const onDragOver = (event: DragEvent): void => {
    if (event.dataTransfer?.types.includes("Files") !== true) return;
    event.preventDefault();
    dropTarget.classList.add("dropping");
  };
  const onDragLeave = (event: DragEvent): void => {
    if (event.target === dropTarget) dropTarget.classList.remove("dropping");
  };
  const onDrop = (event: DragEvent): void => {
    const files = [...(event.dataTransfer?.files ?? [])];
    if (files.length === 0) return;
    event.preventDefault();
    dropTarget.classList.remove("dropping");
    actions.loadFiles(files);
  };
  dropTarget.addEventListener("dragover", onDragOver);
  dropTarget.addEventListener("dragleave", onDragLeave);
  dropTarget.addEventListener("drop", onDrop);

  const update = (state: AppState, previous: AppState | null): void => {
    if (
      previous !== null &&
      state.kb === previous.kb &&
      state.kbError === previous.kbError &&
      state.kbSource === previous.kbSource &&
      state.kbNotice === previous.kbNotice &&
      state.kbUnsaved === previous.kbUnsaved
    )
      return;
    notice.textContent = state.kbNotice ?? "";
    notice.hidden = state.kbNotice === null;
    unsaved.hidden = state.kbUnsaved === null;
    unsavedText.textContent =
      state.kbUnsaved === null ? "" : `Your files are loaded but won't survive a reload (${state.kbUnsaved.reason}). Download them to keep them:`;
    unsavedFiles.replaceChildren(
      ...(state.kbUnsaved?.names ?? []).map((name, i) => {
        const button = el("button", { type: "button", class: "kb-download", text: `Download ${name}` });
        button.addEventListener("click", () => actions.downloadFile(i));
        return el("li", {}, button);
      }),
    );
    const kb = state.kb;
    status.textContent =
      kb === null
        ? "Loading the knowledge base…"
        : `${state.kbSource === "bundled" ? "Bundled" : "Your"} knowledge base (${kb.name}): ${plural(kb.stats.subgraphs, "recipe")}, ${plural(kb.stats.units, "functional unit")}` +
          (kb.warnings.length === 0 ? "." : `, ${plural(kb.warnings.length, "warning")}.`);
    status.dataset.state = kb === null ? "loading" : "ready";
    status.dataset.source = state.kbSource;
    error.textContent = state.kbError ?? "";
    error.hidden = state.kbError === null;
    bundled.disabled = state.kbSource === "bundled";
    body.replaceChildren(
      ...(kb === null ? [] : statsRows(kb.stats)).map(([name, value]) => el("tr", {}, el("th", { scope: "row", text: name }), el("td", { text: value }))),
    );
  };
  update(store.state, null);
  const unsubscribe = store.subscribe(update);
  return () => {
    unsubscribe();
    dropTarget.removeEventListener("dragover", onDragOver);
    dropTarget.removeEventListener("dragleave", onDragLeave);
    dropTarget.removeEventListener("drop", onDrop);
  };
}
