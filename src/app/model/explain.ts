// The explain trace of a plan as a sequence of steps to replay (pure: the Algorithm view renders it).
// Each step has a one-sentence caption in the paper's terms, the paper's section, and the graph as it
// stands after the step: the search tree growing node by node (Alg. 2), the same tree during
// modification, without the pruned units after pruning, and at the end the plan's own task tree.

import type { CandidateUnit, ChoiceReason, Expansion, GoalCandidate, GoalTieBreak, IngredientTrace, Plan, Trace, TraceUnit } from "../../planner/types";
import { planToGraph, type TreeEdge, type TreeGraph, type TreeNode } from "./tree";

export type ExplainPhase = "goal" | "retrieval" | "modification" | "pruning" | "final";

export interface ExplainStep {
  phase: ExplainPhase;
  caption: string;
  /** Where the paper says it, e.g. "Section III-B, Algorithm 2". */
  section: string;
  graph: TreeGraph;
  /** Graph nodes to highlight: the node being expanded, the ingredient being modified. */
  focus: string[];
  /** Graph nodes still waiting in the search's queue. */
  frontier: string[];
  /** What competed at this step, best first where the trace ranks them. */
  rows: { text: string; value: string; chosen: boolean }[];
}

const SECTION: Record<ExplainPhase, string> = {
  goal: "Section III-A, Algorithm 1",
  retrieval: "Section III-B, Algorithm 2",
  modification: "Section III-C, Table I",
  pruning: "Section III-C",
  final: "Section III",
};

const WHY: Record<ChoiceReason, string> = {
  only: "it is the only unit that makes it",
  reused: "it is already in the tree (a unit is never used twice)",
  same_recipe: "it belongs to the recipe of the unit that needs it",
  no_detour: "the others would undo a change only they make (a detour)",
  heuristic: "it has the highest heuristic value g(u)",
  fewer_inputs: "it needs fewer inputs to be made",
  id: "the tie goes to the first unit in the knowledge base",
  fewest_units: "the tree through it has the fewest functional units",
  lowest_cost: "the tree through it costs a robot least",
  most_reliable: "a robot most likely carries out the tree through it",
};

const TIE_BREAK: Record<Exclude<GoalTieBreak, "kin_class" | "fuller_tree">, string> = {
  score: "the highest score",
  exact_matches: "more exact ingredient matches at an equal score",
  fewer_ingredients: "fewer ingredients at an equal score",
  name: "its name, every score being equal",
};

const objectId = (text: string): string => `t:${text}`;
const unitKey = (u: TraceUnit): string => `u:${u.inputs.join("+")}>${u.motion}>${u.outputs.join("+")}`;
const num = (x: number): string => x.toFixed(2);
/** A node's FOON text without its list of contents when it has other states, for a sentence:
 * "salad (in [bowl], mixed)", "bowl (contains {egg,milk})". */
function short(text: string): string {
  const shorter = text.replace(/contains \{[^}]*\}, /, "").replace(/, contains \{[^}]*\}\)$/, ")");
  return shorter.endsWith("()") ? text : shorter;
}

/** The search tree: object nodes by their FOON text, one motion node per unit. */
class SearchGraph {
  private readonly nodes = new Map<string, TreeNode>();
  private readonly edges = new Map<string, TreeEdge>();

  object(text: string, goal = false): string {
    const id = objectId(text);
    if (!this.nodes.has(id)) {
      const at = text.indexOf(" (");
      const label = at < 0 ? text : text.slice(0, at);
      const detail = at < 0 ? "" : text.slice(at + 2, -1);
      this.nodes.set(id, { id, kind: "object", label, detail, unit: -1, ingredient: null, mark: null, goal });
    }
    return id;
  }

  unit(u: TraceUnit): string {
    const id = unitKey(u);
    if (this.nodes.has(id)) return id;
    this.nodes.set(id, { id, kind: "motion", label: u.motion, detail: "", unit: -1, ingredient: null, mark: null, goal: false });
    const edge = (source: string, target: string): void => {
      this.edges.set(`${source}->${target}`, { id: `${source}->${target}`, source, target });
    };
    for (const i of u.inputs) edge(this.object(i), id);
    for (const o of u.outputs) edge(id, this.object(o));
    return id;
  }

