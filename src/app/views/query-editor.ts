// Asking: the dish type picker, the ingredient rows (object + state, autocomplete from the knowledge
// base, free text allowed), add/remove/reorder, pasting a list, and example queries.

import { RETRIEVAL_MODES, type QueryIngredient, type RetrievalMode } from "../../planner/types";
import { el, uid } from "../dom";
import { EXAMPLES, ingredientPhrase, parseIngredientList, parseMode, type AppQuery } from "../query";
import type { AppState, Store } from "../store";

export interface QueryEditorActions {
  setQuery(query: AppQuery): void;
}

const MODE_NAMES: Record<RetrievalMode, string> = {
  heuristic: "Paper's heuristic (ingredient overlap)",
  fewest_units: "Fewest functional units",
  lowest_cost: "Lowest motion cost for a robot",
  most_reliable: "Most reliable for a robot",
};

function sameQuery(a: AppQuery, b: AppQuery): boolean {
  return JSON.stringify(a) === JSON.stringify(b);
}

export function mountQueryEditor(host: HTMLElement, store: Store, actions: QueryEditorActions): () => void {
  const ids = { labels: uid("labels"), states: uid("states"), dish: uid("dish"), paste: uid("paste"), recipes: uid("recipes"), mode: uid("mode") };
  const labelList = el("datalist", { id: ids.labels });
  const stateList = el("datalist", { id: ids.states });
  const dishSelect = el("select", { id: ids.dish, name: "dish" });
  const modeSelect = el("select", { id: ids.mode, name: "mode" }, ...RETRIEVAL_MODES.map((m) => el("option", { value: m, text: MODE_NAMES[m] })));
  const recipes = el("p", { class: "recipes muted", id: ids.recipes, "aria-live": "polite" });
  const rows = el("ol", { class: "ingredient-rows", "aria-label": "Ingredients" });
  const addButton = el("button", { type: "button", class: "add-row", text: "Add ingredient" });
  const pasteArea = el("textarea", { id: ids.paste, rows: 2, placeholder: "chopped chili pepper, whole tomato, cool whip" });
  const pasteButton = el("button", { type: "button", text: "Add these" });
  const examples = el("div", { class: "examples", role: "group", "aria-label": "Example queries" });

  // What the editor last sent: a store query equal to it needs no re-render (keeps focus while typing).
  let shown: AppQuery = store.state.query;

  const emit = (query: AppQuery): void => {
    shown = query;
    actions.setQuery(query);
  };
  const current = (): AppQuery => ({ ...store.state.query, ingredients: readRows() });

  function readRows(): QueryIngredient[] {
    return [...rows.querySelectorAll<HTMLLIElement>("li")].map((li) => ({
      object: li.querySelector<HTMLInputElement>("input.object")?.value ?? "",
      state: li.querySelector<HTMLInputElement>("input.state")?.value ?? "",
    }));
  }

  function rowElement(ingredient: QueryIngredient, index: number, count: number): HTMLLIElement {
    const n = index + 1;
    const object = el("input", {
      class: "object", type: "text", value: ingredient.object, list: ids.labels, autocomplete: "off",
      "aria-label": `Ingredient ${n}: object`, placeholder: "object, e.g. tomato",
    });
    const state = el("input", {
      class: "state", type: "text", value: ingredient.state, list: ids.states, autocomplete: "off",
      "aria-label": `Ingredient ${n}: state`, placeholder: "state, e.g. diced",
    });
    const up = el("button", { type: "button", class: "icon", "aria-label": `Move ingredient ${n} up`, title: "Move up", disabled: index === 0, text: "↑" });
    const down = el("button", { type: "button", class: "icon", "aria-label": `Move ingredient ${n} down`, title: "Move down", disabled: index === count - 1, text: "↓" });
    const remove = el("button", { type: "button", class: "icon", "aria-label": `Remove ingredient ${n}`, title: "Remove", text: "✕" });
    const onInput = (): void => emit(current());
    object.addEventListener("input", onInput);
    state.addEventListener("input", onInput);
    // pasting a whole list into one field adds a row per item
    object.addEventListener("paste", (event: ClipboardEvent) => {
      const text = event.clipboardData?.getData("text") ?? "";
      if (!/[,;\n]/.test(text)) return;
      event.preventDefault();
      const list = readRows();
      list.splice(index, 1, ...parseIngredientList(text, store.state.kb?.vocabulary.states ?? []));
      emitAndRender({ ...store.state.query, ingredients: list });
    });
    const move = (delta: number): void => {
      const list = readRows();
      const [item] = list.splice(index, 1);
      if (item === undefined) return;
      list.splice(index + delta, 0, item);
      emitAndRender({ ...store.state.query, ingredients: list }, { row: index + delta, button: delta < 0 ? "up" : "down" });
    };
    up.addEventListener("click", () => move(-1));
    down.addEventListener("click", () => move(1));
    remove.addEventListener("click", () => {
      const list = readRows();
      list.splice(index, 1);
      emitAndRender({ ...store.state.query, ingredients: list }, { row: Math.min(index, list.length - 1), button: "object" });
    });
    return el("li", { class: "ingredient-row" }, object, state, el("span", { class: "row-buttons" }, up, down, remove));
  }

  type Focus = { row: number; button: "up" | "down" | "object" };

  function renderRows(query: AppQuery, focus?: Focus): void {
    rows.replaceChildren(...query.ingredients.map((i, k) => rowElement(i, k, query.ingredients.length)));
    if (focus !== undefined && focus.row >= 0) {
      const li = rows.children[focus.row];
      const target =
        focus.button === "object"
          ? li?.querySelector<HTMLElement>("input.object")
          : li?.querySelector<HTMLElement>(`button[aria-label^="Move ingredient ${focus.row + 1} ${focus.button}"]`);
      // a disabled button cannot take focus: fall back to the row's object field
      (target !== null && target !== undefined && !(target as HTMLButtonElement).disabled ? target : li?.querySelector<HTMLElement>("input.object"))?.focus();
    }
  }

  function emitAndRender(query: AppQuery, focus?: Focus): void {
    renderRows(query, focus);
    emit(query);
  }

  function renderDishes(state: AppState): void {
    const dishes = state.kb?.vocabulary.dishes ?? [];
    const options = [el("option", { value: "", text: "Any dish type" })];
    for (const d of dishes) options.push(el("option", { value: d.name, text: `${d.name} (${d.recipes.length})` }));
    const dish = state.query.dish;
    if (dish !== "" && !dishes.some((d) => d.name === dish)) options.push(el("option", { value: dish, text: `${dish} (no recipes)` }));
    dishSelect.replaceChildren(...options);
    dishSelect.value = dish;
    const chosen = dishes.find((d) => d.name === dish);
    recipes.textContent =
      chosen === undefined
        ? `Reference goal nodes are searched among all ${dishes.reduce((n, d) => n + d.recipes.length, 0)} recipes.`
        : `Recipes for ${chosen.name}: ${chosen.recipes.join(", ")}.`;
  }

  function renderVocabulary(state: AppState): void {
    const vocab = state.kb?.vocabulary;
    labelList.replaceChildren(...(vocab?.labels ?? []).map((l) => el("option", { value: l })));
    stateList.replaceChildren(...(vocab?.states ?? []).map((s) => el("option", { value: s })));
  }

  dishSelect.addEventListener("change", () => emit({ ...current(), dish: dishSelect.value }));
  modeSelect.addEventListener("change", () => {
    const { mode: _previous, ...rest } = current();
    const mode = parseMode(modeSelect.value);
    emit(mode === undefined || mode === "heuristic" ? rest : { ...rest, mode });
  });
  addButton.addEventListener("click", () => {
    const list = [...readRows(), { object: "", state: "" }];
    emitAndRender({ ...store.state.query, ingredients: list }, { row: list.length - 1, button: "object" });
  });
  pasteButton.addEventListener("click", () => {
    const added = parseIngredientList(pasteArea.value, store.state.kb?.vocabulary.states ?? []);
    if (added.length === 0) return;
    pasteArea.value = "";
    const list = [...readRows().filter((i) => i.object.trim() !== ""), ...added];
    emitAndRender({ ...store.state.query, ingredients: list });
  });
  for (const example of EXAMPLES) {
    const button = el("button", { type: "button", class: "example", text: example.title });
    button.title = example.query.ingredients.map(ingredientPhrase).join(", ");
    button.addEventListener("click", () => emitAndRender(example.query));
    examples.append(button);
  }

  host.replaceChildren(
    el("h2", { text: "Ask" }),
    el("div", { class: "field" }, el("label", { for: ids.dish, text: "Dish type" }), dishSelect),
    recipes,
    el("h3", { text: "Ingredients you have" }),
    el("p", { class: "muted small", text: "Each row is an object and the state it should be in. Unseen ingredients are fine: the planner substitutes them." }),
    rows,
    addButton,
    el("div", { class: "field paste" }, el("label", { for: ids.paste, text: "Paste a list (comma- or line-separated)" }), pasteArea, pasteButton),
    el("div", { class: "field" }, el("label", { for: ids.mode, text: "Retrieval" }), modeSelect),
    el("h3", { text: "Examples" }),
    examples,
    labelList,
    stateList,
  );

  renderVocabulary(store.state);
  renderDishes(store.state);
  renderRows(store.state.query);
  modeSelect.value = store.state.query.mode ?? "heuristic";

  return store.subscribe((state, previous) => {
    modeSelect.value = state.query.mode ?? "heuristic";
    if (state.kb !== previous.kb) {
      renderVocabulary(state);
      renderDishes(state);
    } else if (state.query.dish !== previous.query.dish) {
      renderDishes(state);
    }
    if (state.query !== previous.query && !sameQuery(state.query, shown)) {
      shown = state.query;
      renderRows(state.query);
    }
  });
}
