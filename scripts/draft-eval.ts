// `npm run eval:draft`: how many of the units a person wrote for each recipe the drafter gets right unaided,
// on the 20 recipes it was developed with (tests/data/author-recipes) and on 10 written after it was frozen
// (tests/data/author-recipes-heldout); docs/authoring.md. `--verbose` lists the missed and extra units.
import { join } from "node:path";
import { connectedDrafts, DRAFT_FIXTURES, evaluateDrafts, readDraftFixtures } from "../src/author/draft-eval";
import { ROOT } from "../src/planner/node";

const verbose = process.argv.includes("--verbose");
const pct = (a: number, b: number): string => `${((100 * a) / Math.max(1, b)).toFixed(1)} %`;

async function report(title: string, dir: string): Promise<void> {
  const { results, right, expected, drafted } = evaluateDrafts(readDraftFixtures(dir));
  console.log(`\n## ${title}\n\n| recipe | units right / written | drafted |\n| --- | --- | --- |`);
  for (const r of results) {
    console.log(`| ${r.name} | ${r.score.right} / ${r.score.expected} | ${r.score.drafted} |`);
    if (verbose) for (const line of [...r.score.missed.map((m) => `missed: ${m}`), ...r.score.extra.map((e) => `extra:  ${e}`)]) console.log(`    ${line}`);
  }
  const connected = await connectedDrafts(results);
  console.log(`\nunits right unaided: ${right} of ${expected} (${pct(right, expected)}); precision ${right} of ${drafted} drafted (${pct(right, drafted)})`);
  console.log(`drafts whose every unit the planner retrieves from the goal node: ${connected.length} of ${results.length}`);
}

await report("Development set (20 recipes)", DRAFT_FIXTURES);
await report("Held-out set (10 recipes, written after the drafter was frozen)", join(ROOT, "tests/data/author-recipes-heldout"));
