// The query's ingredient rows: an object and a state each (autocomplete from the knowledge base, free text
// allowed), moved up or down, removed, or split into several by pasting a list into one row.

import type { QueryIngredient } from "../../planner/types";
import { el } from "../dom";
import { parseIngredientList } from "../query";

/** Where focus goes after the rows are drawn anew: a moved row's button, or a row's object field. */
export interface RowFocus {
  row: number;
  control: "up" | "down" | "object";
}

export interface IngredientRowsOptions {
  /** The ids of the datalists the object and state fields complete from. */
  labelsId: string;
  statesId: string;
  /** A field was typed in: the rows as they stand are the new ingredients. */
  typed(): void;
  /** Rows were moved, removed or split: the new ingredients, and where focus should go. */
  changed(ingredients: QueryIngredient[], focus?: RowFocus): void;
  /** The knowledge base's states, to split pasted phrases into object and state. */
  states(): readonly string[];
}

export interface IngredientRows {
  readonly element: HTMLOListElement;
  /** The ingredients as the fields show them. */
  read(): QueryIngredient[];
  render(ingredients: readonly QueryIngredient[], focus?: RowFocus): void;
}

export function ingredientRows(options: IngredientRowsOptions): IngredientRows {
  const element = el("ol", { class: "ingredient-rows", "aria-label": "Ingredients" });
  const read = (): QueryIngredient[] =>
    [...element.querySelectorAll<HTMLLIElement>("li")].map((li) => ({
      object: li.querySelector<HTMLInputElement>("input.object")?.value ?? "",
      state: li.querySelector<HTMLInputElement>("input.state")?.value ?? "",
    }));
  const render = (ingredients: readonly QueryIngredient[], focus?: RowFocus): void => {
    element.replaceChildren(...ingredients.map((i, k) => rowElement(i, k, ingredients.length, options, read)));
    if (focus !== undefined) focusRow(element, focus);
  };
  return { element, read, render };
}

function rowElement(ingredient: QueryIngredient, index: number, count: number, options: IngredientRowsOptions, read: () => QueryIngredient[]): HTMLLIElement {
  const n = index + 1;
  const object = el("input", {
    class: "object", type: "text", value: ingredient.object, list: options.labelsId, autocomplete: "off",
    "aria-label": `Ingredient ${n}: object`, placeholder: "object, e.g. tomato",
  });
  const state = el("input", {
    class: "state", type: "text", value: ingredient.state, list: options.statesId, autocomplete: "off",
    "aria-label": `Ingredient ${n}: state`, placeholder: "state, e.g. diced",
  });
  const up = el("button", { type: "button", class: "icon", "aria-label": `Move ingredient ${n} up`, title: "Move up", disabled: index === 0, text: "↑" });
  const down = el("button", { type: "button", class: "icon", "aria-label": `Move ingredient ${n} down`, title: "Move down", disabled: index === count - 1, text: "↓" });
  const remove = el("button", { type: "button", class: "icon", "aria-label": `Remove ingredient ${n}`, title: "Remove", text: "✕" });

  object.addEventListener("input", () => options.typed());
  state.addEventListener("input", () => options.typed());
  // pasting a whole list into one field adds a row per item
  object.addEventListener("paste", (event: ClipboardEvent) => {
    const text = event.clipboardData?.getData("text") ?? "";
    if (!/[,;\n]/.test(text)) return;
    event.preventDefault();
    const list = read();
    list.splice(index, 1, ...parseIngredientList(text, options.states()));
    options.changed(list);
  });
  const move = (delta: -1 | 1): void => {
    const list = read();
    const [item] = list.splice(index, 1);
    if (item === undefined) return;
    list.splice(index + delta, 0, item);
    options.changed(list, { row: index + delta, control: delta < 0 ? "up" : "down" });
  };
  up.addEventListener("click", () => move(-1));
  down.addEventListener("click", () => move(1));
  remove.addEventListener("click", () => {
    const list = read();
    list.splice(index, 1);
    options.changed(list, { row: Math.min(index, list.length - 1), control: "object" });
  });
  return el("li", { class: "ingredient-row" }, object, state, el("span", { class: "row-buttons" }, up, down, remove));
}

function focusRow(rows: HTMLOListElement, focus: RowFocus): void {
  if (focus.row < 0) return;
  const li = rows.children[focus.row];
  const field = li?.querySelector<HTMLInputElement>("input.object");
  const button = focus.control === "object" ? null : li?.querySelector<HTMLButtonElement>(`button[aria-label^="Move ingredient ${focus.row + 1} ${focus.control}"]`);
  // a disabled button cannot take focus: the row's object field takes it instead
  (button !== null && button !== undefined && !button.disabled ? button : field)?.focus();
}
