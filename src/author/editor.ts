// The FOON text editor: a plain textarea over a coloured copy of its text (the overlay), a line-number
// gutter, errors and warnings with line, column and reason, completion of the knowledge base's words,
// and undo/redo of every change, the page's own included. The page owns the text's meaning: the
// editor reports each change and shows the diagnostics it is given.

import { el, uid } from "../app/dom";
import type { Diagnostic } from "./check";
import { applyCompletion, completeAt, type CompletionWords } from "./complete";
import { mountCompletionList } from "./completion-list";
import { EditHistory, type EditKind, type Snapshot } from "./history";
import { lineKind, tokenizeLine } from "./tokens";

export interface EditorHandle {
  readonly text: string;
  /** Replaces the whole text as one undoable step (a draft, a restore). */
  replace(text: string): void;
  undo(): void;
  redo(): void;
  setDiagnostics(diagnostics: readonly Diagnostic[]): void;
  setWords(words: CompletionWords): void;
}

export interface EditorOptions {
  initial: string;
  label: string;
  onChange(text: string): void;
}

const NO_WORDS: CompletionWords = { labels: [], states: [], motions: [] };

/** Typing and deleting merge into one undo step per word; anything else (paste, drop, cut) is its own. */
const KIND_OF_INPUT: Record<string, EditKind> = { insertText: "type", deleteContentBackward: "delete", deleteContentForward: "delete" };

const count = (ds: readonly Diagnostic[], s: Diagnostic["severity"]): number => ds.filter((d) => d.severity === s).length;

/** The list under the editor: each diagnostic a button that moves the caret to its place. */
function renderDiagnostics(host: HTMLElement, summary: HTMLElement, list: HTMLElement, next: readonly Diagnostic[], goTo: (d: Diagnostic) => void): void {
  host.dataset.errors = String(count(next, "error"));
  host.dataset.warnings = String(count(next, "warning"));
  host.dataset.confirm = String(count(next, "confirm"));
  summary.textContent =
    next.length === 0 ? "No errors or warnings." : `${count(next, "error")} error(s), ${count(next, "warning")} warning(s), ${count(next, "confirm")} guess(es) to confirm.`;
  list.replaceChildren(
    ...next.map((d) => {
      const button = el("button", { type: "button", class: "diagnostic", text: `${where(d)}${d.reason}` });
      button.addEventListener("click", () => goTo(d));
      return el("li", { "data-severity": d.severity }, el("span", { class: "severity", text: d.severity === "confirm" ? "to confirm" : d.severity }), button);
    }),
  );
}

function where(d: Diagnostic): string {
  if (d.line === null) return "";
  return d.column === null ? `line ${d.line}: ` : `line ${d.line}, column ${d.column}: `;
}

/** The overlay's content: one span per line, coloured by token, the error's column marked. */
function overlayLines(text: string, error: Diagnostic | undefined, marked: ReadonlySet<number>): HTMLElement[] {
  return text.split("\n").map((line, i) => {
    const row = el("span", { class: `ln ln-${lineKind(line)}${marked.has(i + 1) ? " ln-flagged" : ""}` });
    let offset = 0;
    const errorAt = error?.line === i + 1 ? (error.column ?? 1) - 1 : -1;
    for (const token of tokenizeLine(line)) {
      const end = offset + token.text.length;
      if (errorAt >= offset && errorAt < end) {
        const cut = errorAt - offset;
        row.append(el("span", { class: `t-${token.role}`, text: token.text.slice(0, cut) }));
        row.append(el("span", { class: `t-${token.role} err-at`, text: token.text.slice(cut) }));
      } else row.append(el("span", { class: `t-${token.role}`, text: token.text }));
      offset = end;
    }
    if (errorAt >= offset) row.append(el("span", { class: "err-at", text: " " }));
    row.append("\n");
    return row;
  });
}

