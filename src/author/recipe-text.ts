// Reading recipe text as cookbooks and recipe sites write it: a title, ingredient lines (quantities and
// units dropped: "2 cloves garlic, minced" -> garlic, minced) and numbered steps.

import table from "./draft-table.json";

export interface IngredientLine {
  /** The knowledge base's spelling: lower case, singular. */
  label: string;
  /** What the line says was done to it ("minced", "cut into cubes"), or "" (to-taste notes dropped). */
  prep: string;
  /** The line as written. */
  text: string;
}

export interface RecipeText {
  title: string;
  ingredients: IngredientLine[];
  steps: string[];
}

const MEASURES = new Set(table.measures);
const DROP = new Set(table.dropWords);
const HEADERS = /^(ingredients?|steps?|directions?|instructions?|method|preparation)\s*:?$/i;
const STEP_START = /^\s*(?:step\s*)?\d+\s*[.):]\s*/i;
const PARTICIPLE = /^(?!.*seed$)[a-z]{3,}ed$/;
const BULLET = /^\s*[-*•·]\s*/;
const QUANTITY = /^(?:\d+(?:[.,/]\d+)?|[½⅓⅔¼¾⅛]|\d+[½⅓⅔¼¾⅛]|to|-|–|x)$/i;

/** "tomatoes" -> "tomato", "leaves" -> "leaf", "berries" -> "berry"; words that end in s anyway stay. */
export function singular(word: string): string {
  if (/(ss|us|is)$/.test(word) || word.length <= 3) return word;
  if (word.endsWith("ies")) return `${word.slice(0, -3)}y`;
  if (word.endsWith("ves")) return `${word.slice(0, -3)}f`;
  if (/(oes|ches|shes|xes)$/.test(word)) return word.slice(0, -2);
  if (word.endsWith("s")) return word.slice(0, -1);
  return word;
}

/** An ingredient line's object and preparation; null when nothing is left of it. */
export function parseIngredientLine(text: string): IngredientLine | null {
  let plain = text.replace(BULLET, "").replace(/\([^)]*\)/g, " ").trim();
  for (const skip of table.skipPreps) plain = plain.replace(new RegExp(`,?\\s*${skip}\\b`, "i"), "");
  const comma = plain.indexOf(",");
  const head = comma === -1 ? plain : plain.slice(0, comma);
  let prep = comma === -1 ? "" : plain.slice(comma + 1).trim().toLowerCase();
  prep = prep.replace(/^(and|or)\s+/, "").replace(/[.;]+$/, "").trim();
  const words = head.toLowerCase().split(/\s+/).filter((w) => w !== "");
  // quantities and units lead; adjectives of size or quality anywhere go too
  let i = 0;
  while (i < words.length && (QUANTITY.test(words[i]!) || MEASURES.has(words[i]!.replace(/\.$/, "")))) i++;
  const kept = words.slice(i).filter((w) => !DROP.has(w) && !QUANTITY.test(w));
  // a participle before the name is its preparation ("2 minced garlic cloves", "1 chopped onion")
  while (kept.length > 1 && PARTICIPLE.test(kept[0]!)) prep = [kept.shift(), prep].filter((p) => p !== "").join(" ");
  const tail = kept.at(-1);
  if (tail === undefined) return null;
  // "garlic cloves": the unit came after the name
  if (kept.length > 1 && MEASURES.has(tail)) kept.pop();
  const label = [...kept.slice(0, -1), singular(kept.at(-1)!)].join(" ");
  return { label, prep, text: text.trim() };
}

function isHeader(line: string): boolean {
  return HEADERS.test(line.trim());
}

/** Splits recipe text into title, ingredient lines and steps (numbered, or the lines after a steps header). */
export function readRecipe(text: string): RecipeText {
  const lines = text.split(/\r?\n/).map((l) => l.trim()).filter((l) => l !== "");
  const title = lines.find((l) => !isHeader(l)) ?? "";
  let section: "ingredients" | "steps" | null = null;
  const ingredients: IngredientLine[] = [];
  const steps: string[] = [];
  for (const line of lines) {
    if (line === title) continue;
    if (isHeader(line)) {
      section = /^ingredient/i.test(line) ? "ingredients" : "steps";
      continue;
    }
    if (STEP_START.test(line) || section === "steps") {
      steps.push(line.replace(STEP_START, ""));
      continue;
    }
    const parsed = parseIngredientLine(line);
    if (parsed !== null) ingredients.push(parsed);
  }
  return { title, ingredients, steps };
}
