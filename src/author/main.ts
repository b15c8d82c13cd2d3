// The FOON editor page (author.html): draft a subgraph from recipe text, write and fix it with live errors
// and a preview drawn by the planner's own task-tree and steps views, and use it in the planner (merged into
// the user's knowledge base in IndexedDB). The work is saved on every keystroke.

import { download, el } from "../app/dom";
import { openKbPersistence } from "../app/kb-store";
import { queryToSearch } from "../app/query";
import { Store } from "../app/store";
import { bindThemePicker } from "../app/theme";
import { mountStepsView } from "../app/views/steps-view";
import type { TreeViewHandle } from "../app/views/tree-view";
import { bundleText } from "../planner/bundle";
import { describeError, toPlannerError } from "../planner/errors";
import type { KnowledgeBaseFile, Plan } from "../planner/types";
import { WorkerPlanner } from "../worker/client";
import { EMPTY_WORK, memoryStorage, restoreWorks, saveWork, type AuthorWork, type SavedWork, type TextStorage } from "./autosave";
import type { CheckResult } from "./check";
import { draftRecipe } from "./draft";
import type { CompletionWords } from "./complete";
import { mountEditor } from "./editor";
import { BUNDLED_NAME, cleanFileName } from "./merge";
import { createAuthorSession, type AuthorSession } from "./session";
import "../app/style.css";
import "../app/page.css";
import "./author.css";

const KB_URL = new URL("kb/default.foon", document.baseURI).href;

/** localStorage, or a page-lifetime stand-in where the browser refuses it (the page says so). */
function textStorage(): { storage: TextStorage; problem: string | null } {
  try {
    const storage = window.localStorage;
    storage.getItem("probe");
    return { storage, problem: null };
  } catch (e) {
    return { storage: memoryStorage(), problem: e instanceof Error ? e.message : String(e) };
  }
}

/** This tab's name for its autosave record: kept across reloads of the tab, new in a new tab. */
function tabId(): string {
  const key = "foon-planner-author-tab";
  try {
    const known = sessionStorage.getItem(key);
    if (known !== null) return known;
    const id = crypto.randomUUID();
    sessionStorage.setItem(key, id);
    return id;
  } catch {
    return crypto.randomUUID();
  }
}

/** Texts other tabs saved, offered to open (the editor's undo brings the current text back). */
function otherWorks(works: readonly SavedWork[], open: (work: SavedWork) => void): HTMLElement {
  const list = el("ul", { class: "other-works" });
  for (const w of works) {
    const title = /^# title:\s*(.+)$/m.exec(w.text)?.[1] ?? w.name;
    const button = el("button", { type: "button", class: "icon", text: "Open" });
    button.addEventListener("click", () => open(w));
    list.append(el("li", {}, `${title} (${w.name}, saved ${new Date(w.savedAt).toLocaleString()}) `, button));
  }
  return el("details", { class: "other-works-box", hidden: works.length === 0 }, el("summary", { text: `Other texts saved in this browser (${works.length})` }), list);
}

async function fetchBundled(): Promise<KnowledgeBaseFile> {
  const response = await fetch(KB_URL);
  if (!response.ok) throw new Error(`${KB_URL}: HTTP ${response.status}`);
  return { name: BUNDLED_NAME, bytes: new Uint8Array(await response.arrayBuffer()) };
}

/** The planner query that finds the authored recipe: its dish class and the goal's ingredients. */
function plannerLink(preview: Plan): string {
  const ingredients = preview.goal.ingredients.map((object) => ({ object, state: "" }));
  return `./${queryToSearch({ dish: preview.dish_class?.name ?? preview.query.type, ingredients, overrides: {} })}`;
}

function draftPanel(work: AuthorWork, onDraft: (recipe: string) => void, save: () => void): HTMLElement {
  const recipe = el("textarea", { id: "recipe-text", class: "recipe-input", rows: 12, spellcheck: "true" });
  recipe.value = work.recipe;
  recipe.addEventListener("input", () => {
    work.recipe = recipe.value;
    save();
  });
  const button = el("button", { type: "button", class: "draft", text: "Draft FOON from this recipe" });
  button.addEventListener("click", () => onDraft(recipe.value));
  return el(
    "section",
    { class: "panel panel-draft", "aria-labelledby": "draft-title" },
    el("h2", { id: "draft-title", text: "Draft from recipe text" }),
    el("p", { class: "muted small", text: "Paste a recipe: its title, the ingredient lines, then numbered steps. The draft replaces the editor's text (Undo brings it back); every guess is a “# confirm:” line." }),
    el("label", { for: "recipe-text", text: "Recipe text" }),
    recipe,
    button,
  );
}

