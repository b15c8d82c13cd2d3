// What the FOON editor tells its user about the text, from the WASM reader itself: the error with its line,
// column and reason, the warnings, the drafter's marks, and the preview of the reference task tree.
import { describe, expect, it } from "vitest";
import { checkText } from "../../src/author/check";
import { localPlanner } from "../../src/author/draft-eval";

const TOAST = ["# title: Toast", "//", "O\tbread\t1", "S\tsliced", "O\ttoaster\t0", "M\ttoast\t<Assumed>", "O\ttoast\t1\t0", "S\ttoasted", "S\tcontains\t{bread}", ""].join("\n");

describe("checking the authored text", () => {
  it("previews a correct subgraph as the planner retrieves it, with its steps", async () => {
    const result = await checkText(localPlanner(), "toast.txt", TOAST);
    expect(result.diagnostics).toEqual([]);
    expect(result.preview?.units.map((u) => u.motion)).toEqual(["toast"]);
    expect(result.preview?.goal.label).toBe("toast");
    expect(result.preview?.steps).toHaveLength(1);
  });

  it("reports the reader's error with line, column and reason, and no preview", async () => {
    const broken = TOAST.replace("O\tbread\t1", "O\tbread\tone");
    const result = await checkText(localPlanner(), "toast.txt", broken);
    expect(result.preview).toBeNull();
    expect(result.diagnostics).toHaveLength(1);
    const [error] = result.diagnostics;
    expect(error).toMatchObject({ severity: "error", line: 3, column: 9 });
    expect(error!.reason).toBe("object flag must be 0 or 1, found 'one'");
    expect(error!.reason).not.toMatch(/toast\.txt:3/); // the place is shown once, by the editor
  });

  it("says when there is no goal node yet, and lists the marks to confirm with their lines", async () => {
    const noGoal = TOAST.replace("O\ttoast\t1\t0", "O\ttoast\t1").replace("//", "# confirm: is it toasted?\n//");
    const result = await checkText(localPlanner(), "toast.txt", noGoal);
    expect(result.preview).toBeNull();
    expect(result.diagnostics.map((d) => [d.severity, d.line])).toEqual([
      ["confirm", 2],
      ["warning", null],
    ]);
    expect(result.diagnostics[1]!.reason).toMatch(/no goal node/);
  });

  it("warns about units the planner never reaches from the goal", async () => {
    const extra = `${TOAST}//\nO\tbanana\t1\nS\twhole\nO\tknife\t1\nM\tslice\t<Assumed>\nO\tbanana\t1\nS\tsliced\n`;
    const result = await checkText(localPlanner(), "toast.txt", extra);
    expect(result.diagnostics.map((d) => d.reason)).toEqual(["1 of 2 functional units are not on the way to the goal node: the planner never retrieves them"]);
  });
});
