// The editor's view of FOON text line by line: what each line is (object, state, motion, separator,
// comment, a mark for the user to confirm) and its tab-separated fields, for colouring and completion.
// It never judges a line: the WASM reader does (errors with line, column and reason).

export type LineKind = "object" | "state" | "motion" | "separator" | "comment" | "confirm" | "blank" | "other";

/** The comment the drafter writes above whatever it was unsure of. */
export const CONFIRM_PREFIX = "# confirm:";

export interface LineToken {
  text: string;
  /** "keyword" is the line's first field; "name" the label, state or motion; "arg" the rest. */
  role: "keyword" | "name" | "arg" | "comment" | "tab";
}

export function lineKind(line: string): LineKind {
  const trimmed = line.trim();
  if (trimmed === "") return "blank";
  if (trimmed.startsWith(CONFIRM_PREFIX)) return "confirm";
  if (trimmed.startsWith("#")) return "comment";
  if (trimmed.startsWith("//")) return "separator";
  const head = line.split("\t", 1)[0] ?? "";
  if (/^O\d*$/.test(head)) return "object";
  if (/^S\d*$/.test(head)) return "state";
  if (/^M\d*$/.test(head)) return "motion";
  return "other";
}

/** A line split into coloured parts; joined, the parts are the line exactly. */
export function tokenizeLine(line: string): LineToken[] {
  const kind = lineKind(line);
  if (kind === "comment" || kind === "confirm" || kind === "separator" || kind === "blank" || kind === "other") {
    return line === "" ? [] : [{ text: line, role: kind === "other" ? "arg" : "comment" }];
  }
  const tokens: LineToken[] = [];
  line.split("\t").forEach((field, i) => {
    if (i > 0) tokens.push({ text: "\t", role: "tab" });
    if (field !== "") tokens.push({ text: field, role: i === 0 ? "keyword" : i === 1 ? "name" : "arg" });
  });
  return tokens;
}

/** The motion names of FOON text (its `M` lines), sorted and unique: the knowledge base's motions. */
export function motionsOf(text: string): string[] {
  const motions = new Set<string>();
  for (const line of text.split(/\r?\n/)) {
    if (lineKind(line) !== "motion") continue;
    const name = line.split("\t")[1]?.trim();
    if (name !== undefined && name !== "") motions.add(name);
  }
  return [...motions].sort();
}
