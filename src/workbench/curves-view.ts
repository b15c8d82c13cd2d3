// Threshold curves from the ratings: choose raters, see Fig. 6, export it as SVG, PNG or CSV.

import { curvesToCsv, thresholdCurves, type Curve } from "../eval/curves";
import { recipeKey } from "../eval/queries";
import { ratingItems } from "../eval/ratings";
import { thresholdChart, svgText, svgToPng } from "./chart";
import { byId, download, el, timestamp } from "./dom";
import type { Workbench } from "./state";

export class CurvesView {
  private curves: Curve[] = [];
  private svg: SVGSVGElement | null = null;
  private readonly raterSelect = byId("curve-rater", HTMLSelectElement);
  private readonly completeOnly = byId("curve-complete", HTMLInputElement);

  constructor(private readonly bench: Workbench) {
    this.raterSelect.addEventListener("change", () => this.render());
    this.completeOnly.addEventListener("change", () => this.render());
    byId("export-svg", HTMLButtonElement).addEventListener("click", () => {
      if (this.svg !== null) download(`threshold-curves-${timestamp()}.svg`, svgText(this.svg), "image/svg+xml");
    });
    byId("export-png", HTMLButtonElement).addEventListener("click", () => {
      if (this.svg !== null) void svgToPng(this.svg).then((png) => download(`threshold-curves-${timestamp()}.png`, png));
    });
    byId("export-curves-csv", HTMLButtonElement).addEventListener("click", () => download(`threshold-curves-${timestamp()}.csv`, curvesToCsv(this.curves), "text/csv"));
  }

  render(): void {
    const ratings = this.bench.allRatings();
    const raters = [...new Set(ratings.map((r) => r.rater))].sort();
    const chosen = this.raterSelect.value;
    this.raterSelect.replaceChildren(el("option", { value: "", text: "all raters (mean)" }), ...raters.map((r) => el("option", { value: r, text: r })));
    this.raterSelect.value = raters.includes(chosen) ? chosen : "";

    const expected = new Map<string, number>();
    if (this.completeOnly.checked) for (const q of this.bench.batch?.queries ?? []) expected.set(recipeKey(q.query), ratingItems(q.query.ingredients).length);
    this.curves = thresholdCurves(ratings, { raters: this.raterSelect.value === "" ? undefined : new Set([this.raterSelect.value]), expected });

    const chart = byId("chart", HTMLElement);
    const summary = byId("curve-summary", HTMLElement);
    for (const id of ["export-svg", "export-png", "export-curves-csv"]) byId(id, HTMLButtonElement).disabled = this.curves.length === 0;
    if (this.curves.length === 0) {
      this.svg = null;
      chart.replaceChildren(el("p", { text: "No rated recipes yet." }));
      summary.replaceChildren();
      return;
    }
    this.svg = thresholdChart(this.curves);
    chart.replaceChildren(this.svg);
    summary.replaceChildren(
      el("caption", { text: "Share of recipes whose every progress line is correct (threshold 100%)" }),
      el("tr", {}, el("th", { text: "dish type" }), el("th", { text: "with modification" }), el("th", { text: "without" })),
      ...[...new Set(this.curves.map((c) => c.type))].map((type) => {
        const at100 = (variant: string): string => {
          const c = this.curves.find((x) => x.type === type && x.variant === variant);
          return c === undefined ? "–" : `${Math.round((c.points[c.points.length - 1]?.share ?? 0) * 100)}% of ${c.recipes}`;
        };
        return el("tr", { "data-type": type }, el("th", { text: type }), el("td", { text: at100("modified") }), el("td", { text: at100("unmodified") }));
      }),
    );
  }
}
