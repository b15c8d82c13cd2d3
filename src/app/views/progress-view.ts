// Progress lines with D3 (section IV-A of the paper): one row per ingredient, its states (green circles,
// with the container under them), the motions between them (red squares), the end product at the right.
// Hovering a motion shows its functional unit; clicking (or Enter) selects it everywhere.

import { select, type Selection as D3Selection } from "d3";
import type { Plan } from "../../planner/types";
import { el } from "../dom";
import { describeUnit, selectProgressMotion, type Selection } from "../model/tree";
import { columnCount, progressRows, type ProgressCell, type ProgressRow } from "../model/progress";
import type { StateSource } from "../draw-schedule";
import type { AppState } from "../store";

const NAME_WIDTH = 130;
const COLUMN = 112;
const ROW = 78;
const TOP = 28;

export interface ProgressViewActions {
  select(selection: Selection): void;
}

/** A cell as drawn: its text and marks (a motion's tooltip describes its unit, and is set for every plan). */
type DrawnCell = ProgressCell & { ingredient: string; selected: boolean };

/** One progress line as drawn, and its key: a line whose key is unchanged keeps its elements across re-plans. */
interface DrawnLine {
  ingredient: string;
  onLine: boolean;
  width: number;
  cells: DrawnCell[];
  key: string;
}

/** Everything a line's elements show, so that two lines with the same key look the same. */
function drawnLines(rows: readonly ProgressRow[], selection: Selection, width: number): DrawnLine[] {
  return rows.map((row) => {
    const cells = row.cells.map((c): DrawnCell => {
      const selected = c.kind === "motion" && c.unit !== null && c.unit === selection.unit && row.ingredient === selection.ingredient;
      return { ...c, ingredient: row.ingredient, selected };
    });
    const line = { ingredient: row.ingredient, onLine: row.ingredient === selection.ingredient, width, cells };
    return { ...line, key: JSON.stringify(line) };
  });
}

