// Batch worker: loads the planner and the knowledge base, then plans every query in every variant,
// posting each result as soon as it is made. Cancelling terminates the worker; results already posted
// are kept by the page.

import { FoonPlanner, initPlanner, toPlannerError } from "../planner/index";
import { planFunction } from "../eval/planner-adapter";
import { runBatch } from "../eval/runner";
import type { RunRequest, WorkerMessage } from "./protocol";

const post = (message: WorkerMessage): void => postMessage(message);

async function run(request: RunRequest): Promise<void> {
  await initPlanner();
  const planner = FoonPlanner.load(request.knowledgeBase, request.embeddings ?? undefined);
  const stats = planner.stats();
  post({ kind: "loaded", subgraphs: stats.subgraphs, units: stats.units });
  const plan = planFunction(planner);
  runBatch(plan, request.queries, request.variants, () => performance.now(), (result, done, total) => {
    post({ kind: "result", record: result.record, plan: result.plan, done, total });
  });
  planner.free();
  post({ kind: "finished" });
}

onmessage = (event: MessageEvent<RunRequest>) => {
  run(event.data).catch((e: unknown) => post({ kind: "failed", message: toPlannerError(e).message }));
};
