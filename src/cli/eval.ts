// `npm run eval -- --kb <dir> --queries <dir> [--no-modify | --both] [--out <dir>] [--write-plans]`:
// plans every query, prints the metrics table per dish type and overall, writes the results as JSON
// and CSV, and fails when a structural invariant breaks (duplicated, out-of-order or dead units).

import { mkdirSync, writeFileSync } from "node:fs";
import { join, relative, resolve } from "node:path";
import { performance } from "node:perf_hooks";
import { parseArgs } from "node:util";
import { describeError } from "../planner/index";
import { loadPlannerFromDisk, ROOT, STARTER_KB_DIR } from "../planner/node";
import { metricsTable } from "../eval/aggregate";
import { brokenInvariants, cautionExamples, formatTable, recipesCsv, summaryCsv, type EvalResults } from "../eval/format";
import { planFunction } from "../eval/planner-adapter";
import { runBatch } from "../eval/runner";
import { readQueries } from "./queries";
import type { Variant } from "../eval/types";

export const EVAL_USAGE = `usage: npm run eval -- --queries <dir> [--kb <dir-or-file>] [--exact] [--no-modify | --both] [--out <dir>] [--write-plans] [--quiet]

  --queries <dir>   recipe-query JSON files (searched recursively), e.g. ../shared/recipes/dev
  --kb <path>       knowledge base: folder of FOON files, a file or a .foon bundle (default: the starter KB)
  --exact           match ingredient names exactly (no embedding table)
  --no-modify       evaluate the reference task trees as retrieved (no tree modification)
  --both            evaluate both, with and without modification
  --out <dir>       where to write eval-<variant>.json, -summary.csv, -recipes.csv (default: test-results/eval)
  --write-plans     also write every plan to <out>/plans/<variant>/<type>/<id>.json
  --quiet           no progress on stderr
Exits with 1 when a structural invariant breaks (duplicated units, units before their inputs, dead units).
`;

export function evalCommand(args: string[]): void {
  const { values } = parseArgs({
    args,
    options: {
      kb: { type: "string" },
      exact: { type: "boolean", default: false },
      queries: { type: "string" },
      "no-modify": { type: "boolean", default: false },
      both: { type: "boolean", default: false },
      out: { type: "string" },
      "write-plans": { type: "boolean", default: false },
      quiet: { type: "boolean", default: false },
      help: { type: "boolean", default: false },
    },
    strict: true,
  });
  if (values.help) {
    process.stdout.write(EVAL_USAGE);
    return;
  }
  if (values.queries === undefined) throw new Error(`--queries is required\n${EVAL_USAGE}`);
  if (values.both && values["no-modify"]) throw new Error("--both and --no-modify exclude each other");
  const variants: Variant[] = values.both ? ["modified", "unmodified"] : values["no-modify"] ? ["unmodified"] : ["modified"];
  const kbPath = resolve(values.kb ?? STARTER_KB_DIR);
  const out = resolve(values.out ?? join(ROOT, "test-results/eval"));

  const queries = readQueries(resolve(values.queries));
  const planner = loadPlannerFromDisk(kbPath, { exact: values.exact });
  for (const w of planner.warnings()) if (!values.quiet) console.error(`warning: ${describeError(w)}`);
  const plan = planFunction(planner);

  const tty = process.stderr.isTTY && !values.quiet;
  const records = runBatch(plan, queries, variants, () => performance.now(), (result, done, total) => {
    if (values["write-plans"] && result.plan !== null) {
      const dir = join(out, "plans", result.record.variant, result.record.recipe.type);
      mkdirSync(dir, { recursive: true });
      writeFileSync(join(dir, `${result.record.recipe.id}.json`), JSON.stringify(result.plan, null, 2) + "\n");
    }
    if (tty && (done % 10 === 0 || done === total)) process.stderr.write(`\rplanned ${done}/${total}`);
  });
  if (tty) process.stderr.write("\n");
  planner.free();

  const table = variants.flatMap((v) => metricsTable(records, v));
  const kbName = relative(process.cwd(), kbPath) || kbPath;
  for (const v of variants) {
    const title = `${v === "modified" ? "With" : "Without"} tree modification — ${queries.length} queries, knowledge base ${kbName}`;
    process.stdout.write(formatTable(table.filter((r) => r.variant === v), title) + "\n");
  }
  const examples = cautionExamples(table);
  if (examples.length > 0) process.stdout.write(examples.join("\n") + "\n\n");

  const name = `eval-${variants.length === 2 ? "both" : variants[0]!}`;
  mkdirSync(out, { recursive: true });
  const results: EvalResults = { format: "foon-planner-eval", version: 1, knowledge_base: kbName, variants, table, records };
  writeFileSync(join(out, `${name}.json`), JSON.stringify(results, null, 2) + "\n");
  writeFileSync(join(out, `${name}-summary.csv`), summaryCsv(table));
  writeFileSync(join(out, `${name}-recipes.csv`), recipesCsv(records));
  process.stdout.write(`results: ${join(out, name)}.json, -summary.csv, -recipes.csv\n`);

  const broken = brokenInvariants(table);
  if (broken.length > 0) {
    const details = records.flatMap((r) => (r.ok ? r.metrics.violations.map((v) => `${r.variant} ${r.recipe.type}/${r.recipe.id}: ${v}`) : []));
    throw new Error(`structural invariants broken:\n  ${broken.join("\n  ")}\n${details.map((d) => `    ${d}`).join("\n")}`);
  }
}
