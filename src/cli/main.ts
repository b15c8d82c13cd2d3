// foon-planner command line: `npm run cli -- <command> [options]`. Every command goes through the same
// WASM build and planner module as the app.

import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { parseArgs } from "node:util";
import { describeError, PlannerError, type FoonPlanner } from "../planner/index";
import { loadPlannerFromDisk, STARTER_KB_DIR } from "../planner/node";
import { RETRIEVAL_MODES, type ExportFormat, type PlanRequest, type RetrievalMode, type RobotOptions } from "../planner/types";
import { evalCommand } from "./eval";
import { readQueries, readQuery } from "./queries";

const USAGE = `usage: npm run cli -- <command> [options]

commands:
  stats   [--kb <dir-or-file>]                       knowledge-base statistics as JSON
  plan    [--kb <dir-or-file>] --query <file.json>   one plan as JSON
          [--no-modify] [--override <object>=<label>]... [--format json|foon|pddl|pddl-domain|pddl-problem|progress]
          [--explain]                                adds the trace: how the plan was found (JSON only)
          [--mode heuristic|fewest_units|lowest_cost|most_reliable] [--human-steps <M>]
          [--motion-cost <motion>=<cost>]... [--success-rate <motion>=<rate>]...
                                                     retrieval mode and robot figures (docs/robot.md)
  batch   [--kb <dir>] --queries <dir> --out <dir> [--no-modify] [--mode ...] [--human-steps <M>]
                                                     plans every query, writes <out>/<type>/<id>.json
  similar [--kb <dir>] [--top 5] [--names <file>] <name>...
                                                     the equivalents the planner would use, best first
  eval    [--kb <dir>] --queries <dir> [--no-modify | --both] [--out <dir>]
                                                     metrics of every query's plan (npm run eval -- --help)

--kb defaults to the project's starter knowledge base (public/kb/starter); it takes a folder of FOON
.txt files, a single file or a bundle. --exact plans with exact name matching (no embedding table).
`;

const KB_OPTIONS = { kb: { type: "string" }, exact: { type: "boolean" } } as const;

function planner(values: { kb?: string; exact?: boolean }): FoonPlanner {
  const p = loadPlannerFromDisk(values.kb ?? STARTER_KB_DIR, { exact: values.exact });
  for (const w of p.warnings()) process.stderr.write(`warning: ${describeError(w)}\n`);
  return p;
}

/** `name=value` pairs of a repeated option, e.g. `--override "cool whip=whipped cream"`. */
function pairs(option: string, list: string[] | undefined, shape: string): Record<string, string> {
  const out: Record<string, string> = {};
  for (const item of list ?? []) {
    const at = item.indexOf("=");
    if (at <= 0) throw new Error(`--${option} '${item}': expected ${shape}`);
    out[item.slice(0, at).trim()] = item.slice(at + 1).trim();
  }
  return out;
}

function numbers(option: string, list: string[] | undefined): Record<string, number> {
  const out: Record<string, number> = {};
  for (const [motion, text] of Object.entries(pairs(option, list, "<motion>=<number>"))) {
    const value = Number(text);
    if (text === "" || !Number.isFinite(value)) throw new Error(`--${option} '${motion}=${text}': not a number`);
    out[motion] = value;
  }
  return out;
}

const ROBOT_OPTIONS = {
  mode: { type: "string" },
  "human-steps": { type: "string" },
  "motion-cost": { type: "string", multiple: true },
  "success-rate": { type: "string", multiple: true },
} as const;

/** The request's `robot` from --mode and the figures, or undefined when none is given (the default plan). */
function robotOptions(values: { mode?: string; "human-steps"?: string; "motion-cost"?: string[]; "success-rate"?: string[] }): RobotOptions | undefined {
  const given = [values.mode, values["human-steps"], values["motion-cost"], values["success-rate"]].some((v) => v !== undefined);
  if (!given) return undefined;
  const mode = (values.mode ?? "heuristic") as RetrievalMode;
  if (!RETRIEVAL_MODES.includes(mode)) throw new Error(`--mode must be one of ${RETRIEVAL_MODES.join(", ")}`);
  const humanSteps = Number(values["human-steps"] ?? "0");
  if (!Number.isInteger(humanSteps) || humanSteps < 0) throw new Error("--human-steps must be a whole number, 0 or more");
  return {
    mode,
    motion_costs: numbers("motion-cost", values["motion-cost"]),
    success_rates: numbers("success-rate", values["success-rate"]),
    human_steps: humanSteps,
  };
}

const FORMATS: readonly ExportFormat[] = ["json", "foon", "pddl", "pddl-domain", "pddl-problem", "progress"];

function progressBar(done: number, total: number, errors: number): string {
  const width = 30;
  const filled = Math.round((done / Math.max(total, 1)) * width);
  return `\r[${"#".repeat(filled)}${".".repeat(width - filled)}] ${done}/${total}  errors: ${errors}`;
}

