// Every error path of the planner's JavaScript API through the WASM build, each with its stable code and
// message: plan requests with wrong JSON types or over the limits, unknown export formats, name lists,
// damaged embedding tables, knowledge bases without goals, values JSON cannot carry. After each error the
// module still plans. (Reader errors: errors-corpus.test.ts; before initialisation: not-initialised.test.ts.)
import { beforeAll, describe, expect, it } from "vitest";
import { FoonPlanner, PlannerError, toPlannerError, type ErrorCode, type PlanRequest } from "../../src/planner/index";
import { initPlannerFromDisk, loadPlannerFromDisk } from "../../src/planner/node";
import { encode } from "./helpers";

let planner: FoonPlanner;

beforeAll(() => {
  initPlannerFromDisk();
  planner = loadPlannerFromDisk();
});

const SALAD: PlanRequest = {
  query: { type: "salad", ingredients: [{ object: "tomato", state: "sliced" }, { object: "cucumber", state: "chopped" }] },
};

function thrownBy(call: () => unknown): PlannerError {
  try {
    call();
  } catch (e) {
    expect(e).toBeInstanceOf(PlannerError);
    return e as PlannerError;
  }
  throw new Error("expected a PlannerError");
}

/** Code, reason, line and column of the error a raw (possibly ill-typed) request gives. */
function planError(request: unknown): [ErrorCode, string, number | undefined, number | undefined] {
  const e = thrownBy(() => planner.plan(request as PlanRequest));
  // the message is the reason followed by the code, as every core error is shown
  expect(e.message).toBe(`${e.reason} (${e.code})`);
  return [e.code, e.reason, e.line, e.column];
}

const query = (ingredients: unknown, type: unknown = "salad") => ({ query: { type, ingredients } });

describe("plan requests with wrong JSON types", () => {
  it.each([
    ["ingredients is a string", query("tomato"), "plan request: invalid type: string \"tomato\", expected a sequence at line 1 column 47", 1, 47],
    ["query is a number", { query: 7 }, "plan request: invalid type: integer `7`, expected struct Query at line 1 column 10", 1, 10],
    ["no query", { modify: true }, "plan request: missing field `query` at line 1 column 15", 1, 15],
    ["type is a number", query([{ object: "tomato", state: "" }], 15), "plan request: invalid type: integer `15`, expected a string at line 1 column 19", 1, 19],
    ["object is an array", query([{ object: ["tomato"], state: "" }]), "plan request: invalid type: sequence, expected a string at line 1 column 50", 1, 50],
    ["state is null", query([{ object: "tomato", state: null }]), "plan request: invalid type: null, expected a string at line 1 column 71", 1, 71],
    ["modify is a string", { ...SALAD, modify: "yes" }, "plan request: invalid type: string \"yes\", expected a boolean at line 1 column 133", 1, 133],
    ["overrides is a list", { ...SALAD, overrides: ["a"] }, "plan request: invalid type: sequence, expected a map at line 1 column 131", 1, 131],
    ["the request is a string", "salad", "plan request: invalid type: string \"salad\", expected struct PlanRequest at line 1 column 7", 1, 7],
    ["the request is null", null, "plan request: invalid type: null, expected struct PlanRequest at line 1 column 4", 1, 4],
  ])("%s: bad_query with the JSON place", (_what, request, reason, line, column) => {
    expect(planError(request)).toEqual(["bad_query", reason, line, column]);
  });

  it("values JSON cannot carry are bad queries too, before the WASM call", () => {
    const cyclic: Record<string, unknown> = { query: { type: "salad", ingredients: [] } };
    cyclic.self = cyclic;
    expect(planError(cyclic)[0]).toBe("bad_query");
    expect(planError({ query: { type: "salad", ingredients: [{ object: 1n, state: "" }] } })[0]).toBe("bad_query");
    expect(planError(undefined)).toEqual(["bad_query", "plan request: not a JSON value", undefined, undefined]);
  });
});

