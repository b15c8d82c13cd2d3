// Draft from recipe text: a FOON subgraph proposed from a recipe's title, ingredient lines and steps.
// Each step's verbs are looked up in the project's verb table (draft-table.json) and become functional
// units in a small model of the kitchen (which food is where, what each container holds); containers
// come from the step's prepositions, the goal node and its dish class from the title. Whatever the
// drafter had to guess becomes a `# confirm:` mark for the user.

import table from "./draft-table.json";
import { draftToFoon, foonLabel, type DraftUnit } from "./draft-foon";
import { Kitchen, motionToAdd, type Verb } from "./kitchen";
import { readRecipe, singular, type IngredientLine } from "./recipe-text";

export type { Verb, VerbKind } from "./kitchen";
export const VERBS = table.verbs as Verb[];

export interface Draft {
  title: string;
  fileName: string;
  /** Dish class index of the goal node; null when the title names none (marked for the user). */
  dishClass: number | null;
  units: DraftUnit[];
  /** Marks that belong to no one unit (unknown verbs, unused ingredients, unknown objects). */
  notes: string[];
  text: string;
}

export interface DraftOptions {
  /** The knowledge base's object labels: an ingredient outside them is marked for the user. */
  labels?: readonly string[];
}

const escape = (s: string): string => s.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");
const byLength = (a: string, b: string): number => b.length - a.length;
const phraseRegex = (phrases: readonly string[]): RegExp => new RegExp(`\\b(${[...phrases].sort(byLength).map(escape).join("|")})\\b`, "gi");

const VERB_RE = phraseRegex(VERBS.map((v) => v.phrase));
const VERB_OF = new Map(VERBS.map((v) => [v.phrase, v]));
const CONTAINER_RE = new RegExp(`\\b(?:in|into|to|on|onto|over|inside)\\s+(?:(?:a|an|the|your|large|big|small|medium|clean|separate|another|greased|prepared|hot)\\s+)*?(${[...table.containers].sort(byLength).map(escape).join("|")})\\b`, "i");
const CONTAINER_NAMES = table.containerNames as Record<string, string>;
const PRONOUN = /\b(them|it|they|everything|all)\b/i;
const ALL = /\b(everything|all (?:the )?(?:remaining )?ingredients|remaining ingredients|the rest)\b/i;

/** The verbs of a text in order, each with the text up to the next verb. */
export function verbSegments(text: string): { verb: Verb; text: string }[] {
  const found = [...text.matchAll(VERB_RE)];
  return found.map((m, i) => ({ verb: VERB_OF.get(m[1]!.toLowerCase())!, text: text.slice(m.index, found[i + 1]?.index ?? text.length) }));
}

/** The dish class named in a title: the last dish word in it ("potato salad" -> salad). */
export function dishClassOf(title: string): number | null {
  let best: { at: number; cls: number } | null = null;
  for (const d of table.dishes) {
    const m = new RegExp(`\\b${escape(d.word)}(e?s)?\\b`, "i").exec(title);
    if (m !== null && (best === null || m.index + m[0].length > best.at)) best = { at: m.index + m[0].length, cls: d.class };
  }
  return best?.cls ?? null;
}

export function containerOf(text: string): string | null {
  const m = CONTAINER_RE.exec(text);
  if (m === null) return null;
  const word = m[1]!.toLowerCase();
  return CONTAINER_NAMES[word] ?? word;
}

/** The ingredients a piece of text names, in the order of the ingredient list. */
function mentioned(text: string, ingredients: readonly IngredientLine[]): string[] {
  const lower = text.toLowerCase();
  const words = new Set(lower.split(/[^a-z-]+/).map(singular));
  const full = ingredients.filter((i) => new RegExp(`\\b${escape(i.label)}(e?s)?\\b`).test(lower)).map((i) => i.label);
  // "the onion" for "red onion": the head word, when the full name is not there
  const heads = ingredients.filter((i) => !full.includes(i.label) && words.has(i.label.split(" ").at(-1)!)).map((i) => i.label);
  return [...full, ...heads.filter((h) => !full.some((f) => f.endsWith(h.split(" ").at(-1)!)))];
}

/** The food a verb puts things on or into ("on the bread", "to the cabbage"), if the text names one. */
function targetFood(text: string, foods: readonly string[]): string | null {
  const lower = text.toLowerCase();
  return foods.find((f) => new RegExp(`\\b(?:on|onto|over|to|into)\\s+(?:the\\s+|some\\s+)?(?:\\w+\\s+)?${escape(f.split(" ").at(-1)!)}`).test(lower)) ?? null;
}

interface StepContext {
  kitchen: Kitchen;
  ingredients: readonly IngredientLine[];
  /** The foods of the previous verb ("them", "it"). */
  last: string[];
}

/** "add", "pour", "spread", "top with": foods into a container, onto a food, or the current container's contents moved on. */
function addAll(kitchen: Kitchen, foods: readonly string[], verb: Verb, text: string, into: string | null, notes: string[]): void {
  const motion = (f: string): string => (verb.byFood === true ? motionToAdd(f) : verb.motion!);
  const target = into === null ? targetFood(text, foods) : null;
  const others = foods.filter((f) => f !== target);
  if (target !== null && others.length > 0) {
    const key = kitchen.hold(target);
    if (key !== null) for (const f of others) kitchen.add(f, key, motion(f), notes);
    return;
  }
  const from = kitchen.current;
  if (target !== null) {
    // "pour the dressing over the cabbage": what is in use goes where that food is
    const to = kitchen.foods.get(target)?.inside ?? kitchen.mixtureHolding(target);
    if (from !== null && to !== null && to !== from) kitchen.transfer(from, to, verb.motion!, notes);
    return;
  }
  if (foods.length === 0 && from !== null && into !== null && into !== from) kitchen.transfer(from, into, verb.motion!, notes);
  for (const f of foods) kitchen.add(f, into ?? from!, motion(f), notes);
}

