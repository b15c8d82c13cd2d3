// The bad-input corpus (tests/data/bad-inputs/expected.tsv) through the WASM build: every file gives exactly
// the error (stable code, file, line, column, message), the first warning, or the load figures the manifest
// says — the same rows wasm/core/tests/bad_inputs.rs checks natively, so both sides of the boundary agree.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { beforeAll, describe, expect, it } from "vitest";
import { FoonPlanner, PlannerError, type FoonErrorData } from "../../src/planner/index";
import { initPlannerFromDisk, ROOT } from "../../src/planner/node";

const CORPUS = join(ROOT, "tests/data/bad-inputs");

// limits.rs, repeated here so that a change of a limit is a visible change of this test too
const MAX_FILE_BYTES = 32 * 1024 * 1024;
const MAX_LINE_BYTES = 64 * 1024;
const MAX_LABEL_CHARS = 200;
const MAX_UNITS = 1_000_000;

const GOOD = "//\nO\ttomato\t1\nS\twhole\nO\tknife\t0\nS\tclean\nM\tslice\t<0:10,0:20>\nO\ttomato\t1\nS\tsliced\n//\n";

/** Bytes of a generated case: the same recipes as `generated` in wasm/core/tests/bad_inputs.rs. */
function generatedCase(name: string): Uint8Array {
  const text = (s: string) => new TextEncoder().encode(s);
  switch (name) {
    case "@line-10mb":
      return text(`${GOOD}O\t${"x".repeat(10 * 1024 * 1024)}\t1\n`);
    case "@file-over-limit":
      return new Uint8Array(MAX_FILE_BYTES + 1).fill(0x23);
    case "@line-over-limit":
      return text(`O\t${"x".repeat(MAX_LINE_BYTES - 1)}\n`);
    case "@line-at-limit":
      return text(`O\t${"x".repeat(MAX_LINE_BYTES - 2)}\n`);
    case "@label-at-limit":
      return text(`O\t${"x".repeat(MAX_LABEL_CHARS)}\t1\nM\tcut\nO\tb\t1\n`);
    case "@units-over-limit":
      return text("O\ta\nM\tc\nO\tb\n//\n".repeat(MAX_UNITS + 1));
    case "@bundle-units-over-limit": {
      const part = "O\ta\nM\tc\nO\tb\n//\n".repeat(MAX_UNITS / 2 + 1);
      return text(`#@file a.txt\n${part}#@file b.txt\n${part}`);
    }
    case "@many-fields":
      return text(`O\ta${"\tx".repeat(30_000)}\n`);
    case "@wide-unit": {
      const lines: string[] = [];
      for (let i = 0; i < 20_000; i++) lines.push(`O\tin${i}\t1`);
      lines.push("M\tmix");
      for (let i = 0; i < 20_000; i++) lines.push(`O\tout${i}\t1`);
      lines.push("O\tout0\t1", "M\tserve", "O\tdish\t1", "");
      return text(lines.join("\n"));
    }
    default:
      throw new Error(`unknown generated case ${name}`);
  }
}

interface Row {
  file: string;
  outcome: "error" | "warning" | "ok";
  code: string;
  where: string;
  detail: string;
}

const rows: Row[] = readFileSync(join(CORPUS, "expected.tsv"), "utf8")
  .split("\n")
  .filter((line) => line.trim() !== "" && !line.startsWith("#"))
  .map((line) => {
    const [file, outcome, code, where, detail] = line.split("\t");
    return { file, outcome: outcome as Row["outcome"], code, where, detail };
  });

function place(e: FoonErrorData): string {
  const parts = [e.file ?? "", ...(e.line === undefined ? [] : [String(e.line)]), ...(e.column === undefined ? [] : [String(e.column)])];
  const text = parts.join(":");
  return text === "" ? "-" : text;
}

beforeAll(() => initPlannerFromDisk());

describe("the bad-input corpus through WASM", () => {
  it("has rows for every outcome and every reader error code", () => {
    expect(rows.length).toBeGreaterThan(60);
    const codes = new Set(rows.map((r) => r.code));
    for (const code of [
      "invalid_utf8", "too_large", "unknown_line", "missing_field", "bad_number", "empty_label", "bad_brackets",
      "state_without_object", "bad_motion", "motion_without_inputs", "unit_without_outputs", "empty_knowledge_base",
    ]) {
      expect(codes, code).toContain(code);
    }
  });

  it.each(rows.map((r) => [r.file, r] as const))("%s", (_name, row) => {
    const bytes = row.file.startsWith("@") ? generatedCase(row.file) : new Uint8Array(readFileSync(join(CORPUS, row.file)));
    let planner: FoonPlanner | undefined;
    let error: unknown;
    try {
      planner = FoonPlanner.load([{ name: row.file, bytes }]);
    } catch (e) {
      error = e;
    }
    if (row.outcome === "error") {
      expect(planner).toBeUndefined();
      expect(error).toBeInstanceOf(PlannerError);
      const e = error as PlannerError;
      expect([e.code, place(e), e.reason]).toEqual([row.code, row.where, row.detail]);
      // the message is the Display form of the core error: "file:line:column: reason (code)"
      const prefix = row.where === "-" ? "" : `${row.where}: `;
      expect(e.message).toBe(`${prefix}${row.detail} (${row.code})`);
      return;
    }
    expect(error).toBeUndefined();
    const p = planner!;
    const warnings = p.warnings();
    if (row.outcome === "warning") {
      expect([warnings[0]?.code, place(warnings[0]), warnings[0]?.message]).toEqual([row.code, row.where, row.detail]);
    } else {
      const stats = p.stats();
      expect(warnings).toEqual([]);
      expect(`units=${stats.units} goals=${stats.goal_nodes} warnings=${stats.warnings}`).toBe(row.detail);
    }
    p.free();
  }, 60_000);

  it("keeps working after every error (the module survives)", () => {
    const p = FoonPlanner.load([{ name: "ok.txt", bytes: new TextEncoder().encode(GOOD) }]);
    expect(p.stats().units).toBe(1);
    p.free();
  });
});
