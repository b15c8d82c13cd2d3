// Rating mode: step through the batch's recipes; for each, both plans (modified and reference tree,
// or "Plan A"/"Plan B" in blind mode) with each ingredient's progress line, rated 0/1/2 with the
// keyboard. Every rating is written through to IndexedDB at once.

import { BLIND_NAMES, variantOrder } from "../eval/blind";
import { recipeKey } from "../eval/queries";
import type { Score } from "../eval/ratings";
import type { EvalRecord, LoadedQuery, Variant } from "../eval/types";
import type { Plan } from "../planner/types";
import { byId, el } from "./dom";
import { ingredientView, outcomeNote, progressLine, taskTree } from "./plan-render";
import type { Workbench } from "./state";

interface Item {
  variant: Variant;
  object: string;
  state: string;
  /** Index of the ingredient in the query (and in plan.ingredients). */
  index: number;
}

const SCORE_NAMES: Record<Score, string> = { 0: "incorrect", 1: "partially incorrect", 2: "correct" };

/** Distinct (object, state) pairs of a query with the index of their first occurrence. */
function queryItems(query: LoadedQuery["query"]): { object: string; state: string; index: number }[] {
  const seen = new Set<string>();
  return query.ingredients.flatMap((i, index) => {
    const key = JSON.stringify([i.object, i.state]);
    if (seen.has(key)) return [];
    seen.add(key);
    return [{ object: i.object, state: i.state, index }];
  });
}

export class RateView {
  private cursor = 0;
  private showTrees = false;
  private items: Item[] = [];
  /** The recipe `items` belong to (ratings go to it even if the position moved meanwhile). */
  private itemsRecipe: LoadedQuery | null = null;
  private renderToken = 0;
  private readonly root = byId("rate-body", HTMLElement);

  constructor(
    private readonly bench: Workbench,
    private readonly active: () => boolean,
  ) {
    document.addEventListener("keydown", (event) => this.onKey(event));
    byId("prev-recipe", HTMLButtonElement).addEventListener("click", () => void this.move(-1));
    byId("next-recipe", HTMLButtonElement).addEventListener("click", () => void this.move(1));
    byId("toggle-trees", HTMLButtonElement).addEventListener("click", () => {
      this.showTrees = !this.showTrees;
      void this.render();
    });
  }

  /** Recipes of the batch that were planned (at least one record). */
  private queue(): LoadedQuery[] {
    const batch = this.bench.batch;
    if (batch === null) return [];
    const planned = new Set(batch.records.map((r) => recipeKey(r.recipe)));
    return batch.queries.filter((q) => planned.has(recipeKey(q.query)));
  }

  private position(queue: readonly LoadedQuery[]): number {
    const key = this.bench.settings.position;
    const i = queue.findIndex((q) => recipeKey(q.query) === key);
    return i < 0 ? 0 : i;
  }

  private forgetItems(): void {
    this.items = [];
    this.itemsRecipe = null;
  }

  async open(key: string): Promise<void> {
    this.cursor = 0;
    this.forgetItems();
    await this.bench.saveSettings({ position: key });
  }

  private async move(step: number): Promise<void> {
    const queue = this.queue();
    if (queue.length === 0) return;
    const next = Math.min(queue.length - 1, Math.max(0, this.position(queue) + step));
    this.cursor = 0;
    this.forgetItems(); // keys pressed before the next recipe is shown rate nothing
    await this.bench.saveSettings({ position: recipeKey(queue[next]!.query) });
  }

  private onKey(event: KeyboardEvent): void {
    if (!this.active() || event.ctrlKey || event.metaKey || event.altKey) return;
    const target = event.target;
    if (target instanceof HTMLInputElement || target instanceof HTMLTextAreaElement || target instanceof HTMLSelectElement) return;
    const key = event.key;
    if (key === "0" || key === "1" || key === "2") {
      event.preventDefault();
      void this.rate(this.cursor, Number(key) as Score, true);
    } else if (key === "ArrowDown" || key === "j") {
      event.preventDefault();
      this.setCursor(this.cursor + 1);
    } else if (key === "ArrowUp" || key === "k") {
      event.preventDefault();
      this.setCursor(this.cursor - 1);
    } else if (key === "ArrowRight" || key === "n") {
      event.preventDefault();
      void this.move(1);
    } else if (key === "ArrowLeft" || key === "p") {
      event.preventDefault();
      void this.move(-1);
    } else if (key === "t") {
      event.preventDefault();
      this.showTrees = !this.showTrees;
      void this.render();
    }
  }

  private setCursor(i: number): void {
    if (this.items.length === 0) return;
    this.cursor = Math.min(this.items.length - 1, Math.max(0, i));
    for (const row of this.root.querySelectorAll<HTMLElement>(".item")) {
      const current = Number(row.dataset.item) === this.cursor;
      row.classList.toggle("current", current);
      row.setAttribute("aria-current", current ? "true" : "false");
      if (current) row.scrollIntoView({ block: "nearest" });
    }
  }

