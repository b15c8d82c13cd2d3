// Writes the builder-made starter recipes into public/kb/starter/ (`npm run build:starter`); with --check
// it only reports the files that differ from what the recipes in scripts/starter/recipes/ make.
import { readFileSync, writeFileSync, existsSync } from "node:fs";
import { join } from "node:path";
import { STARTER_KB_DIR } from "../../src/planner/node";
import { allRecipes } from "./recipes/index";

const check = process.argv.includes("--check");
let stale = 0;
for (const r of allRecipes()) {
  const path = join(STARTER_KB_DIR, r.file);
  const same = existsSync(path) && readFileSync(path, "utf8") === r.text;
  if (same) continue;
  stale++;
  if (check) console.error(`out of date: ${path}`);
  else writeFileSync(path, r.text);
}
console.log(`${allRecipes().length} builder recipes, ${stale} ${check ? "out of date" : "written"}`);
if (check && stale > 0) process.exit(1);
