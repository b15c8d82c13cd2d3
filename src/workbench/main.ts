// The evaluation workbench page: batch mode, rating mode and threshold curves (section IV of the
// paper), with ratings kept in IndexedDB.

import { parseRatingsFile, ratingsToCsv, ratingsToJson, type Rating } from "../eval/ratings";
import { BatchView } from "./batch-view";
import { CurvesView } from "./curves-view";
import { byId, download, timestamp } from "./dom";
import { RateView } from "./rate-view";
import { Workbench } from "./state";

type Tab = "batch" | "rate" | "curves";
const TABS: readonly Tab[] = ["batch", "rate", "curves"];

function currentTab(): Tab {
  const hash = location.hash.replace(/^#/, "");
  return (TABS as readonly string[]).includes(hash) ? (hash as Tab) : "batch";
}

function exportRatings(bench: Workbench, format: "json" | "csv"): void {
  const ratings = bench.allRatings();
  if (format === "json") download(`ratings-${timestamp()}.json`, ratingsToJson(ratings, new Date()), "application/json");
  else download(`ratings-${timestamp()}.csv`, ratingsToCsv(ratings), "text/csv");
}

async function start(): Promise<void> {
  const bench = await Workbench.open();
  const show = (tab: Tab): void => {
    for (const t of TABS) {
      byId(`${t}-view`, HTMLElement).hidden = t !== tab;
      byId(`tab-${t}`, HTMLAnchorElement).setAttribute("aria-current", t === tab ? "page" : "false");
    }
    render();
  };
  const rateView = new RateView(bench, () => currentTab() === "rate");
  const curvesView = new CurvesView(bench);
  const batchView = new BatchView(bench, (key) => {
    void rateView.open(key).then(() => {
      location.hash = "rate";
    });
  });

  const rater = byId("rater", HTMLInputElement);
  const blind = byId("blind", HTMLInputElement);
  rater.value = bench.settings.rater;
  blind.checked = bench.settings.blind;
  rater.addEventListener("change", () => {
    const name = rater.value.trim();
    if (name === "") rater.value = bench.settings.rater;
    else void bench.saveSettings({ rater: name });
  });
  blind.addEventListener("change", () => void bench.saveSettings({ blind: blind.checked }));

  for (const format of ["json", "csv"] as const) {
    byId(`export-ratings-${format}`, HTMLButtonElement).addEventListener("click", () => exportRatings(bench, format));
    byId(`notice-export-${format}`, HTMLButtonElement).addEventListener("click", () => exportRatings(bench, format));
  }
  const importInput = byId("import-ratings", HTMLInputElement);
  importInput.addEventListener("change", () => {
    const files = [...(importInput.files ?? [])];
    importInput.value = "";
    void (async () => {
      const report = byId("import-report", HTMLElement);
      const incoming: Rating[] = [];
      try {
        for (const f of files) incoming.push(...parseRatingsFile(f.name, await f.text()));
      } catch (e) {
        report.textContent = `Nothing imported: ${e instanceof Error ? e.message : String(e)}`;
        report.dataset.state = "error";
        return;
      }
      const merged = await bench.importRatings(incoming);
      report.textContent = `Imported ${incoming.length} ratings from ${files.length} file(s): ${merged.added} new, ${merged.updated} newer, ${merged.unchanged} unchanged.`;
      report.dataset.state = "ok";
    })();
  });
  byId("clear-ratings", HTMLButtonElement).addEventListener("click", () => {
    const n = bench.allRatings().length;
    if (n === 0) return;
    exportRatings(bench, "json"); // a copy first, whatever the answer
    if (confirm(`Delete all ${n} ratings from this browser? A JSON copy was just downloaded.`)) void bench.clearRatings();
  });

  let persistAsked = false;
  const saveStatus = byId("save-status", HTMLElement);
  const notice = byId("notice", HTMLElement);
  function render(): void {
    saveStatus.dataset.state = bench.saveState;
    const n = bench.allRatings().length;
    saveStatus.textContent = bench.saveState === "saved" ? `${n} ratings saved` : bench.saveState === "saving" ? "saving…" : "NOT SAVED";
    notice.hidden = bench.storageProblem === null;
    byId("notice-text", HTMLElement).textContent = bench.storageProblem ?? "";
    if (!persistAsked && n > 0) {
      persistAsked = true;
      void navigator.storage?.persist?.();
    }
    blind.checked = bench.settings.blind;
    document.body.classList.toggle("blind", bench.settings.blind);
    const tab = currentTab();
    if (tab === "batch") batchView.render();
    else if (tab === "rate") void rateView.render();
    else curvesView.render();
  }
  bench.onChange(render);
  window.addEventListener("hashchange", () => show(currentTab()));
  window.addEventListener("beforeunload", (event) => {
    if (bench.hasUnsaved()) event.preventDefault();
  });
  show(currentTab());
  document.body.dataset.ready = "true";
}

start().catch((e: unknown) => {
  const notice = document.getElementById("notice");
  const text = document.getElementById("notice-text");
  if (notice !== null && text !== null) {
    notice.hidden = false;
    text.textContent = `The workbench could not start: ${e instanceof Error ? e.message : String(e)}`;
  }
  document.body.dataset.ready = "error";
});