export function mountEditor(host: HTMLElement, options: EditorOptions): EditorHandle {
  const inputId = uid("foon-text");
  const listId = uid("foon-complete");
  const input = el("textarea", {
    id: inputId,
    class: "code-input",
    spellcheck: "false",
    autocapitalize: "off",
    autocomplete: "off",
    wrap: "off",
    "aria-autocomplete": "list",
    "aria-controls": listId,
    "aria-describedby": `${inputId}-help`,
  });
  input.value = options.initial;
  const overlay = el("pre", { class: "code-overlay", "aria-hidden": "true" });
  const gutter = el("pre", { class: "code-gutter", "aria-hidden": "true" });
  const suggestions = el("ul", { id: listId, class: "completions", role: "listbox", "aria-label": "Suggestions", hidden: true });
  const problems = el("ul", { class: "diagnostics", "aria-label": "Errors and warnings" });
  const summary = el("p", { class: "diagnostics-summary", role: "status" });
  host.replaceChildren(
    el("label", { for: inputId, text: options.label }),
    el("p", { id: `${inputId}-help`, class: "muted small", text: "Tab types a tab (FOON separates fields with tabs); Escape, then Tab leaves the editor. Ctrl+Z undoes, Ctrl+Shift+Z or Ctrl+Y redoes; Ctrl+Space suggests." }),
    el("div", { class: "code-editor" }, gutter, el("div", { class: "code-stack" }, overlay, input)),
    suggestions,
    summary,
    problems,
  );

  const history = new EditHistory({ text: input.value, start: 0, end: 0 });
  let diagnostics: readonly Diagnostic[] = [];
  let words = NO_WORDS;
  let escaped = false;
  const completion = mountCompletionList(suggestions, input, (c, option) => {
    const next = applyCompletion(input.value, c, option);
    edit(next.text, next.caret, "replace");
  });

  function render(): void {
    const error = diagnostics.find((d) => d.severity === "error");
    const flagged = new Set(diagnostics.filter((d) => d.line !== null).map((d) => d.line!));
    overlay.replaceChildren(...overlayLines(input.value, error, flagged));
    const count = input.value.split("\n").length;
    gutter.textContent = Array.from({ length: count }, (_, i) => String(i + 1)).join("\n") + "\n";
    syncScroll();
  }

  function syncScroll(): void {
    overlay.scrollTop = input.scrollTop;
    overlay.scrollLeft = input.scrollLeft;
    gutter.scrollTop = input.scrollTop;
  }

  function changed(): void {
    render();
    options.onChange(input.value);
  }

  function show(snapshot: Snapshot): void {
    input.value = snapshot.text;
    input.setSelectionRange(snapshot.start, snapshot.end);
    completion.close();
    changed();
  }

  function edit(text: string, caret: number, kind: EditKind): void {
    input.value = text;
    input.setSelectionRange(caret, caret);
    history.record({ text, start: caret, end: caret }, kind);
    changed();
  }

  function openCompletion(): void {
    completion.show(input.selectionStart === input.selectionEnd ? completeAt(input.value, input.selectionStart, words) : null);
  }

  input.addEventListener("beforeinput", (event) => {
    // the browser's own undo knows nothing of the page's edits: use the editor's
    if (event.inputType === "historyUndo" || event.inputType === "historyRedo") {
      event.preventDefault();
      if (event.inputType === "historyUndo") undo();
      else redo();
    }
  });
  input.addEventListener("input", (event) => {
    const kind = KIND_OF_INPUT[(event as InputEvent).inputType ?? ""] ?? "replace";
    history.record({ text: input.value, start: input.selectionStart, end: input.selectionEnd }, kind);
    changed();
    if (kind === "type") openCompletion();
    else completion.close();
  });
  input.addEventListener("scroll", syncScroll);
  input.addEventListener("blur", () => completion.close());
  input.addEventListener("keydown", (event) => {
    const mod = event.ctrlKey || event.metaKey;
    const key = event.key.toLowerCase();
    const wasEscaped = escaped;
    escaped = event.key === "Escape";
    if (completion.key(event)) return;
    if (mod && (key === "z" || key === "y")) {
      event.preventDefault();
      if (key === "z" && !event.shiftKey) undo();
      else redo();
    } else if (mod && event.key === " ") {
      event.preventDefault();
      openCompletion();
    } else if (event.key === "Tab" && !event.shiftKey && !wasEscaped) {
      event.preventDefault();
      const { selectionStart: start, selectionEnd: end, value } = input;
      edit(value.slice(0, start) + "\t" + value.slice(end), start + 1, "type");
    }
  });

  function undo(): void {
    const snapshot = history.undo();
    if (snapshot !== null) show(snapshot);
  }

  function redo(): void {
    const snapshot = history.redo();
    if (snapshot !== null) show(snapshot);
  }

  /** Moves the caret to a diagnostic's place and scrolls it into view. */
  function goTo(d: Diagnostic): void {
    if (d.line === null) return;
    const lines = input.value.split("\n");
    const offset = lines.slice(0, d.line - 1).reduce((sum, l) => sum + l.length + 1, 0) + Math.max(0, (d.column ?? 1) - 1);
    input.focus();
    input.setSelectionRange(offset, offset);
    const lineHeight = input.scrollHeight / Math.max(1, lines.length);
    input.scrollTop = Math.max(0, (d.line - 3) * lineHeight);
    syncScroll();
  }

  render();
  return {
    get text() {
      return input.value;
    },
    replace(text) {
      edit(text, 0, "replace");
    },
    undo,
    redo,
    setDiagnostics(next) {
      diagnostics = next;
      renderDiagnostics(host, summary, problems, next, goTo);
      render();
    },
    setWords(next) {
      words = next;
    },
  };
}