describe("plan requests the planner rejects", () => {
  const long = "x".repeat(201);
  it.each([
    ["no ingredients", query([]), "bad_query", "the query has no ingredients"],
    ["201 ingredients", query(Array.from({ length: 201 }, (_, i) => ({ object: `food ${i}`, state: "" }))), "too_large", "the query has 201 ingredients; the limit is 200"],
    ["a 201-character object", query([{ object: long, state: "" }]), "bad_query", "ingredient 1 object is longer than 200 characters"],
    ["a 201-character state", query([{ object: "tomato", state: long }]), "bad_query", "ingredient 1 state is longer than 200 characters"],
    ["a 201-character dish type", query([{ object: "tomato", state: "" }], long), "bad_query", "the dish type is longer than 200 characters"],
    ["an empty object", query([{ object: "  _ ", state: "" }]), "bad_query", "ingredient 1 has an empty object name"],
    ["brackets in an object", query([{ object: "tomato [red]", state: "" }]), "bad_query", "ingredient 1 ('tomato [red]') has a character not allowed in a FOON label"],
    ["a comma in a state", query([{ object: "tomato", state: "sliced, diced" }]), "bad_query", "ingredient 1 state ('sliced, diced') has a character not allowed in a FOON state"],
    ["an empty override", { ...SALAD, overrides: { tomato: " " } }, "bad_query", "an override has an empty name"],
    ["a request over 1 MiB", { ...SALAD, padding: "x".repeat(1024 * 1024) }, "too_large", `plan request is ${1024 * 1024 + 132} bytes of JSON; the limit is 1048576 bytes`],
  ])("%s", (_what, request, code, reason) => {
    const [gotCode, gotReason] = planError(request);
    expect([gotCode, gotReason]).toEqual([code, reason]);
  });

  it("a knowledge base without goal nodes: no_goal", () => {
    const p = FoonPlanner.load([{ name: "nogoal.txt", bytes: encode("O\ttomato\t1\nS\twhole\nM\tslice\nO\ttomato\t1\nS\tsliced\n") }]);
    const e = thrownBy(() => p.plan(SALAD));
    expect([e.code, e.reason]).toEqual(["no_goal", "the knowledge base has no goal node with a functional unit that makes it"]);
    p.free();
  });
});

describe("other calls", () => {
  it("an unknown export format: bad_query", () => {
    const e = thrownBy(() => planner.exportPlan(SALAD, "docx" as never));
    expect([e.code, e.reason]).toEqual(["bad_query", "unknown export format 'docx' (json, foon, pddl, pddl-domain, pddl-problem, progress)"]);
  });

  it("name lists of the wrong type or size", () => {
    const wrong = thrownBy(() => planner.similar([1, "tomato"] as never));
    expect([wrong.code, wrong.reason]).toEqual(["bad_query", "names (a JSON array of strings): invalid type: integer `1`, expected a string at line 1 column 2"]);
    const many = thrownBy(() => planner.similar(Array.from({ length: 201 }, () => "tomato")));
    expect([many.code, many.reason]).toEqual(["too_large", "201 names; the limit is 200"]);
    // odd `top` values are clamped by the binding, never a trap
    expect(planner.similar(["tomato"], -1)[0].candidates.length).toBeGreaterThan(0);
    expect(planner.similar(["tomato"], Number.NaN)[0].candidates).toEqual([]);
  });

  it("a damaged embedding table: bad_embeddings", () => {
    const e = thrownBy(() => FoonPlanner.load([{ name: "kb.txt", bytes: encode("O\ta\t1\nM\tcut\nO\ta\t1\nS\tcut\n") }], new Uint8Array([1, 2, 3])));
    expect([e.code, e.reason]).toEqual(["bad_embeddings", "not a foon-planner embedding table (bad magic)"]);
  });

  it("a trap or a foreign throw becomes an internal PlannerError", () => {
    const e = toPlannerError(new WebAssembly.RuntimeError("unreachable"));
    expect([e.code, e.message]).toEqual(["internal", "planner failure: unreachable"]);
    expect(toPlannerError("boom").code).toBe("internal");
  });

  it("still plans after all of these", () => {
    const plan = planner.plan(SALAD);
    expect(plan.units.length).toBeGreaterThan(0);
    expect(plan.steps.length).toBe(plan.units.length);
  });
});

describe("every stable error code has a test", () => {
  // Record<ErrorCode, …>: adding a code to the union without saying where it is tested fails `tsc`.
  const testedIn: Record<ErrorCode, string> = {
    invalid_utf8: "errors-corpus",
    too_large: "errors-corpus, errors-requests",
    unknown_line: "errors-corpus",
    missing_field: "errors-corpus",
    bad_number: "errors-corpus",
    empty_label: "errors-corpus",
    bad_brackets: "errors-corpus",
    state_without_object: "errors-corpus",
    bad_motion: "errors-corpus",
    motion_without_inputs: "errors-corpus",
    unit_without_outputs: "errors-corpus",
    empty_knowledge_base: "errors-corpus",
    bad_query: "errors-requests",
    bad_embeddings: "errors-requests",
    no_goal: "errors-requests",
    not_initialised: "not-initialised",
    unsupported: "not-initialised",
    internal: "errors-requests",
  };
  it("lists them all", () => {
    expect(Object.keys(testedIn).length).toBe(18);
  });
});