export function mountProgressView(host: HTMLElement, store: StateSource, actions: ProgressViewActions): () => void {
  const frame = el("div", { class: "progress-frame" });
  const detail = el("p", { class: "muted small progress-detail", "aria-live": "polite" });
  host.replaceChildren(el("h2", { text: "Progress lines" }), frame, detail);
  const svgNs = "http://www.w3.org/2000/svg";
  const svgElement = document.createElementNS(svgNs, "svg");
  svgElement.setAttribute("class", "progress-svg");
  svgElement.setAttribute("role", "group");
  svgElement.setAttribute("aria-label", "Progress line of each ingredient");
  frame.append(svgElement);
  const svg = select(svgElement);
  // kept lines' handlers outlive the plan they were drawn for: they ask the one drawn now
  let drawnPlan: Plan | null = null;

  /** A motion's tooltip: its functional unit in the plan drawn now (a kept line's unit may have other inputs). */
  const describe = (c: DrawnCell): string => (c.kind === "motion" && c.unit !== null && drawnPlan !== null ? `Step ${c.unit + 1}. ${describeUnit(drawnPlan, c.unit)}` : c.text);
  const choose = (c: DrawnCell): void => {
    if (c.kind === "motion" && drawnPlan !== null) actions.select(selectProgressMotion(drawnPlan, c.ingredient, c.index));
  };

  /** A new line's elements: its band, name and track, and its cells. */
  function drawLine(row: D3Selection<SVGGElement, DrawnLine, SVGSVGElement, unknown>): void {
    row
      .attr("class", (d) => (d.onLine ? "line on-line" : "line"))
      .attr("data-ingredient", (d) => d.ingredient);
    row.append("rect").attr("class", "band").attr("x", 0).attr("y", -22).attr("width", (d) => d.width).attr("height", ROW - 8).attr("rx", 6);
    row.append("text").attr("class", "name").attr("x", 8).attr("y", 4).text((d) => d.ingredient);
    row
      .append("line")
      .attr("class", "track")
      .attr("x1", NAME_WIDTH)
      .attr("x2", (d) => NAME_WIDTH + (d.cells.length - 1) * COLUMN)
      .attr("y1", 0)
      .attr("y2", 0);

    const cell = row
      .selectAll<SVGGElement, DrawnCell>("g.cell")
      .data((d) => d.cells)
      .join("g")
      .attr("class", (c) => `cell ${c.kind}`)
      .attr("transform", (_c, i) => `translate(${NAME_WIDTH + i * COLUMN}, 0)`);

    cell.filter((c) => c.kind === "state").append("circle").attr("r", 9);
    cell
      .filter((c) => c.kind === "motion")
      .append("rect")
      .attr("x", -8)
      .attr("y", -8)
      .attr("width", 16)
      .attr("height", 16)
      .attr("class", (c) => (c.selected ? "selected" : ""));
    cell.filter((c) => c.kind === "product").append("rect").attr("x", -10).attr("y", -10).attr("width", 20).attr("height", 20).attr("rx", 10).attr("class", "product-mark");

    // state text under the circle, its container below; motion text above the square
    cell.append("text").attr("class", "label").attr("text-anchor", "middle").attr("y", (c) => (c.kind === "motion" ? -14 : 24)).text((c) => c.text);
    cell
      .filter((c) => c.kind === "state")
      .append("text")
      .attr("class", "location")
      .attr("text-anchor", "middle")
      .attr("y", 37)
      .text((c) => (c.kind === "state" ? c.location : ""));

    const motions = cell.filter((c) => c.kind === "motion");
    motions
      .attr("tabindex", 0)
      .attr("role", "button")
      .attr("aria-label", (c) => `${c.ingredient}: ${c.text}${c.kind === "motion" && c.unit !== null ? `, step ${c.unit + 1}` : ""}`)
      .append("title");
    motions.on("click", (_event: MouseEvent, c) => choose(c));
    motions.on("keydown", (event: KeyboardEvent, c) => {
      if (event.key === "Enter" || event.key === " ") {
        event.preventDefault();
        choose(c);
      }
    });
    motions.on("mouseenter", (_event: MouseEvent, c) => {
      if (c.kind === "motion" && c.unit !== null) detail.textContent = describe(c);
    });
  }

  /** Draws the lines whose picture changed (a re-plan usually changes one ingredient's line) and moves the rest. */
  function render(plan: Plan | null, selection: Selection): void {
    drawnPlan = plan;
    const rows: ProgressRow[] = plan === null ? [] : progressRows(plan);
    const width = NAME_WIDTH + Math.max(1, columnCount(rows)) * COLUMN;
    const height = TOP + Math.max(1, rows.length) * ROW;
    svg.attr("width", width).attr("height", height).attr("viewBox", `0 0 ${width} ${height}`);
    svg.selectAll("text.empty").remove();
    const lines = plan === null ? [] : drawnLines(rows, selection, width);
    svg
      .selectAll<SVGGElement, DrawnLine>("g.line")
      .data(lines, (d) => d.key)
      .join((enter) => enter.append("g").call(drawLine))
      .attr("transform", (_d, i) => `translate(0, ${TOP + i * ROW})`)
      .order()
      .selectAll<SVGTitleElement, DrawnCell>("g.cell.motion title")
      .text(describe);
    if (lines.length === 0) {
      svg.append("text").attr("x", 8).attr("y", 24).attr("class", "empty").text(plan === null ? "No plan yet." : "No ingredient has a progress line in this plan.");
    }
  }

  function renderDetail(state: AppState): void {
    const unit = state.selection.unit;
    detail.textContent = state.plan === null || unit === null ? "Hover or select a motion to see its functional unit." : `Step ${unit + 1}. ${describeUnit(state.plan, unit)}`;
  }

  const update = (state: AppState, previous: AppState | null): void => {
    if (previous === null || state.plan !== previous.plan || state.selection !== previous.selection) {
      render(state.plan, state.selection);
      renderDetail(state);
    }
  };
  update(store.state, null);
  return store.subscribe(update);
}
