// How well a plan covers its query: query objects and (object, state) pairs present in the tree,
// starting ingredients nobody asked for, substitution cases and confidence.

import type { Plan, PlanNode } from "../planner/types";
import { isGoal, nodeKey, producedKeys } from "./structure";
import type { CaseCounts, CoverageMetrics } from "./types";

export const emptyCases = (): CaseCounts => ({ c1: 0, c2: 0, c3: 0, c4: 0, none: 0 });

function allNodes(plan: Plan): PlanNode[] {
  return plan.units.flatMap((u) => [...u.inputs, ...u.outputs]);
}

/**
 * Starting ingredients: labels of input nodes that no earlier unit produced, which end up in some
 * node's ingredient list (`contains {…}`) and are not used as a container.
 */
export function startingIngredients(plan: Plan): Set<string> {
  const nodes = allNodes(plan);
  const listed = new Set(nodes.flatMap((n) => n.ingredients));
  const containers = new Set(nodes.flatMap((n) => (n.container === null ? [] : [n.container])));
  const produced = new Set<string>();
  const starting = new Set<string>();
  for (const unit of plan.units) {
    for (const input of unit.inputs) {
      if (!produced.has(nodeKey(input)) && listed.has(input.label) && !containers.has(input.label)) starting.add(input.label);
    }
    for (const key of producedKeys(unit)) produced.add(key);
  }
  return starting;
}

export function coverageMetrics(plan: Plan): CoverageMetrics {
  const nodes = allNodes(plan);
  const labels = new Set(nodes.flatMap((n) => [n.label, ...n.ingredients]));
  const objects = new Set(plan.query.ingredients.map((i) => i.object));
  const pairs = new Map(plan.query.ingredients.map((i) => [JSON.stringify([i.object, i.state]), i]));
  const pairsInTree = [...pairs.values()].filter((q) => nodes.some((n) => n.label === q.object && n.states.includes(q.state)));
  // the dish as the last unit making it lists it: what the plan carries into the dish
  const dish = plan.units.flatMap((u) => u.outputs).filter((n) => isGoal(n, plan.goal)).at(-1);
  const inDish = new Set(dish === undefined ? [] : [dish.label, ...dish.ingredients]);

  const asked = new Set(objects);
  for (const outcome of plan.ingredients) if (outcome.match !== null) asked.add(outcome.match.label);
  const extra = [...startingIngredients(plan)].filter((label) => !asked.has(label)).sort();

  const cases = emptyCases();
  let substitutions = 0;
  let lowConfidence = 0;
  let unplannable = 0;
  for (const outcome of plan.ingredients) {
    if (outcome.case === null) cases.none += 1;
    else cases[`c${outcome.case}`] += 1;
    const substituted = outcome.match !== null && outcome.match.label !== outcome.object;
    if (substituted) {
      substitutions += 1;
      if (outcome.low_confidence) lowConfidence += 1;
    }
    if (outcome.status === "unplannable") unplannable += 1;
  }

  return {
    query_objects: objects.size,
    objects_in_tree: [...objects].filter((o) => labels.has(o)).length,
    objects_in_dish: [...objects].filter((o) => inDish.has(o)).length,
    query_pairs: pairs.size,
    pairs_in_tree: pairsInTree.length,
    extra_ingredients: extra,
    // the units the planner counts for its note on a plan keeping little of its reference (planner/mod.rs)
    reference_units: plan.units.filter((u) => u.origin === "reference" || u.origin === "renamed" || u.origin === "attached").length,
    reference_own_type: plan.dish_class !== null && plan.goal.dish_class === plan.dish_class.index,
    cases,
    substitutions,
    low_confidence: lowConfidence,
    unplannable,
  };
}
