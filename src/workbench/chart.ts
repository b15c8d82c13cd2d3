// Fig. 6 of the paper with D3: share of recipes (y) whose score reaches each correctness threshold
// (x), one colour per dish type, solid with tree modification and dashed without. Styles are set as
// attributes so an exported SVG looks the same outside the page.

import * as d3 from "d3";
import type { Curve } from "../eval/curves";

const WIDTH = 760;
const HEIGHT = 440;
const MARGIN = { top: 20, right: 170, bottom: 48, left: 60 };
const FONT = "system-ui, sans-serif";

export function thresholdChart(curves: readonly Curve[]): SVGSVGElement {
  const svg = d3
    .create("svg")
    .attr("xmlns", "http://www.w3.org/2000/svg")
    .attr("viewBox", `0 0 ${WIDTH} ${HEIGHT}`)
    .attr("width", WIDTH)
    .attr("height", HEIGHT)
    .attr("role", "img")
    .attr("font-family", FONT)
    .attr("font-size", 12);
  svg.append("title").text("Share of recipes reaching each correctness threshold, per dish type, with (solid) and without (dashed) tree modification");
  svg.append("rect").attr("width", WIDTH).attr("height", HEIGHT).attr("fill", "white");

  const x = d3.scaleLinear().domain([0, 100]).range([MARGIN.left, WIDTH - MARGIN.right]);
  const y = d3.scaleLinear().domain([0, 100]).range([HEIGHT - MARGIN.bottom, MARGIN.top]);
  const types = [...new Set(curves.map((c) => c.type))].sort();
  const colour = d3.scaleOrdinal<string, string>().domain(types).range(d3.schemeTableau10);

  svg.append("g").attr("transform", `translate(0,${HEIGHT - MARGIN.bottom})`).call(d3.axisBottom(x).ticks(10).tickFormat((d) => `${String(d)}%`));
  svg.append("g").attr("transform", `translate(${MARGIN.left},0)`).call(d3.axisLeft(y).ticks(10).tickFormat((d) => `${String(d)}%`));
  svg.append("text").attr("x", (MARGIN.left + WIDTH - MARGIN.right) / 2).attr("y", HEIGHT - 10).attr("text-anchor", "middle").text("threshold of correctness per recipe");
  svg.append("text").attr("transform", "rotate(-90)").attr("x", -(HEIGHT - MARGIN.bottom + MARGIN.top) / 2).attr("y", 16).attr("text-anchor", "middle").text("recipes reaching it");

  const line = d3
    .line<{ threshold: number; share: number }>()
    .x((p) => x(p.threshold))
    .y((p) => y(p.share * 100))
    .curve(d3.curveStepAfter);
  svg
    .append("g")
    .attr("class", "curves")
    .selectAll("path")
    .data(curves)
    .join("path")
    .attr("class", "curve")
    .attr("data-type", (c) => c.type)
    .attr("data-variant", (c) => c.variant)
    .attr("fill", "none")
    .attr("stroke", (c) => colour(c.type))
    .attr("stroke-width", 2)
    .attr("stroke-dasharray", (c) => (c.variant === "modified" ? null : "6 4"))
    .attr("d", (c) => line(c.points));

  const legend = svg.append("g").attr("class", "legend").attr("transform", `translate(${WIDTH - MARGIN.right + 16},${MARGIN.top})`);
  types.forEach((type, i) => {
    const row = legend.append("g").attr("transform", `translate(0,${i * 20})`);
    row.append("line").attr("x1", 0).attr("x2", 22).attr("y1", 0).attr("y2", 0).attr("stroke", colour(type)).attr("stroke-width", 3);
    const n = (variant: string): string => String(curves.find((c) => c.type === type && c.variant === variant)?.recipes ?? 0);
    row.append("text").attr("x", 28).attr("y", 4).text(`${type} (n = ${n("modified")} / ${n("unmodified")})`);
  });
  const keys = legend.append("g").attr("transform", `translate(0,${types.length * 20 + 16})`);
  keys.append("line").attr("x1", 0).attr("x2", 22).attr("stroke", "#333").attr("stroke-width", 2);
  keys.append("text").attr("x", 28).attr("y", 4).text("with modification");
  keys.append("line").attr("x1", 0).attr("x2", 22).attr("y1", 20).attr("y2", 20).attr("stroke", "#333").attr("stroke-width", 2).attr("stroke-dasharray", "6 4");
  keys.append("text").attr("x", 28).attr("y", 24).text("without");

  const node = svg.node();
  if (node === null) throw new Error("d3 did not create the chart");
  return node;
}

export function svgText(svg: SVGSVGElement): string {
  return `<?xml version="1.0" encoding="UTF-8"?>\n${new XMLSerializer().serializeToString(svg)}\n`;
}

/** Renders the SVG into a PNG at `scale` × its size. */
export async function svgToPng(svg: SVGSVGElement, scale = 2): Promise<Blob> {
  const url = URL.createObjectURL(new Blob([svgText(svg)], { type: "image/svg+xml" }));
  try {
    const image = new Image();
    image.src = url;
    await image.decode();
    const canvas = document.createElement("canvas");
    canvas.width = WIDTH * scale;
    canvas.height = HEIGHT * scale;
    const context = canvas.getContext("2d");
    if (context === null) throw new Error("no 2D canvas");
    context.drawImage(image, 0, 0, canvas.width, canvas.height);
    return await new Promise<Blob>((resolve, reject) => canvas.toBlob((b) => (b === null ? reject(new Error("PNG encoding failed")) : resolve(b)), "image/png"));
  } finally {
    URL.revokeObjectURL(url);
  }
}