function applySegment(ctx: StepContext, verb: Verb, text: string, step: number): void {
  const { kitchen } = ctx;
  let foods = mentioned(text, ctx.ingredients);
  const notes: string[] = [];
  if (foods.length === 0 && ALL.test(text)) foods = ctx.ingredients.map((i) => i.label).filter((l) => kitchen.foods.has(l) && kitchen.foods.get(l)!.inside !== kitchen.current);
  if (foods.length === 0 && (verb.kind === "cut" || verb.kind === "add") && ctx.last.length > 0 && PRONOUN.test(text)) {
    foods = ctx.last;
    notes.push(`step ${step}: "${text.trim()}" taken to mean ${foods.join(", ")}`);
  }
  let into = containerOf(text);
  if (into === null && (verb.kind === "add" || verb.kind === "mix" || verb.kind === "transfer") && kitchen.current === null) {
    into = "mixing bowl";
    notes.push(`step ${step}: no container named for "${verb.phrase}": a mixing bowl assumed`);
  }
  const place = into ?? kitchen.current;
  switch (verb.kind) {
    case "cut":
      for (const f of foods) kitchen.cut(f, verb, notes);
      break;
    case "add":
      addAll(kitchen, foods, verb, text, into, notes);
      break;
    case "mix":
      for (const f of foods) if (kitchen.mixtureHolding(f) !== place) kitchen.add(f, place!, motionToAdd(f), notes);
      kitchen.mix(place!, verb, notes);
      break;
    case "cook": {
      // on the stove, named foods join the pan already in use
      const pan = into ?? (verb.appliance === "stove" ? kitchen.current : null);
      if (pan !== null) for (const f of foods) kitchen.add(f, pan, motionToAdd(f), notes);
      kitchen.cook(foods, pan ?? (foods.length > 0 ? null : kitchen.current), verb, notes);
      break;
    }
    case "transfer":
      if (kitchen.current !== null && into !== null && into !== kitchen.current) kitchen.transfer(kitchen.current, into, verb.motion!, notes);
      break;
    case "skip":
      break;
  }
  if (foods.length > 0) ctx.last = foods;
}

/** Units for what the ingredient lines say was done before the steps ("garlic, minced"). */
function prepUnits(kitchen: Kitchen, ingredients: readonly IngredientLine[], notes: string[]): void {
  for (const i of ingredients) {
    if (i.prep === "") continue;
    const segments = verbSegments(i.prep).filter((s) => s.verb.kind === "cut" || s.verb.kind === "cook");
    if (segments.length === 0) notes.push(`ingredient "${i.text}": "${i.prep}" is no preparation the drafter knows`);
    for (const { verb } of segments) {
      if (verb.kind === "cut") kitchen.cut(i.label, verb, []);
      else kitchen.cook([i.label], null, verb, []);
    }
  }
}

/** The last unit's product — what holds everything (a container or mixture), else its food — becomes the goal
 * node: the dish's name, its dish class, all its ingredients. */
function markGoal(units: DraftUnit[], label: string, dishClass: number | null): void {
  const last = units.at(-1);
  if (last === undefined) return;
  const holder = last.outputs.findIndex((n) => (n.contains?.length ?? 0) > 0);
  const index = holder !== -1 ? holder : last.outputs.findIndex((n) => n.flag === 1);
  const out = last.outputs[index];
  if (out === undefined) return;
  last.outputs[index] = { ...out, label, flag: 1, contains: out.contains ?? [out.label], ...(dishClass === null ? {} : { dishClass }) };
}

function goalLabel(title: string): string {
  return foonLabel(title.replace(/\b(easy|quick|simple|best|homemade|classic|my|perfect)\b/gi, " ")) || "my dish";
}

export function draftRecipe(text: string, options: DraftOptions = {}): Draft {
  const recipe = readRecipe(text);
  const title = recipe.title === "" ? "My recipe" : recipe.title;
  const ingredients = recipe.ingredients.map((i) => ({ ...i, label: foonLabel(i.label) })).filter((i) => i.label !== "");
  const notes: string[] = [];
  const known = options.labels === undefined ? null : new Set(options.labels);
  for (const i of ingredients) if (known !== null && !known.has(i.label)) notes.push(`"${i.label}" (from "${i.text}") is not an object of the knowledge base: keep it as new or rename it`);
  const kitchen = new Kitchen(ingredients);
  prepUnits(kitchen, ingredients, notes);
  const ctx: StepContext = { kitchen, ingredients, last: [] };
  recipe.steps.forEach((step, i) => {
    const segments = verbSegments(step);
    if (segments.length === 0) notes.push(`step ${i + 1} ("${step}") has no verb the drafter knows: write its units`);
    for (const s of segments) applySegment(ctx, s.verb, s.text, i + 1);
  });
  const used = new Set(kitchen.units.flatMap((u) => u.inputs.flatMap((n) => [n.label, ...(n.contains ?? [])])));
  for (const i of ingredients) if (!used.has(i.label)) notes.push(`"${i.label}" is listed but no step uses it`);
  const dishClass = dishClassOf(title);
  if (dishClass === null) notes.push("the title names no dish class: add it as the 4th field of the goal node's O line");
  markGoal(kitchen.units, goalLabel(title), dishClass);
  const fileName = goalLabel(title).replace(/[^a-z0-9]+/g, "-").replace(/^-|-$/g, "");
  return { title, fileName, dishClass, units: kitchen.units, notes, text: draftToFoon(title, notes, kitchen.units) };
}
