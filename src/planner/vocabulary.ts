// The query editor's vocabulary (dish classes with their recipes, object labels, states), read from the
// knowledge-base text itself. The WASM planner does not expose these lists; scanning the `O`/`S` lines is
// cheap and needs none of the reader's validation (the WASM loader has already accepted the same files).

import type { KnowledgeBaseFile, Vocabulary } from "./types";

/** Dish classes by index, as in public/kb/VOCABULARY.md (the plain dialect's 4th `O` field). */
export const DISH_CLASSES: readonly string[] = [
  "bread", "soup", "roast", "pizza", "sandwich", "cake", "pie", "sauce", "dessert", "drinks",
  "cookie", "meatball", "muffin", "pasta", "noodle", "salad", "burger", "seafood", "steak", "rice",
  "chicken", "casserole", "vegetables", "omelette", "potato", "beef", "pork", "stir-fry", "meatloaf", "sausage",
];

/** "s01-greek_salad.txt" -> "greek salad". */
export function titleFromFileName(name: string): string {
  return name
    .replace(/\.(txt|foon)$/i, "")
    .replace(/^[a-z]?\d+[-_]/i, "")
    .replace(/[-_]done$/i, "") // FOON-111 marks finished annotations so
    .replace(/_/g, " ")
    .trim();
}

interface Section {
  name: string;
  text: string;
}

/** Splits a bundle (`#@file <name>` lines) into its files; a plain file is one section. */
function sections(file: KnowledgeBaseFile): Section[] {
  const text = new TextDecoder().decode(file.bytes);
  const out: Section[] = [];
  let current: Section = { name: file.name, text: "" };
  const lines: string[] = [];
  for (const line of text.split(/\r?\n/)) {
    const marker = /^#@file\s+(.+)$/.exec(line);
    if (marker !== null) {
      if (lines.length > 0) out.push({ ...current, text: lines.join("\n") });
      lines.length = 0;
      current = { name: marker[1]!.trim(), text: "" };
    } else {
      lines.push(line);
    }
  }
  if (lines.length > 0) out.push({ ...current, text: lines.join("\n") });
  return out;
}

/** Collects labels, plain state names and, per dish class, the recipe titles of its goal nodes. */
export function scanVocabulary(files: readonly KnowledgeBaseFile[]): Vocabulary {
  const labels = new Set<string>();
  const states = new Set<string>();
  const recipes = new Map<string, Set<string>>();
  const titles: Record<string, string> = {};
  for (const file of files) {
    for (const section of sections(file)) {
      let title = titleFromFileName(section.name);
      for (const raw of section.text.split("\n")) {
        const line = raw.trimEnd();
        const titled = /^#\s*title:\s*(.+)$/i.exec(line);
        if (titled !== null) {
          title = titled[1]!.trim();
          titles[section.name] = title;
        }
        const fields = line.split("\t");
        if (fields[0] === "O" && fields[1] !== undefined) {
          const label = fields[1].trim().toLowerCase();
          if (label !== "") labels.add(label);
          const cls = fields[3] === undefined ? NaN : Number(fields[3]);
          const name = DISH_CLASSES[cls];
          if (name !== undefined) {
            const set = recipes.get(name) ?? new Set<string>();
            set.add(title);
            recipes.set(name, set);
          }
        } else if (fields[0] === "S" && fields[1] !== undefined) {
          const state = fields[1].trim().toLowerCase();
          // container and contents arguments ("in [bowl]", "contains {…}") are not states one asks for
          if (state !== "" && fields[2] === undefined && !/[[{]/.test(state)) states.add(state);
        }
      }
    }
  }
  const byName = (a: string, b: string): number => a.localeCompare(b);
  return {
    dishes: [...recipes.entries()]
      .map(([name, set]) => ({ name, recipes: [...set].sort(byName) }))
      .sort((a, b) => byName(a.name, b.name)),
    labels: [...labels].sort(byName),
    states: [...states].sort(byName),
    titles,
  };
}
