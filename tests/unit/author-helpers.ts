// The editor's checks against the real WASM module, without a worker: the same calls the page's worker makes.
import { FoonPlanner, toPlannerError } from "../../src/planner/index";
import { initPlannerFromDisk } from "../../src/planner/node";
import type { CheckPlanner } from "../../src/author/check";

export function directPlanner(): CheckPlanner & { current(): FoonPlanner | null } {
  initPlannerFromDisk();
  let planner: FoonPlanner | null = null;
  return {
    current: () => planner,
    async loadFiles(files) {
      const next = FoonPlanner.load(files);
      planner?.free();
      planner = next;
      return { name: files.map((f) => f.name).join(", "), stats: next.stats(), vocabulary: next.vocabulary(), warnings: next.warnings(), embeddings: false, phases: [] };
    },
    async plan(request) {
      if (planner === null) throw toPlannerError(new Error("nothing loaded"));
      return { plan: planner.plan(request), ms: 0 };
    },
  };
}