  private async rate(i: number, score: Score, advance: boolean): Promise<void> {
    const item = this.items[i];
    const recipe = this.itemsRecipe;
    if (item === undefined || recipe === null) return;
    if (advance) this.cursor = Math.min(this.items.length - 1, i + 1);
    const { type, id } = recipe.query;
    await this.bench.rate([{ rater: this.bench.settings.rater, type, id, variant: item.variant, object: item.object, state: item.state, score, updated: new Date().toISOString() }]);
  }

  async render(): Promise<void> {
    const token = ++this.renderToken;
    const queue = this.queue();
    const counter = byId("rate-position", HTMLElement);
    if (queue.length === 0) {
      counter.textContent = "";
      this.forgetItems();
      delete this.root.dataset.recipe;
      this.root.replaceChildren(el("p", { text: "Run a batch first: its recipes are rated here." }));
      return;
    }
    const at = this.position(queue);
    const recipe = queue[at]!;
    const key = recipeKey(recipe.query);
    const { blind, seed, rater } = this.bench.settings;
    const order = variantOrder(key, seed, blind);
    const plans = await Promise.all(order.map((v) => this.bench.plan(recipe.query.type, recipe.query.id, v)));
    if (token !== this.renderToken) return; // a newer render started meanwhile
    const records = this.bench.batch?.records.filter((r) => recipeKey(r.recipe) === key) ?? [];
    const items = queryItems(recipe.query);
    this.items = order.flatMap((variant) => items.map((i) => ({ variant, ...i })));
    this.itemsRecipe = recipe;
    this.cursor = Math.min(this.cursor, this.items.length - 1);

    const ratedCount = this.items.filter((i) => this.bench.rating({ rater, type: recipe.query.type, id: recipe.query.id, ...i }) !== undefined).length;
    counter.textContent = `Recipe ${at + 1} of ${queue.length} — ${ratedCount}/${this.items.length} rated`;
    const panels = order.map((variant, v) =>
      this.panel(recipe, variant, blind ? BLIND_NAMES[v]! : variant === "modified" ? "With tree modification" : "Without modification (reference tree)", plans[v] ?? null, records.find((r) => r.variant === variant), v * items.length),
    );
    this.root.replaceChildren(
      el("h3", { class: "recipe-title" }, el("span", { text: recipe.query.type }), " ", el("code", { text: recipe.query.id })),
      el("p", { class: "query", text: `Asked for: ${recipe.query.ingredients.map((i) => `${i.state} ${i.object}`).join(", ")}` }),
      el("div", { class: "panels" }, ...panels),
    );
    this.root.dataset.recipe = key;
    this.setCursor(this.cursor);
  }

  private panel(recipe: LoadedQuery, variant: Variant, title: string, plan: Plan | null, record: EvalRecord | undefined, offset: number): HTMLElement {
    const { blind, rater } = this.bench.settings;
    const section = el("section", { class: "plan-panel", "data-panel": title, "data-variant": blind ? undefined : variant });
    section.append(el("h4", { text: title }));
    if (plan === null) {
      const why = record !== undefined && !record.ok ? `${record.error.code}: ${record.error.message}` : "the plan is not available";
      section.append(el("p", { class: "no-plan", text: `No plan (${why}). Rate its ingredients 0.` }));
    } else if (!blind) {
      section.append(el("p", { class: "goal", text: `Reference: ${plan.goal.reference} from ${plan.goal.subgraph} (score ${plan.goal.score.toFixed(2)})` }));
      const violations = record?.ok === true ? record.metrics.violations : [];
      if (violations.length > 0) section.append(el("ul", { class: "violations" }, ...violations.map((v) => el("li", { text: v }))));
    }
    const list = el("ol", { class: "items" });
    queryItems(recipe.query).forEach((item, j) => {
      const index = offset + j;
      const view = plan === null ? { outcome: undefined, line: undefined } : ingredientView(plan, item.index);
      const current = this.bench.rating({ rater, type: recipe.query.type, id: recipe.query.id, variant, object: item.object, state: item.state });
      const buttons = ([0, 1, 2] as const).map((score) => {
        const b = el("button", { type: "button", class: `score score-${score}`, "data-score": score, "aria-pressed": current?.score === score ? "true" : "false", title: SCORE_NAMES[score], text: String(score) });
        b.addEventListener("click", () => {
          this.cursor = index;
          void this.rate(index, score, false);
        });
        return b;
      });
      const row = el(
        "li",
        { class: "item", "data-item": index, "data-rated": current === undefined ? undefined : String(current.score) },
        el("div", { class: "item-head" }, el("strong", { class: "ingredient", text: `${item.state} ${item.object}` }), ...(blind ? [] : [outcomeNote(view.outcome)])),
        progressLine(plan === null ? undefined : view.line),
        el("div", { class: "scores", role: "group", "aria-label": `rating of ${item.state} ${item.object}` }, ...buttons),
      );
      row.addEventListener("click", (event) => {
        if (!(event.target instanceof HTMLButtonElement)) this.setCursor(index);
      });
      list.append(row);
    });
    section.append(list);
    if (plan !== null && this.showTrees) {
      section.append(el("h5", { text: `Task tree (${plan.units.length} units)` }), taskTree(plan, !blind));
    }
    return section;
  }
}
