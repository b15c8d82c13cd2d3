// The FOON editor page (author.html): draft a subgraph from recipe text, write and fix it with live
// errors and a preview drawn by the planner's own task-tree and steps views, and use it in the planner
// (merged into the user's knowledge base in IndexedDB). The work is saved on every keystroke.

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
import type { LoadedKnowledgeBase } from "../worker/protocol";
import { EMPTY_WORK, restoreWork, saveWork, type AuthorWork, type TextStorage } from "./autosave";
import { authoredFile, checkText } from "./check";
import { draftRecipe } from "./draft";
import { mountEditor } from "./editor";
import { BUNDLED_NAME, cleanFileName, withAuthored } from "./merge";
import { motionsOf } from "./tokens";
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
    const memory = new Map<string, string>();
    const storage: TextStorage = { getItem: (k) => memory.get(k) ?? null, setItem: (k, v) => void memory.set(k, v) };
    return { storage, problem: e instanceof Error ? e.message : String(e) };
  }
}

async function fetchBundled(): Promise<KnowledgeBaseFile> {
  const response = await fetch(KB_URL);
  if (!response.ok) throw new Error(`${KB_URL}: HTTP ${response.status}`);
  return { name: BUNDLED_NAME, bytes: new Uint8Array(await response.arrayBuffer()) };
}

/** The planner query that finds the authored recipe: its dish class and the goal's ingredients. */
function plannerLink(preview: Plan): string {
  const query = { dish: preview.dish_class?.name ?? preview.query.type, ingredients: preview.goal.ingredients.map((object) => ({ object, state: "" })), overrides: {} };
  return `./${queryToSearch(query)}`;
}

