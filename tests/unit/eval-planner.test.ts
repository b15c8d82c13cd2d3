// The evaluation on the real planner: a few dev queries per dish type, FOON-111 and the starter KB.
import { describe, expect, it } from "vitest";
import { metricsTable } from "../../src/eval/aggregate";
import { planFunction } from "../../src/eval/planner-adapter";
import { runBatch } from "../../src/eval/runner";
import { readQueries } from "../../src/cli/queries";
import { loadPlannerFromDisk, STARTER_KB_DIR } from "../../src/planner/node";
import { sharedPath } from "./helpers";

describe("evaluation with the real planner", () => {
  const queries = readQueries(sharedPath("recipes/dev")).filter((_, i) => i % 40 === 0);

  for (const [name, kb] of [["FOON-111", () => sharedPath("foon/subgraphs-plain")], ["starter KB", () => STARTER_KB_DIR]] as const) {
    it(`plans ${queries.length} dev queries with ${name} in both variants`, () => {
      const planner = loadPlannerFromDisk(kb());
      const records = runBatch(planFunction(planner), queries, ["modified", "unmodified"], () => performance.now());
      planner.free();
      const table = [...metricsTable(records, "modified"), ...metricsTable(records, "unmodified")];
      // the invariants themselves are checked on all dev queries by `npm test` (scripts/test.sh)
      expect(table.every((r) => r.duplicate_units === 0 && r.dead_units === 0)).toBe(true);
      const all = table.filter((r) => r.group === "all");
      for (const row of all) expect(row.plans).toBeGreaterThan(0);
      // modification brings the query's ingredients into the tree
      expect(all[0]!.pair_share).toBeGreaterThanOrEqual(all[1]!.pair_share);
      expect(all[0]!.object_share).toBeGreaterThanOrEqual(all[1]!.object_share);
    }, 60_000);
  }
});