  /** Removes a unit and the object nodes nothing links any more. */
  remove(u: TraceUnit): void {
    const id = unitKey(u);
    this.nodes.delete(id);
    for (const [key, e] of this.edges) if (e.source === id || e.target === id) this.edges.delete(key);
    const linked = new Set([...this.edges.values()].flatMap((e) => [e.source, e.target]));
    for (const [key, n] of this.nodes) if (n.kind === "object" && !n.goal && !linked.has(key)) this.nodes.delete(key);
  }

  snapshot(): TreeGraph {
    return { nodes: [...this.nodes.values()].map((n) => ({ ...n })), edges: [...this.edges.values()] };
  }
}

function goalReason(g: Trace["goal_selection"]): string {
  if (g.tie_break === null) return "it is the only one";
  if (g.tie_break === "kin_class") return `no recipe of the dish type fits well, and this ${g.kin_class ?? "kin"} recipe, a dish made the same way, fits clearly better`;
  if (g.tie_break === "fuller_tree") return "the best-scoring goal's task tree would keep next to nothing of itself for this query (at most two of its units), and this runner-up's keeps more";
  return `it has ${TIE_BREAK[g.tie_break]}`;
}

function goalStep(trace: Trace, plan: Plan, graph: SearchGraph): ExplainStep {
  const g = trace.goal_selection;
  const best: GoalCandidate | undefined = g.candidates[0];
  const focus = best === undefined ? [] : [graph.object(best.node, true)];
  const ofType = g.candidates.length - (g.kin_class === null ? 0 : 1);
  const among = g.searched_all ? `all ${ofType} goal nodes (no recipe of this dish type)` : `the ${ofType} goal node(s) of the dish type`;
  const why = goalReason(g);
  return {
    phase: "goal",
    caption: `Algorithm 1 compares the query's ingredients with ${among}: the reference goal node is “${plan.goal.reference}” from ${plan.goal.subgraph} (score ${num(plan.goal.score)}), because ${why}.`,
    section: SECTION.goal,
    graph: graph.snapshot(),
    focus,
    frontier: focus,
    rows: g.candidates.slice(0, 8).map((c, i) => ({
      text: `${c.node} — ${c.subgraph}`,
      value: `score ${num(c.score)} (recall ${num(c.recall)}, precision ${num(c.precision)}, ${c.exact_matches} exact)`,
      chosen: i === 0,
    })),
  };
}

function candidateRow(c: CandidateUnit, chosen: boolean): ExplainStep["rows"][number] {
  const flags = [c.reused ? "in the tree" : "", c.same_recipe ? "same recipe" : "", c.cycle ? "closes a cycle" : ""].filter((f) => f !== "");
  return { text: `${c.inputs.join(" + ")} → ${c.motion}`, value: `g(u) = ${num(c.heuristic)}${flags.length === 0 ? "" : `, ${flags.join(", ")}`}`, chosen };
}

function expansionCaption(e: Expansion): string {
  const chosen = e.chosen === null ? undefined : e.candidates[e.chosen];
  switch (e.outcome) {
    case "kitchen":
      return `“${short(e.node)}” is in the kitchen: the search takes it as it is.`;
    case "recipe_start":
      return `“${short(e.node)}” is a starting item of the recipe that needs it: taken from the kitchen, as that recipe did.`;
    case "cycle":
      return `Every functional unit making “${short(e.node)}” would close a cycle: it is taken as available.`;
    case "had_from_start":
      return `The recipe only makes “${short(e.node)}” again later: it had it from the start.`;
    case "expanded":
      return chosen === undefined
        ? `“${short(e.node)}” is expanded.`
        : `To make “${short(e.node)}”, ${e.candidates.length} functional unit(s) compete; “${chosen.motion}” is chosen because ${WHY[e.why ?? "only"]} (${chosen.value === undefined ? `g(u) = ${num(chosen.heuristic)}` : `value ${num(chosen.value)}`}).`;
  }
}

function retrievalSteps(trace: Trace, graph: SearchGraph, queue: string[]): ExplainStep[] {
  return trace.retrieval.map((e) => {
    const focus = graph.object(e.node);
    const at = queue.indexOf(focus);
    if (at >= 0) queue.splice(at, 1);
    const chosen = e.chosen === null ? undefined : e.candidates[e.chosen];
    if (chosen !== undefined) {
      graph.unit(chosen);
      for (const i of chosen.inputs) if (!queue.includes(objectId(i))) queue.push(objectId(i));
    }
    return {
      phase: "retrieval" as const,
      caption: expansionCaption(e),
      section: SECTION.retrieval,
      graph: graph.snapshot(),
      focus: [focus],
      frontier: [...queue],
      rows: e.candidates.map((c, i) => candidateRow(c, i === e.chosen)),
    };
  });
}

