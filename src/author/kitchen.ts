// The drafter's model of the kitchen: which ingredient is where, what each container holds, and the functional
// units that the steps' verbs make of it (cut, add, mix, cook, transfer). Nodes are built as the plain
// dialect writes them (draft-foon.ts).

import table from "./draft-table.json";
import type { DraftNode, DraftUnit } from "./draft-foon";
import type { IngredientLine } from "./recipe-text";

export type VerbKind = "cut" | "mix" | "add" | "transfer" | "cook" | "skip";

export interface Verb {
  phrase: string;
  motion?: string;
  kind: VerbKind;
  state?: string;
  appliance?: string;
  /** The motion depends on the food ("add the milk" pours, "add the tomato" places it). */
  byFood?: boolean;
}

const START_STATE = new Map<string, string>(Object.entries(table.startStates).flatMap(([state, labels]) => labels.map((l) => [l, state] as [string, string])));
const ADD_MOTION = new Map<string, string>(Object.entries(table.addMotions).flatMap(([motion, labels]) => labels.map((l) => [l, motion] as [string, string])));
const POURED = new Set(["liquid", "powder", "creamy"]);
/** How an ingredient goes into a container when the verb does not say: eggs are cracked, salt sprinkled, liquids poured. */
export const motionToAdd = (food: string): string => ADD_MOTION.get(food) ?? (POURED.has(START_STATE.get(food) ?? "") ? "pour" : "pick-and-place");

const tool = (label: string): DraftNode => ({ label, states: ["clean"], inside: null, contains: null, flag: 1 });
const appliance = (label: string): DraftNode => ({ label, states: ["on"], inside: null, contains: null, flag: 0 });
const withState = (n: DraftNode, state: string): DraftNode => ({ ...n, states: [...n.states.filter((s) => s !== "whole" && s !== state), state] });
const sorted = (xs: Iterable<string>): string[] => [...new Set(xs)].sort();
/** What a mixture, or a food that others were put on, holds. */
const holds = (n: DraftNode): string[] => n.contains ?? [n.label];

/** The kitchen as the steps change it: where each ingredient is and what each container holds. */
export class Kitchen {
  readonly units: DraftUnit[] = [];
  /** Ingredient -> its node, until it becomes part of a mixture. */
  readonly foods = new Map<string, DraftNode>();
  /** Container -> its node; a container with a mixture in it is in `mixtures`. */
  readonly containers = new Map<string, DraftNode>();
  readonly mixtures = new Map<string, DraftNode>();
  current: string | null = null;

  constructor(readonly ingredients: readonly IngredientLine[]) {
    for (const i of ingredients) this.foods.set(i.label, { label: i.label, states: [START_STATE.get(i.label) ?? "whole"], inside: null, contains: null, flag: 1 });
  }

  private emit(inputs: DraftNode[], motion: string, outputs: DraftNode[], notes: string[]): void {
    this.units.push({ inputs, motion, outputs, notes });
  }

  container(label: string): DraftNode {
    return this.containers.get(label) ?? { label, states: [], inside: null, contains: [], flag: 0 };
  }

  /** Where an ingredient is now: in a mixture (its container) or as itself. */
  mixtureHolding(food: string): string | null {
    for (const [c, m] of this.mixtures) if (holds(m).includes(food)) return c;
    return null;
  }

  cut(food: string, verb: Verb, notes: string[]): void {
    const node = this.foods.get(food);
    if (node === undefined || verb.state === undefined || node.states.includes(verb.state)) return;
    const out = withState(node, verb.state);
    this.emit([node, tool(table.tools.cut)], verb.motion!, [out], notes);
    this.foods.set(food, out);
  }

  add(food: string, into: string, motion: string, notes: string[]): void {
    const node = this.foods.get(food);
    const held = this.mixtureHolding(food);
    if (node === undefined && held !== null && held !== into) this.transfer(held, into, motion, notes);
    if (node === undefined || node.inside === into) return;
    const mixture = this.mixtures.get(into);
    if (mixture !== undefined) {
      // a topping: the mixture grows
      const grown = { ...mixture, contains: sorted([...holds(mixture), food]) };
      this.emit([mixture, node], motion, [grown], notes);
      this.mixtures.set(into, grown);
      this.foods.delete(food);
    } else {
      const holder = this.container(into);
      const grown = { ...holder, contains: sorted([...(holder.contains ?? []), food]) };
      const moved = { ...node, inside: into };
      this.emit([holder, node], motion, [grown, moved], notes);
      this.containers.set(into, grown);
      this.foods.set(food, moved);
    }
    this.current = into;
  }

  /** Everything in a container becomes one mixture. */
  mix(into: string, verb: Verb, notes: string[]): void {
    const holder = this.container(into);
    const loose = [...this.foods.values()].filter((n) => n.inside === into);
    const before = this.mixtures.get(into);
    if (loose.length === 0 && before === undefined) return;
    const contains = sorted([...(before === undefined ? [] : holds(before)), ...loose.map((n) => n.label)]);
    const out: DraftNode = { label: "mixture", states: [verb.state ?? "mixed"], inside: into, contains, flag: 1 };
    this.emit([...(before === undefined ? [holder] : [before]), ...loose], verb.motion!, [out], notes);
    for (const n of loose) this.foods.delete(n.label);
    this.mixtures.set(into, out);
    this.current = into;
  }

  /** Cooks foods on their own, or a container's contents (its mixture, or the foods in it, the container staying as it is). */
  cook(foods: readonly string[], into: string | null, verb: Verb, notes: string[]): void {
    const extra = verb.appliance === undefined || verb.appliance === into ? [] : [appliance(verb.appliance)];
    const mixture = into === null ? undefined : this.mixtures.get(into);
    if (mixture !== undefined) {
      const out = withState(mixture, verb.state!);
      this.emit([mixture, ...extra], verb.motion!, [out], notes);
      this.mixtures.set(into!, out);
      return;
    }
    const nodes = into === null ? foods.flatMap((f) => this.foods.get(f) ?? []) : [...this.foods.values()].filter((n) => n.inside === into);
    if (nodes.length === 0) return;
    const outputs = nodes.map((n) => withState(n, verb.state!));
    this.emit([...(into === null ? [] : [this.container(into)]), ...nodes, ...extra], verb.motion!, outputs, notes);
    for (const out of outputs) this.foods.set(out.label, out);
  }

  /** A food that others go on ("spread the butter on the bread"): it becomes a holder, keyed by its container or its name. */
  hold(food: string): string | null {
    const held = this.mixtureHolding(food);
    const node = this.foods.get(food);
    if (node === undefined) return held;
    const key = node.inside ?? food;
    if (this.mixtures.has(key)) return key;
    this.mixtures.set(key, node);
    this.foods.delete(food);
    return key;
  }

  /** Moves a container's mixture (or its foods) into another container; a mixture there takes it in. */
  transfer(from: string, into: string, motion: string, notes: string[]): void {
    const mixture = this.mixtures.get(from);
    if (mixture === undefined) {
      for (const n of [...this.foods.values()].filter((f) => f.inside === from)) this.add(n.label, into, motion, notes);
      return;
    }
    const there = this.mixtures.get(into);
    const moved = there === undefined ? { ...mixture, inside: into } : { ...there, contains: sorted([...holds(there), ...holds(mixture)]) };
    this.emit([there ?? this.container(into), mixture], motion, [moved], notes);
    this.mixtures.delete(from);
    this.mixtures.set(into, moved);
    this.current = into;
  }
}