const commands: Record<string, (args: string[]) => void> = {
  eval: evalCommand,
  stats(args) {
    const { values } = parseArgs({ args, options: KB_OPTIONS, strict: true });
    console.log(JSON.stringify(planner(values).stats(), null, 2));
  },

  plan(args) {
    const { values } = parseArgs({
      args,
      options: {
        ...KB_OPTIONS,
        query: { type: "string" },
        "no-modify": { type: "boolean" },
        override: { type: "string", multiple: true },
        format: { type: "string", default: "json" },
        explain: { type: "boolean" },
        ...ROBOT_OPTIONS,
      },
      strict: true,
    });
    if (values.query === undefined) throw new Error("plan needs --query <file.json>");
    const format = values.format as ExportFormat;
    if (!FORMATS.includes(format)) throw new Error(`--format must be one of ${FORMATS.join(", ")}`);
    const explain = values.explain === true;
    if (explain && format !== "json") throw new Error("--explain adds the trace to the plan JSON: it needs --format json");
    const request: PlanRequest = {
      query: readQuery(values.query),
      modify: values["no-modify"] !== true,
      overrides: pairs("override", values.override, "<object>=<label>"),
      explain,
      robot: robotOptions(values),
    };
    const p = planner(values);
    if (format === "json") console.log(JSON.stringify(p.plan(request), null, 2));
    else process.stdout.write(p.exportPlan(request, format));
  },

  batch(args) {
    const { values } = parseArgs({
      args,
      options: { ...KB_OPTIONS, queries: { type: "string" }, out: { type: "string" }, "no-modify": { type: "boolean" }, ...ROBOT_OPTIONS },
      strict: true,
    });
    if (values.queries === undefined || values.out === undefined) throw new Error("batch needs --queries <dir> and --out <dir>");
    const queries = readQueries(values.queries);
    const p = planner(values);
    const modify = values["no-modify"] !== true;
    const robot = robotOptions(values);
    const errors: Record<string, number> = {};
    const times: number[] = [];
    const tty = process.stderr.isTTY === true;
    queries.forEach((q, i) => {
      const started = performance.now();
      let result: unknown;
      try {
        result = p.plan({ query: q.query, modify, robot });
      } catch (e) {
        if (!(e instanceof PlannerError)) throw e;
        errors[e.code] = (errors[e.code] ?? 0) + 1;
        result = { format_version: 1, query: q.query, error: e.toJSON() };
      }
      times.push(performance.now() - started);
      const out = join(values.out as string, q.source);
      mkdirSync(dirname(out), { recursive: true });
      writeFileSync(out, `${JSON.stringify(result, null, 2)}\n`);
      const failed = Object.values(errors).reduce((a, b) => a + b, 0);
      if (tty || i + 1 === queries.length || (i + 1) % 50 === 0) process.stderr.write(progressBar(i + 1, queries.length, failed));
    });
    process.stderr.write("\n");
    const failed = Object.values(errors).reduce((a, b) => a + b, 0);
    const sorted = [...times].sort((a, b) => a - b);
    const summary = {
      queries: queries.length,
      planned: queries.length - failed,
      errors,
      modify,
      out: values.out,
      plan_ms: { median: sorted[Math.floor(sorted.length / 2)] ?? 0, max: sorted[sorted.length - 1] ?? 0 },
    };
    console.log(JSON.stringify(summary, null, 2));
  },

  similar(args) {
    const { values, positionals } = parseArgs({
      args,
      options: { ...KB_OPTIONS, top: { type: "string", default: "5" }, names: { type: "string" } },
      allowPositionals: true,
      strict: true,
    });
    const top = Number(values.top);
    if (!Number.isInteger(top) || top < 1) throw new Error("--top must be a positive whole number");
    const fromFile = values.names === undefined ? [] : readFileSync(values.names, "utf8").split(/\r?\n/).map((l) => l.trim());
    const names = [...positionals, ...fromFile].filter((n) => n !== "");
    if (names.length === 0) throw new Error("similar needs at least one name (or --names <file>)");
    console.log(JSON.stringify(planner(values).similar(names, top), null, 2));
  },
};

function main(argv: string[]): number {
  const [name, ...rest] = argv;
  if (name === undefined || name === "help" || name === "--help") {
    process.stdout.write(USAGE);
    return name === undefined ? 2 : 0;
  }
  const command = commands[name];
  if (command === undefined) {
    process.stderr.write(`unknown command '${name}'\n${USAGE}`);
    return 2;
  }
  try {
    command(rest);
    return 0;
  } catch (e) {
    process.stderr.write(`error: ${e instanceof Error ? e.message : String(e)}\n`);
    return 1;
  }
}

process.exitCode = main(process.argv.slice(2));