/** The preview: the planner's task-tree and steps views on a store of their own. */
function mountPreview(results: HTMLElement, themePicker: HTMLSelectElement): { show(result: CheckResult): void } {
  const store = new Store();
  const status = el("p", { class: "plan-status", role: "status", text: "The preview appears once the text loads and has a goal node." });
  const treeHost = el("section", { class: "panel panel-tree", "data-view": "tree" });
  const stepsHost = el("section", { class: "panel panel-steps", "data-view": "steps" });
  results.replaceChildren(status, treeHost, stepsHost);
  const select = { select: (selection: Store["state"]["selection"]) => store.set({ selection }) };
  mountStepsView(stepsHost, store, select);
  let tree: TreeViewHandle | null = null;
  void import("../app/views/tree-view").then(({ mountTreeView }) => {
    tree = mountTreeView(treeHost, store, select);
  });
  bindThemePicker(themePicker, document.documentElement, () => tree?.restyle());
  return {
    show({ preview }) {
      store.set({ plan: preview });
      status.dataset.state = preview === null ? "idle" : "ready";
      status.textContent =
        preview === null ? "The preview appears once the text loads and has a goal node." : `Preview: ${preview.units.length} functional units from “${preview.goal.label}”, as the planner retrieves them.`;
    },
  };
}

/** "Use in planner": adds the checked text to the user's knowledge base and links to a plan with it. */
function bindUse(button: HTMLButtonElement, status: HTMLElement, session: AuthorSession, onWords: (words: CompletionWords) => void, current: () => { name: string; text: string | null; preview: Plan | null }): void {
  button.addEventListener("click", () => {
    const { name, text, preview } = current();
    if (text === null) return;
    status.dataset.state = "saving";
    status.textContent = "Adding it to your knowledge base…";
    session.useInPlanner(name, text).then(
      ({ files, words }) => {
        onWords(words);
        status.dataset.state = "saved";
        status.replaceChildren(`Saved in your knowledge base (${files.length} files). `, preview === null ? "" : el("a", { href: plannerLink(preview), class: "plan-link", text: "Plan with it" }));
      },
      (e: unknown) => {
        status.dataset.state = "error";
        status.textContent = `Not added: ${e instanceof Error && "code" in e ? describeError(toPlannerError(e)) : String(e)}`;
      },
    );
  });
}

interface EditorControls {
  nameInput: HTMLInputElement;
  undoButton: HTMLButtonElement;
  redoButton: HTMLButtonElement;
  txtButton: HTMLButtonElement;
  bundleButton: HTMLButtonElement;
  useButton: HTMLButtonElement;
  useStatus: HTMLElement;
}

function editorControls(name: string): EditorControls {
  return {
    nameInput: el("input", { id: "file-name", type: "text", value: name, class: "file-name" }),
    undoButton: el("button", { type: "button", class: "icon", text: "Undo" }),
    redoButton: el("button", { type: "button", class: "icon", text: "Redo" }),
    txtButton: el("button", { type: "button", class: "icon", text: "Download .txt" }),
    bundleButton: el("button", { type: "button", class: "icon", text: "Download knowledge base (.foon)" }),
    useButton: el("button", { type: "button", class: "use", text: "Use in planner", disabled: true }),
    useStatus: el("p", { class: "use-status", role: "status" }),
  };
}

function editorSection(ui: EditorControls, editorHost: HTMLElement, saveStatus: HTMLElement, others: HTMLElement): HTMLElement {
  return el(
    "section",
    { class: "panel panel-editor", "aria-labelledby": "editor-title" },
    el(
      "div",
      { class: "view-head" },
      el("h2", { id: "editor-title", text: "FOON editor" }),
      el("div", { class: "toolbar wrap", role: "toolbar", "aria-label": "Editor" }, ui.undoButton, ui.redoButton, ui.txtButton, ui.bundleButton),
    ),
    el("div", { class: "field" }, el("label", { for: "file-name", text: "File name in your knowledge base" }), ui.nameInput),
    editorHost,
    el("div", { class: "use-row" }, ui.useButton, ui.useStatus),
    saveStatus,
    others,
  );
}