const ROUTE: Record<IngredientTrace["route"], string> = {
  override: "the equivalent you chose",
  exact: "a FOON label itself",
  tree: "its most similar ingredient in the reference task tree",
  foon: "its most similar ingredient in the universal FOON (none in the tree was close enough)",
  none: "no equivalent",
};

const CASE: Record<number, string> = {
  1: "Table I case 1 (object and state matched): no change",
  2: "Table I case 2 (state matched, object not): the equivalent is substituted",
  3: "Table I case 3 (object matched, state not): functional units are added to reach the state",
  4: "Table I case 4 (neither matched): substituted, and functional units added to reach the state",
};

function modificationStep(i: IngredientTrace, plan: Plan, graph: TreeGraph): ExplainStep {
  const match = plan.ingredients.find((o) => o.object === i.object && o.state === i.state)?.match ?? null;
  // the equivalent's nodes in the reference task tree, where the change happens
  const focus = match === null ? [] : graph.nodes.filter((n) => n.kind === "object" && n.label === match.label).map((n) => n.id);
  const equivalent = match === null || match.label === i.object ? "" : ` “${match.label}” (similarity ${num(match.similarity)}),`;
  const what = i.case === null ? "it cannot be planned" : CASE[i.case];
  const rows: ExplainStep["rows"] = [];
  if (i.tree_match !== null) rows.push({ text: `best in the reference tree: ${i.tree_match.label}`, value: `similarity ${num(i.tree_match.similarity)}`, chosen: i.route === "tree" });
  if (i.foon_match !== null) rows.push({ text: `best in the universal FOON: ${i.foon_match.label}`, value: `similarity ${num(i.foon_match.similarity)}`, chosen: i.route === "foon" });
  const s = i.state_choice;
  if (s !== null) rows.push({ text: `state taxonomy: ${s.node ?? "taken as bought"}`, value: `category ${s.category}, ${s.in_state ? "in the state" : "as bought"}, seen ${s.frequency_in_class}× in the class (${s.frequency_overall}× overall)`, chosen: true });
  const a = i.attached;
  if (a !== null) rows.push({ text: `attached at “${a.motion}”`, value: a.rank === null ? "no motion of the dish pattern fits" : `motion ${a.rank + 1} of the dish pattern (${a.pattern.join(", ")})`, chosen: true });
  return {
    phase: "modification",
    caption: `“${i.state} ${i.object}”: the equivalent is ${ROUTE[i.route]},${equivalent} so ${what}${i.reason === null ? "." : ` — ${i.reason}.`}`,
    section: SECTION.modification,
    graph,
    focus,
    frontier: [],
    rows,
  };
}

function pruningStep(trace: Trace, graph: SearchGraph): ExplainStep {
  const p = trace.pruning;
  for (const u of p.units) graph.remove(u);
  const removed = p.removed.length === 0 ? "nothing was left that the query does not ask for" : `it removes ${p.removed.map((r) => `“${r}”`).join(", ")}, not asked for`;
  return {
    phase: "pruning",
    caption: `Pruning: ${removed}${p.units.length === 0 ? "." : `, and ${p.units.length} functional unit(s) with it.`}`,
    section: SECTION.pruning,
    graph: graph.snapshot(),
    focus: [],
    frontier: [],
    rows: p.units.map((u) => ({ text: `${u.inputs.join(" + ")} → ${u.motion}`, value: "removed", chosen: false })),
  };
}

/** The steps of a plan's trace, in order; `null` when the plan has no trace. */
export function explainSteps(plan: Plan): ExplainStep[] | null {
  const trace = plan.trace;
  if (trace === undefined) return null;
  const graph = new SearchGraph();
  const first = goalStep(trace, plan, graph);
  const queue = [...first.frontier];
  const steps = [first, ...retrievalSteps(trace, graph, queue)];
  if (plan.modified) {
    const reference = graph.snapshot();
    steps.push(...trace.ingredients.map((i) => modificationStep(i, plan, reference)));
    steps.push(pruningStep(trace, graph));
  }
  steps.push({
    phase: "final",
    caption: `The task tree: ${plan.units.length} functional unit(s) from the query's ingredients to “${plan.goal.label}”.`,
    section: SECTION.final,
    graph: planToGraph(plan),
    focus: [],
    frontier: [],
    rows: [],
  });
  return steps;
}
