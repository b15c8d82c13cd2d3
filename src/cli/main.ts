// foon-planner command line: `npm run cli -- <command> [options]`. Every command goes through the same
// WASM build and planner module as the app.

import { parseArgs } from "node:util";
import { describeError } from "../planner/index";
import { loadPlannerFromDisk, STARTER_KB_DIR } from "../planner/node";
import { evalCommand } from "./eval";

const USAGE = `usage: npm run cli -- <command> [options]

commands:
  stats [--kb <dir-or-file>]      knowledge-base statistics as JSON (default: the starter knowledge base)
  eval --queries <dir> [--kb ...] metrics of the plans of many queries (see \`npm run eval -- --help\`)
`;

type Command = (args: string[]) => void;

const commands: Record<string, Command> = {
  eval: evalCommand,
  stats(args) {
    const { values } = parseArgs({ args, options: { kb: { type: "string" } }, strict: true });
    const planner = loadPlannerFromDisk(values.kb ?? STARTER_KB_DIR);
    for (const w of planner.warnings()) console.error(`warning: ${describeError(w)}`);
    console.log(JSON.stringify(planner.stats(), null, 2));
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