function saveStatusText(problem: string | null, restored: SavedWork | undefined): string {
  if (problem !== null) return `This browser does not keep your text (${problem}): download it to keep it.`;
  return restored !== undefined && restored.text !== "" ? "Your text was restored. Everything you type is saved in this browser." : "Everything you type is saved in this browser.";
}

function start(): void {
  const host = document.getElementById("author");
  const themePicker = document.getElementById("theme");
  if (host === null || !(themePicker instanceof HTMLSelectElement)) return;
  const root: HTMLElement = host;
  const { storage, problem } = textStorage();
  const tab = tabId();
  const [restored, ...older] = restoreWorks(storage);
  const work: AuthorWork = restored === undefined ? { ...EMPTY_WORK } : { text: restored.text, name: restored.name, recipe: restored.recipe };
  const session = createAuthorSession({ planner: new WorkerPlanner(), persistence: openKbPersistence(), bundled: fetchBundled });

  const saveStatus = el("p", { class: "save-status muted small", role: "status" });
  const save = (): void => {
    const failed = saveWork(storage, tab, work);
    if (failed !== null) saveStatus.textContent = `Your text cannot be saved in this browser (${failed}): download it to keep it.`;
  };
  saveStatus.textContent = saveStatusText(problem, restored);

  const ui = editorControls(work.name);
  const { nameInput, useButton } = ui;
  const editorHost = el("div", { class: "editor-host" });
  const results = el("div", { class: "results" });

  let checked: { text: string | null; preview: Plan | null } = { text: null, preview: null };
  const editor = mountEditor(editorHost, {
    initial: work.text,
    label: "FOON text (plain dialect)",
    onChange(text) {
      work.text = text;
      save();
      scheduleCheck();
    },
  });
  const preview = mountPreview(results, themePicker);

  function scheduleCheck(): void {
    const text = editor.text;
    root.dataset.checked = "no";
    useButton.disabled = true; // until this text is checked
    const result = text.trim() === "" ? Promise.resolve({ diagnostics: [], preview: null }) : session.check(cleanFileName(work.name), text);
    void result.then((r) => {
      if (r === null || text !== editor.text) return; // a newer edit is being checked
      editor.setDiagnostics(r.diagnostics);
      preview.show(r);
      checked = { text: r.diagnostics.some((d) => d.severity === "error") || r.preview === null ? null : text, preview: r.preview };
      useButton.disabled = checked.text === null;
      root.dataset.checked = "yes";
    });
  }

  /** The knowledge base's labels: the drafter marks ingredients outside them. */
  let labels: readonly string[] | undefined;
  const setWords = (words: CompletionWords): void => {
    labels = words.labels;
    editor.setWords(words);
    root.dataset.words = "ready";
  };
  const onDraft = (recipe: string): void => {
    const draft = draftRecipe(recipe, { labels });
    work.name = cleanFileName(draft.fileName);
    nameInput.value = work.name;
    editor.replace(draft.text);
  };
  nameInput.addEventListener("input", () => {
    work.name = nameInput.value;
    save();
    scheduleCheck();
  });
  ui.undoButton.addEventListener("click", () => editor.undo());
  ui.redoButton.addEventListener("click", () => editor.redo());
  ui.txtButton.addEventListener("click", () => download(cleanFileName(work.name), editor.text));
  ui.bundleButton.addEventListener("click", () => {
    void session.knowledgeBaseWith(cleanFileName(work.name), editor.text).then((files) => download("my-knowledge-base.foon", bundleText(files)));
  });
  bindUse(useButton, ui.useStatus, session, setWords, () => ({ name: cleanFileName(work.name), ...checked }));

  const others = otherWorks(
    older.filter((w) => w.text.trim() !== "" && w.text !== work.text),
    (w) => {
      work.name = w.name;
      nameInput.value = w.name;
      editor.replace(w.text);
    },
  );
  root.classList.add("foon-app");
  root.replaceChildren(el("div", { class: "author-layout" }, el("div", { class: "author-inputs" }, draftPanel(work, onDraft, save), editorSection(ui, editorHost, saveStatus, others)), results));

  session.words().then(
    setWords,
    (e: unknown) => (saveStatus.textContent = `The knowledge base's words could not be loaded for completion: ${String(e)}`),
  );
  scheduleCheck();
}

start();
