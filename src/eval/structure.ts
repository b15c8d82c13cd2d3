// Structural invariants of a plan, computed from its `units` alone (not from the planner's claims):
// duplicated units, units scheduled before their inputs exist, dead units.

import type { Plan, PlanNode, PlanUnit } from "../planner/types";
import type { StructureMetrics } from "./types";

const sorted = (items: readonly string[]): string[] => [...items].sort();

/** Identity of an object node: label, states, ingredients (as sets) and container. */
export function nodeKey(node: PlanNode): string {
  return JSON.stringify([node.label, sorted(node.states), sorted(node.ingredients), node.container]);
}

/**
 * States of things a kitchen has before cooking starts. A node in only such states, not inside anything
 * and containing nothing (an empty bowl, a clean knife, a pot lid, a whole onion), is available from the
 * start even when a later unit makes it again (a bowl emptied, a lid put back).
 */
export const START_STATES: ReadonlySet<string> = new Set(["empty", "clean", "whole", "raw", "off", "off (ready)", "unopened", "closed", "dry"]);

export function availableAtStart(node: PlanNode): boolean {
  return node.ingredients.length === 0 && node.container === null && node.states.every((s) => START_STATES.has(s));
}

/** Identity of a unit: motion and its input and output nodes (as sets). */
export function unitKey(unit: PlanUnit): string {
  return JSON.stringify([unit.motion, sorted(unit.inputs.map(nodeKey)), sorted(unit.outputs.map(nodeKey))]);
}

/** Output nodes a unit makes: its outputs that are not also among its inputs (utensils pass through). */
export function producedKeys(unit: PlanUnit): Set<string> {
  const inputs = new Set(unit.inputs.map(nodeKey));
  return new Set(unit.outputs.map(nodeKey).filter((key) => !inputs.has(key)));
}

/** Whether a node is the goal node: its label and states. */
export function isGoal(node: PlanNode, goal: Plan["goal"]): boolean {
  if (node.label !== goal.label) return false;
  const a = sorted(node.states);
  const b = sorted(goal.states);
  return a.length === b.length && a.every((s, i) => s === b[i]);
}

export function structureMetrics(units: readonly PlanUnit[], goal: Plan["goal"]): StructureMetrics {
  const produced = units.map(producedKeys);
  const inputKeys = units.map((u) => new Set(u.inputs.map(nodeKey)));
  /** First unit index that produces each node. */
  const firstProducer = new Map<string, number>();
  produced.forEach((keys, i) => {
    for (const key of keys) if (!firstProducer.has(key)) firstProducer.set(key, i);
  });

  /** Last unit index that uses each node as an input. */
  const lastUse = new Map<string, number>();
  inputKeys.forEach((keys, i) => {
    for (const key of keys) lastUse.set(key, i);
  });

  /** Every unit index that produces each node. */
  const producers = new Map<string, number[]>();
  produced.forEach((keys, i) => {
    for (const key of keys) producers.set(key, [...(producers.get(key) ?? []), i]);
  });
  /** Whether unit `j` needs unit `i` first: it uses something `i` makes, directly or through earlier units. */
  const dependsOn = (j: number, i: number): boolean => {
    const stack = [j];
    const visited = new Set<number>();
    while (stack.length > 0) {
      const k = stack.pop()!;
      if (visited.has(k)) continue;
      visited.add(k);
      for (const key of inputKeys[k]!) {
        for (const m of producers.get(key) ?? []) {
          if (m >= k) continue;
          if (m === i) return true;
          stack.push(m);
        }
      }
    }
    return false;
  };

  const seen = new Map<string, number>();
  const violations: string[] = [];
  let duplicates = 0;
  let beforeInputs = 0;
  let dead = 0;
  let goalProduced = false;
  units.forEach((unit, i) => {
    const name = `unit ${i + 1} (${unit.motion})`;
    const key = unitKey(unit);
    const twin = seen.get(key);
    if (twin !== undefined) {
      duplicates += 1;
      violations.push(`${name} repeats unit ${twin + 1}`);
    } else seen.set(key, i);

    const early = unit.inputs.filter((node) => {
      const key = nodeKey(node);
      const first = firstProducer.get(key);
      if (first === undefined || first < i) return false;
      // the finished dish is never in the kitchen at the start, whatever its states say
      if (isGoal(node, goal)) return true;
      if (availableAtStart(node)) return false;
      // a state the recipe returns to (a lid put back, butter melted again in the pot) was there from
      // the start: every unit making it again needs this one first, so no order could do better
      return !(producers.get(key) ?? []).every((j) => dependsOn(j, i));
    });
    if (early.length > 0) {
      beforeInputs += 1;
      for (const node of early) violations.push(`${name} needs ${describeNode(node)}, first made by unit ${firstProducer.get(nodeKey(node))! + 1}`);
    }

    const outputsGoal = unit.outputs.some((node) => isGoal(node, goal));
    if (outputsGoal) goalProduced = true;
    const used = [...produced[i]!].some((k) => (lastUse.get(k) ?? -1) > i);
    if (!used && !outputsGoal) {
      dead += 1;
      violations.push(`${name} makes nothing a later unit uses`);
    }
  });

  return { units: units.length, duplicate_units: duplicates, units_before_inputs: beforeInputs, dead_units: dead, goal_produced: goalProduced, violations };
}

export function describeNode(node: PlanNode): string {
  return node.states.length === 0 ? node.label : `${node.label} [${node.states.join("; ")}]`;
}
