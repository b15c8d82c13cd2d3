// Planner errors as data and as a class, without the WASM glue: the page imports these without
// pulling the WebAssembly module into its bundle (the worker owns it).

import type { ErrorCode, FoonErrorData } from "./types";

/** An error from the planner or the loader, with a stable `code` and, for file errors, a place. */
export class PlannerError extends Error implements FoonErrorData {
  readonly code: ErrorCode;
  readonly file?: string;
  readonly line?: number;
  readonly column?: number;
  /** The reason alone, without the place prefix of `message`. */
  readonly reason: string;

  constructor(data: FoonErrorData & { reason?: string }) {
    super(data.message);
    this.name = "PlannerError";
    this.code = data.code;
    this.file = data.file;
    this.line = data.line;
    this.column = data.column;
    this.reason = data.reason ?? data.message;
  }

  toJSON(): FoonErrorData {
    return { code: this.code, message: this.message, file: this.file, line: this.line, column: this.column };
  }
}

/** "file:line:column: reason" for an error or warning given as data. */
export function describeError(e: FoonErrorData): string {
  const place = [e.file, e.line, e.column].filter((part) => part !== undefined).join(":");
  // the core's messages already start with their place: never say it twice
  return place === "" || e.message.startsWith(`${place}:`) ? e.message : `${place}: ${e.message}`;
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === "object" && value !== null;
}

/** Turns whatever the WASM layer threw into a PlannerError. */
export function toPlannerError(thrown: unknown): PlannerError {
  if (thrown instanceof PlannerError) return thrown;
  if (isRecord(thrown) && typeof thrown.code === "string" && typeof thrown.message === "string") {
    return new PlannerError({
      code: thrown.code as ErrorCode,
      message: thrown.message,
      reason: typeof thrown.reason === "string" ? thrown.reason : undefined,
      file: typeof thrown.file === "string" ? thrown.file : undefined,
      line: typeof thrown.line === "number" ? thrown.line : undefined,
      column: typeof thrown.column === "number" ? thrown.column : undefined,
    });
  }
  const message = thrown instanceof Error ? thrown.message : String(thrown);
  return new PlannerError({ code: "internal", message: `planner failure: ${message}` });
}

