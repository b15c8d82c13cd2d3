// The drafter measured (Node only): each recipe of tests/data/author-recipes — its text, then after a
// "---- units" line the functional units a person wrote for it — drafted and scored unit by unit.

import { readdirSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { FoonPlanner, toPlannerError } from "../planner/index";
import { initPlannerFromDisk, ROOT } from "../planner/node";
import type { CheckPlanner } from "./check";
import { checkText } from "./check";
import { draftRecipe, type Draft } from "./draft";
import { normalizeSignature, scoreDraft, unitSignature, type DraftScore } from "./draft-score";

export const DRAFT_FIXTURES = join(ROOT, "tests/data/author-recipes");
const SEPARATOR = /^---- units$/m;

export interface DraftFixture {
  name: string;
  recipe: string;
  units: string[];
}

export function readDraftFixtures(dir: string = DRAFT_FIXTURES): DraftFixture[] {
  return readdirSync(dir)
    .filter((f) => f.endsWith(".txt"))
    .sort()
    .map((name) => {
      const [recipe, units = ""] = readFileSync(join(dir, name), "utf8").split(SEPARATOR) as [string, string?];
      const lines = units.split("\n").map((l) => l.trim()).filter((l) => l !== "" && !l.startsWith("#"));
      if (lines.length === 0) throw new Error(`${name}: no units after the '---- units' line`);
      return { name, recipe, units: lines.map(normalizeSignature) };
    });
}

export interface DraftResult {
  name: string;
  draft: Draft;
  score: DraftScore;
}

export function evaluateDrafts(fixtures: readonly DraftFixture[]): { results: DraftResult[]; right: number; expected: number; drafted: number } {
  const results = fixtures.map((f) => {
    const draft = draftRecipe(f.recipe);
    return { name: f.name, draft, score: scoreDraft(draft.units.map(unitSignature), f.units) };
  });
  const sum = (key: "right" | "expected" | "drafted"): number => results.reduce((n, r) => n + r.score[key], 0);
  return { results, right: sum("right"), expected: sum("expected"), drafted: sum("drafted") };
}

/** The editor's checks against the WASM module in this process: the calls the page's worker makes. */
export function localPlanner(): CheckPlanner {
  initPlannerFromDisk();
  let planner: FoonPlanner | null = null;
  return {
    async loadFiles(files) {
      const next = FoonPlanner.load(files);
      planner?.free();
      planner = next;
      return { name: files.map((f) => f.name).join(", "), stats: next.stats(), vocabulary: next.vocabulary(), warnings: next.warnings(), embeddings: false, from: "files", phases: [] };
    },
    async plan(request) {
      if (planner === null) throw toPlannerError(new Error("no knowledge base is loaded"));
      return { plan: planner.plan(request), ms: 0 };
    },
  };
}

/** Drafts whose every unit the planner retrieves from their goal node (the rest leave units dangling). */
export async function connectedDrafts(results: readonly DraftResult[], planner: CheckPlanner = localPlanner()): Promise<string[]> {
  const connected: string[] = [];
  for (const r of results) {
    const check = await checkText(planner, r.name, r.draft.text);
    if (check.preview?.units.length === r.draft.units.length) connected.push(r.name);
  }
  return connected;
}
