// The task tree of a plan as graph data: object nodes (one per distinct label + states, so an output that
// feeds a later unit is one node), a motion node per functional unit, edges input -> motion -> output,
// and the marks of what modification changed. Pure: the Cytoscape view and the SVG export render it.

import type { Plan, PlanNode, UnitOrigin } from "../../planner/types";

export type Mark = Exclude<UnitOrigin, "reference"> | "substituted";

export interface TreeNode {
  id: string;
  kind: "object" | "motion";
  label: string;
  /** States as text (object nodes) or the unit's number (motion nodes), shown under the label. */
  detail: string;
  /** Index of the functional unit: the motion's own, or the unit that makes (else first uses) the object. */
  unit: number;
  /** The query ingredient whose progress line this node is on, if any. */
  ingredient: string | null;
  mark: Mark | null;
  goal: boolean;
}

export interface TreeEdge {
  id: string;
  source: string;
  target: string;
}

export interface TreeGraph {
  nodes: TreeNode[];
  edges: TreeEdge[];
}

export function objectKey(n: PlanNode): string {
  return `o:${n.label}|${[...n.states].sort().join("|")}`;
}

export function motionKey(unit: number): string {
  return `m:${unit}`;
}

/** Labels substituted into the tree (cases 2 and 4): the query objects that replaced an equivalent. */
function substitutedLabels(plan: Plan): Set<string> {
  return new Set(plan.ingredients.filter((i) => i.case === 2 || i.case === 4).map((i) => i.object));
}

export function planToGraph(plan: Plan): TreeGraph {
  const nodes = new Map<string, TreeNode>();
  const edges: TreeEdge[] = [];
  const lines = new Set(plan.progress_lines.map((l) => l.ingredient));
  const substituted = substitutedLabels(plan);
  const goalKey = objectKey({ label: plan.goal.label, states: plan.goal.states, ingredients: [], container: null });

  const objectNode = (n: PlanNode, unit: number, madeHere: boolean, origin: UnitOrigin): string => {
    const id = objectKey(n);
    const known = nodes.get(id);
    const mark: Mark | null = substituted.has(n.label) ? "substituted" : madeHere && origin !== "reference" ? origin : null;
    if (known === undefined) {
      nodes.set(id, {
        id,
        kind: "object",
        label: n.label,
        detail: n.states.join(", "),
        unit,
        ingredient: lines.has(n.label) ? n.label : null,
        mark,
        goal: id === goalKey,
      });
    } else if (madeHere) {
      // the unit that makes an object is the one to show for it
      known.unit = unit;
      known.mark ??= mark;
    }
    return id;
  };

  plan.units.forEach((u, i) => {
    const motion = motionKey(i);
    nodes.set(motion, {
      id: motion,
      kind: "motion",
      label: u.motion,
      detail: `step ${i + 1}`,
      unit: i,
      ingredient: u.inputs.map((n) => n.label).find((l) => lines.has(l)) ?? null,
      mark: u.origin === "reference" ? null : u.origin,
      goal: false,
    });
    for (const input of u.inputs) {
      const id = objectNode(input, i, false, u.origin);
      edges.push({ id: `e:${id}>${motion}`, source: id, target: motion });
    }
    for (const output of u.outputs) {
      const id = objectNode(output, i, true, u.origin);
      edges.push({ id: `e:${motion}>${id}`, source: motion, target: id });
    }
  });
  // the last unit's outputs are the goal when the reference goal was renamed by modification
  if (![...nodes.values()].some((n) => n.goal) && plan.units.length > 0) {
    const last = plan.units[plan.units.length - 1]!;
    for (const out of last.outputs) {
      const node = nodes.get(objectKey(out));
      if (node !== undefined) node.goal = true;
    }
  }
  return { nodes: [...nodes.values()], edges: dedupe(edges) };
}

function dedupe(edges: TreeEdge[]): TreeEdge[] {
  const seen = new Set<string>();
  return edges.filter((e) => (seen.has(e.id) ? false : (seen.add(e.id), true)));
}

/** The units on an ingredient's progress line, in order: motion j of the line is units[j]. */
export function unitsOfIngredient(plan: Plan, ingredient: string): number[] {
  const out: number[] = [];
  plan.units.forEach((u, i) => {
    if (u.inputs.some((n) => n.label === ingredient)) out.push(i);
  });
  return out;
}

/** What is selected: a functional unit (its step), the ingredient whose progress line to highlight. */
export interface Selection {
  unit: number | null;
  ingredient: string | null;
  /** The graph node the user picked (else the unit's motion node is shown selected). */
  node: string | null;
}

export const NO_SELECTION: Selection = { unit: null, ingredient: null, node: null };

export function selectUnit(plan: Plan, unit: number): Selection {
  const u = plan.units[unit];
  if (u === undefined) return NO_SELECTION;
  const lines = new Set(plan.progress_lines.map((l) => l.ingredient));
  return { unit, ingredient: u.inputs.map((n) => n.label).find((l) => lines.has(l)) ?? null, node: motionKey(unit) };
}

export function selectNode(graph: TreeGraph, id: string): Selection {
  const node = graph.nodes.find((n) => n.id === id);
  if (node === undefined) return NO_SELECTION;
  return { unit: node.unit, ingredient: node.ingredient, node: node.id };
}

/** Selecting motion `motionIndex` of an ingredient's progress line selects that functional unit. */
export function selectProgressMotion(plan: Plan, ingredient: string, motionIndex: number): Selection {
  const unit = unitsOfIngredient(plan, ingredient)[motionIndex];
  if (unit === undefined) return { unit: null, ingredient, node: null };
  return { unit, ingredient, node: motionKey(unit) };
}

/** Plain-language caption of a unit: "dice: tomato, knife → tomato (diced, on [cutting board])". */
export function describeUnit(plan: Plan, unit: number): string {
  const u = plan.units[unit];
  if (u === undefined) return "";
  const names = (ns: PlanNode[]): string => ns.map((n) => (n.states.length === 0 ? n.label : `${n.label} (${n.states.join(", ")})`)).join(", ");
  return `${u.motion}: ${names(u.inputs)} → ${names(u.outputs)}`;
}
