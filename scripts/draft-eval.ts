// `npm run eval:draft`: how many of the units people wrote for 20 recipes the drafter gets right unaided
// (tests/data/author-recipes; docs/authoring.md). `--verbose` lists the missed and extra units.
import { connectedDrafts, evaluateDrafts, readDraftFixtures } from "../src/author/draft-eval";

const verbose = process.argv.includes("--verbose");
const { results, right, expected, drafted } = evaluateDrafts(readDraftFixtures());
const pct = (a: number, b: number): string => `${((100 * a) / Math.max(1, b)).toFixed(1)} %`;
console.log("| recipe | units right / written | drafted |");
console.log("| --- | --- | --- |");
for (const r of results) {
  console.log(`| ${r.name} | ${r.score.right} / ${r.score.expected} | ${r.score.drafted} |`);
  if (verbose) {
    for (const m of r.score.missed) console.log(`    missed: ${m}`);
    for (const e of r.score.extra) console.log(`    extra:  ${e}`);
  }
}
console.log(`\nunits right unaided: ${right} of ${expected} (${pct(right, expected)}); precision ${right} of ${drafted} drafted (${pct(right, drafted)})`);
const connected = await connectedDrafts(results);
console.log(`drafts whose every unit the planner retrieves from the goal node: ${connected.length} of ${results.length}`);