function start(): void {
  const found = document.getElementById("author");
  const themePicker = document.getElementById("theme");
  if (found === null || !(themePicker instanceof HTMLSelectElement)) return;
  const host: HTMLElement = found;
  const { storage, problem } = textStorage();
  const restored = restoreWork(storage);
  const work: AuthorWork = { ...(restored ?? EMPTY_WORK) };
  const planner = new WorkerPlanner();
  const persistence = openKbPersistence();
  const preview = new Store();

  const save = (): void => {
    const failed = saveWork(storage, work);
    host.dataset.saved = failed === null && problem === null ? "yes" : "no";
    if (failed !== null) saveStatus.textContent = `Your text cannot be saved in this browser (${failed}): download it to keep it.`;
  };

  // ---- the recipe text and the drafter ----
  const recipeInput = el("textarea", { id: "recipe-text", class: "recipe-input", rows: 12, spellcheck: "true" });
  recipeInput.value = work.recipe;
  const draftButton = el("button", { type: "button", class: "draft", text: "Draft FOON from this recipe" });
  const draftSection = el(
    "section",
    { class: "panel panel-draft", "aria-labelledby": "draft-title" },
    el("h2", { id: "draft-title", text: "Draft from recipe text" }),
    el("p", { class: "muted small", text: "Paste a recipe: its title, the ingredient lines, then numbered steps. The draft replaces the editor's text (Undo brings it back); every guess is a “# confirm:” line." }),
    el("label", { for: "recipe-text", text: "Recipe text" }),
    recipeInput,
    draftButton,
  );

  // ---- the editor ----
  const nameInput = el("input", { id: "file-name", type: "text", value: work.name, class: "file-name" });
  const undoButton = el("button", { type: "button", class: "icon", text: "Undo" });
  const redoButton = el("button", { type: "button", class: "icon", text: "Redo" });
  const useButton = el("button", { type: "button", class: "use", text: "Use in planner", disabled: true });
  const txtButton = el("button", { type: "button", class: "icon", text: "Download .txt" });
  const bundleButton = el("button", { type: "button", class: "icon", text: "Download knowledge base (.foon)" });
  const useStatus = el("p", { class: "use-status", role: "status" });
  const saveStatus = el("p", { class: "save-status muted small", role: "status" });
  const editorHost = el("div", { class: "editor-host" });
  const editorSection = el(
    "section",
    { class: "panel panel-editor", "aria-labelledby": "editor-title" },
    el("div", { class: "view-head" }, el("h2", { id: "editor-title", text: "FOON editor" }), el("div", { class: "toolbar wrap", role: "toolbar", "aria-label": "Editor" }, undoButton, redoButton, txtButton, bundleButton)),
    el("div", { class: "field" }, el("label", { for: "file-name", text: "File name in your knowledge base" }), nameInput),
    editorHost,
    el("div", { class: "use-row" }, useButton, useStatus),
    saveStatus,
  );

  const treeHost = el("section", { class: "panel panel-tree", "data-view": "tree" });
  const stepsHost = el("section", { class: "panel panel-steps", "data-view": "steps" });
  const previewStatus = el("p", { class: "plan-status", role: "status" });
  host.classList.add("foon-app");
  host.replaceChildren(
    el("div", { class: "author-layout" }, el("div", { class: "author-inputs" }, draftSection, editorSection), el("div", { class: "results" }, previewStatus, treeHost, stepsHost)),
  );

  let checkedText: string | null = null;
  let lastPreview: Plan | null = null;
  const editor = mountEditor(editorHost, {
    initial: work.text,
    label: "FOON text (plain dialect)",
    onChange(text) {
      work.text = text;
      save();
      scheduleCheck();
    },
  });
  saveStatus.textContent =
    problem !== null ? `This browser does not keep your text (${problem}): download it to keep it.` : restored !== null && restored.text !== "" ? "Your text was restored. Everything you type is saved in this browser." : "Everything you type is saved in this browser.";

  recipeInput.addEventListener("input", () => {
    work.recipe = recipeInput.value;
    save();
  });
  nameInput.addEventListener("input", () => {
    work.name = nameInput.value;
    save();
    scheduleCheck();
  });
  draftButton.addEventListener("click", () => {
    const draft = draftRecipe(recipeInput.value);
    work.name = cleanFileName(draft.fileName);
    nameInput.value = work.name;
    editor.replace(draft.text);
  });
  undoButton.addEventListener("click", () => editor.undo());
  redoButton.addEventListener("click", () => editor.redo());
  txtButton.addEventListener("click", () => download(cleanFileName(work.name), editor.text));

  // ---- the planner: one job at a time (a check loads the text alone, "use" loads the merged knowledge base) ----
  let chain: Promise<void> = Promise.resolve();
  const exclusive = (job: () => Promise<void>): Promise<void> => (chain = chain.then(job, job));
  let checkSeq = 0;

  function setWords(kb: LoadedKnowledgeBase, files: readonly KnowledgeBaseFile[]): void {
    const decoder = new TextDecoder();
    const motions = [...new Set(files.flatMap((f) => motionsOf(decoder.decode(f.bytes))))].sort();
    editor.setWords({ labels: kb.vocabulary.labels, states: kb.vocabulary.states, motions });
  }

  async function userFiles(): Promise<KnowledgeBaseFile[] | null> {
    return (await persistence).restore().catch(() => null);
  }

  function scheduleCheck(): void {
    const seq = ++checkSeq;
    host.dataset.checked = "no";
    void exclusive(async () => {
      if (seq !== checkSeq) return; // a newer edit will be checked instead
      const text = editor.text;
      const name = cleanFileName(work.name);
      const result = text.trim() === "" ? { diagnostics: [], preview: null } : await checkText(planner, name, text);
      if (seq !== checkSeq) return;
      editor.setDiagnostics(result.diagnostics);
      lastPreview = result.preview;
      checkedText = result.diagnostics.some((d) => d.severity === "error") || result.preview === null ? null : text;
      useButton.disabled = checkedText === null;
      preview.set({ plan: result.preview });
      previewStatus.dataset.state = result.preview === null ? "idle" : "ready";
      previewStatus.textContent =
        result.preview === null ? "The preview appears once the text loads and has a goal node." : `Preview: ${result.preview.units.length} functional units from “${result.preview.goal.label}”, as the planner retrieves them.`;
      host.dataset.checked = "yes";
    });
  }

  async function useInPlanner(): Promise<void> {
    const text = checkedText;
    if (text === null) return;
    const file = authoredFile(cleanFileName(work.name), text);
    useStatus.dataset.state = "saving";
    useStatus.textContent = "Adding it to your knowledge base…";
    try {
      const files = await withAuthored(await userFiles(), fetchBundled, file);
      const kb = await planner.loadFiles(files); // the merged knowledge base must load too (cycles, clashes)
      setWords(kb, files);
      await (await persistence).save(files);
      useStatus.dataset.state = "saved";
      useStatus.replaceChildren(
        `Saved in your knowledge base (${files.length} files). `,
        lastPreview === null ? "" : el("a", { href: plannerLink(lastPreview), class: "plan-link", text: "Plan with it" }),
      );
    } catch (e) {
      useStatus.dataset.state = "error";
      useStatus.textContent = `Not added: ${e instanceof Error && "code" in e ? describeError(toPlannerError(e)) : String(e)}`;
    }
    checkSeq++; // the worker now holds the merged knowledge base: check the text alone again
    scheduleCheck();
  }
  useButton.addEventListener("click", () => void exclusive(useInPlanner));
  bundleButton.addEventListener("click", () => {
    void (async () => {
      const files = await withAuthored(await userFiles(), fetchBundled, authoredFile(cleanFileName(work.name), editor.text));
      download("my-knowledge-base.foon", bundleText(files));
    })();
  });

  // the words to complete: the user's knowledge base (else the bundled one)
  void exclusive(async () => {
    try {
      const files = (await userFiles()) ?? [await fetchBundled()];
      setWords(await planner.loadFiles(files), files);
    } catch (e) {
      saveStatus.textContent = `The knowledge base's words could not be loaded for completion: ${String(e)}`;
    }
  });
  scheduleCheck();

  // the planner's own views draw the preview
  let tree: TreeViewHandle | null = null;
  mountStepsView(stepsHost, preview, { select: (selection) => preview.set({ selection }) });
  void import("../app/views/tree-view").then(({ mountTreeView }) => {
    tree = mountTreeView(treeHost, preview, { select: (selection) => preview.set({ selection }) });
  });
  bindThemePicker(themePicker, document.documentElement, () => tree?.restyle());
}

start();
