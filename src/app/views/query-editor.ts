// Asking: the dish type picker, the ingredient rows (`ingredient-rows.ts`), pasting a list, the retrieval
// mode and example queries. The editor sends each edit as a whole query; the store's query is drawn back
// only when it differs from what the editor sent (so typing keeps focus).

import { RETRIEVAL_MODES, type QueryIngredient, type RetrievalMode } from "../../planner/types";
import { el, uid } from "../dom";
import { EXAMPLES, ingredientPhrase, parseIngredientList, parseMode, type AppQuery } from "../query";
import type { AppState, Store } from "../store";
import { ingredientRows, type RowFocus } from "./ingredient-rows";

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

/** The dish types of the knowledge base (and the asked one, if it has no recipes), and the recipes searched. */
function renderDishes(select: HTMLSelectElement, recipes: HTMLElement, state: AppState): void {
  const dishes = state.kb?.vocabulary.dishes ?? [];
  const dish = state.query.dish;
  const options = [el("option", { value: "", text: "Any dish type" })];
  for (const d of dishes) options.push(el("option", { value: d.name, text: `${d.name} (${d.recipes.length})` }));
  if (dish !== "" && !dishes.some((d) => d.name === dish)) options.push(el("option", { value: dish, text: `${dish} (no recipes)` }));
  select.replaceChildren(...options);
  select.value = dish;
  const chosen = dishes.find((d) => d.name === dish);
  recipes.textContent =
    chosen === undefined
      ? `Reference goal nodes are searched among all ${dishes.reduce((n, d) => n + d.recipes.length, 0)} recipes.`
      : `Recipes for ${chosen.name}: ${chosen.recipes.join(", ")}.`;
}

function renderVocabulary(labels: HTMLDataListElement, states: HTMLDataListElement, state: AppState): void {
  const vocab = state.kb?.vocabulary;
  labels.replaceChildren(...(vocab?.labels ?? []).map((l) => el("option", { value: l })));
  states.replaceChildren(...(vocab?.states ?? []).map((s) => el("option", { value: s })));
}

/** One button per example query; `pick` receives the example's query. */
function exampleButtons(pick: (query: AppQuery) => void): HTMLElement {
  const examples = el("div", { class: "examples", role: "group", "aria-label": "Example queries" });
  for (const example of EXAMPLES) {
    const button = el("button", { type: "button", class: "example", text: example.title });
    button.title = example.query.ingredients.map(ingredientPhrase).join(", ");
    button.addEventListener("click", () => pick(example.query));
    examples.append(button);
  }
  return examples;
}

/** The "Paste a list" field: `add` receives the pasted ingredients (never none), and the field is cleared. */
function pasteField(id: string, knownStates: () => readonly string[], add: (ingredients: QueryIngredient[]) => void): HTMLElement {
  const area = el("textarea", { id, rows: 2, placeholder: "chopped chili pepper, whole tomato, cool whip" });
  const button = el("button", { type: "button", text: "Add these" });
  button.addEventListener("click", () => {
    const added = parseIngredientList(area.value, knownStates());
    if (added.length === 0) return;
    area.value = "";
    add(added);
  });
  return el("div", { class: "field paste" }, el("label", { for: id, text: "Paste a list (comma- or line-separated)" }), area, button);
}

export function mountQueryEditor(host: HTMLElement, store: Store, actions: QueryEditorActions): () => void {
  const ids = { labels: uid("labels"), states: uid("states"), dish: uid("dish"), paste: uid("paste"), recipes: uid("recipes"), mode: uid("mode") };
  const labelList = el("datalist", { id: ids.labels });
  const stateList = el("datalist", { id: ids.states });
  const dishSelect = el("select", { id: ids.dish, name: "dish" });
  const modeSelect = el("select", { id: ids.mode, name: "mode" }, ...RETRIEVAL_MODES.map((m) => el("option", { value: m, text: MODE_NAMES[m] })));
  const recipes = el("p", { class: "recipes muted", id: ids.recipes, "aria-live": "polite" });
  const addButton = el("button", { type: "button", class: "add-row", text: "Add ingredient" });
  const knownStates = (): readonly string[] => store.state.kb?.vocabulary.states ?? [];

  // What the editor last sent: a store query equal to it needs no re-render (keeps focus while typing).
  let shown: AppQuery = store.state.query;
  const emit = (query: AppQuery): void => {
    shown = query;
    actions.setQuery(query);
  };
  const emitAndRender = (query: AppQuery, focus?: RowFocus): void => {
    rows.render(query.ingredients, focus);
    emit(query);
  };
  const withIngredients = (ingredients: QueryIngredient[]): AppQuery => ({ ...store.state.query, ingredients });
  const current = (): AppQuery => withIngredients(rows.read());
  const rows = ingredientRows({
    labelsId: ids.labels,
    statesId: ids.states,
    typed: () => emit(current()),
    changed: (ingredients, focus) => emitAndRender(withIngredients(ingredients), focus),
    states: knownStates,
  });

  dishSelect.addEventListener("change", () => emit({ ...current(), dish: dishSelect.value }));
  modeSelect.addEventListener("change", () => {
    const { mode: _previous, ...rest } = current();
    const mode = parseMode(modeSelect.value);
    emit(mode === undefined || mode === "heuristic" ? rest : { ...rest, mode });
  });
  addButton.addEventListener("click", () => {
    const list = [...rows.read(), { object: "", state: "" }];
    emitAndRender(withIngredients(list), { row: list.length - 1, control: "object" });
  });

  host.replaceChildren(
    el("h2", { text: "Ask" }),
    el("div", { class: "field" }, el("label", { for: ids.dish, text: "Dish type" }), dishSelect),
    recipes,
    el("h3", { text: "Ingredients you have" }),
    el("p", { class: "muted small", text: "Each row is an object and the state it should be in. Unseen ingredients are fine: the planner substitutes them." }),
    rows.element,
    addButton,
    pasteField(ids.paste, knownStates, (added) => emitAndRender(withIngredients([...rows.read().filter((i) => i.object.trim() !== ""), ...added]))),
    el("div", { class: "field" }, el("label", { for: ids.mode, text: "Retrieval" }), modeSelect),
    el("h3", { text: "Examples" }),
    exampleButtons((query) => emitAndRender(query)),
    labelList,
    stateList,
  );

  renderVocabulary(labelList, stateList, store.state);
  renderDishes(dishSelect, recipes, store.state);
  rows.render(store.state.query.ingredients);
  modeSelect.value = store.state.query.mode ?? "heuristic";

  return store.subscribe((state, previous) => {
    modeSelect.value = state.query.mode ?? "heuristic";
    if (state.kb !== previous.kb) renderVocabulary(labelList, stateList, state);
    if (state.kb !== previous.kb || state.query.dish !== previous.query.dish) renderDishes(dishSelect, recipes, state);
    if (state.query !== previous.query && !sameQuery(state.query, shown)) {
      shown = state.query;
      rows.render(state.query.ingredients);
    }
  });
}
