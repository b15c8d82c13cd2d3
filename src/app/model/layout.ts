// Positions of a task tree's nodes, left to right towards the goal node. A task tree is nearly a tree
// rooted at its goal (an object used by two units is the exception), so a tidy tree layout fits it, at a
// fraction of a layered-DAG layout's cost (dagre, 15 kB gzip and milliseconds per re-plan): each node goes
// one column before its earliest user, and beside the children the walk from the goal first reached it
// through. Pure: the views only draw it.

import type { TreeEdge, TreeGraph } from "./tree";

export interface Point {
  x: number;
  y: number;
}

/** Column and row pitch in pixels: node size plus the gap the labels need. */
export const COLUMN_GAP = 100;
export const ROW_GAP = 60;

/** Graph nodes in edge order: the given edges' targets (or sources) of each node. */
function neighbours(ids: readonly string[], edges: readonly TreeEdge[], forward: boolean): Map<string, string[]> {
  const out = new Map<string, string[]>(ids.map((id) => [id, []]));
  for (const e of edges) out.get(forward ? e.source : e.target)?.push(forward ? e.target : e.source);
  return out;
}

/** How many edges the longest path from each node to a sink has (an edge closing a cycle is not followed). */
function depths(ids: readonly string[], successors: Map<string, string[]>): Map<string, number> {
  const depth = new Map<string, number>();
  const open = new Set<string>();
  const visit = (id: string): number => {
    const known = depth.get(id);
    if (known !== undefined) return known;
    open.add(id);
    let d = 0;
    for (const s of successors.get(id) ?? []) if (!open.has(s)) d = Math.max(d, visit(s) + 1);
    open.delete(id);
    depth.set(id, d);
    return d;
  };
  ids.forEach(visit);
  return depth;
}

/**
 * Each node's position: its column from its depth; its row from a tidy layout of the tree found from the
 * sinks (a node sits midway between its first and last child, a leaf in its column's first free row).
 */
export function layoutTree(graph: TreeGraph): Map<string, Point> {
  const ids = graph.nodes.map((n) => n.id);
  const successors = neighbours(ids, graph.edges, true);
  const predecessors = neighbours(ids, graph.edges, false);
  const depth = depths(ids, successors);
  const columns = Math.max(0, ...depth.values());
  const placed = new Map<string, Point>();
  const reached = new Set<string>();
  /** The first row of each column no node takes yet: rows only grow down a column, so nodes never overlap. */
  const free: number[] = Array.from({ length: columns + 1 }, () => 0);

  const place = (id: string): number => {
    reached.add(id);
    // the predecessors no other node has claimed are this node's children in the tree
    const children = (predecessors.get(id) ?? []).filter((p) => !reached.has(p));
    for (const c of children) reached.add(c);
    const rows = children.map(place);
    const column = columns - depth.get(id)!;
    const wanted = rows.length === 0 ? 0 : (rows[0]! + rows[rows.length - 1]!) / 2;
    const row = Math.max(wanted, free[column]!);
    free[column] = row + 1;
    placed.set(id, { x: column * COLUMN_GAP, y: row * ROW_GAP });
    return row;
  };
  const sinks = ids.filter((id) => successors.get(id)!.length === 0);
  // sinks first; a cycle with no way out has none, so any node not reached yet roots its own tree
  for (const id of [...sinks, ...ids]) if (!reached.has(id)) place(id);
  return placed;
}
