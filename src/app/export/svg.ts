// The task tree as a standalone SVG document, drawn from the laid-out positions of the tree view: object
// nodes as circles (green), motion nodes as squares (red), edges as arrows, modified nodes outlined.

import type { GraphColors } from "../theme-colors";
import type { TreeNode } from "../model/tree";

export interface PlacedNode extends Pick<TreeNode, "id" | "kind" | "label" | "detail" | "mark" | "goal"> {
  x: number;
  y: number;
  size: number;
}

export interface PlacedEdge {
  source: string;
  target: string;
}

export function escapeXml(text: string): string {
  return text.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

const r = (n: number): string => (Math.round(n * 10) / 10).toString();

export function graphToSvg(nodes: readonly PlacedNode[], edges: readonly PlacedEdge[], colors: GraphColors, title: string): string {
  if (nodes.length === 0) {
    return `<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><title>${escapeXml(title)}</title></svg>\n`;
  }
  const pad = 60;
  const minX = Math.min(...nodes.map((n) => n.x - n.size)) - pad;
  const maxX = Math.max(...nodes.map((n) => n.x + n.size)) + pad;
  const minY = Math.min(...nodes.map((n) => n.y - n.size)) - pad / 2;
  const maxY = Math.max(...nodes.map((n) => n.y + n.size)) + pad;
  const byId = new Map(nodes.map((n) => [n.id, n]));
  const out: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" viewBox="${r(minX)} ${r(minY)} ${r(maxX - minX)} ${r(maxY - minY)}" width="${r(maxX - minX)}" height="${r(maxY - minY)}" font-family="system-ui, sans-serif" font-size="11">`,
    `<title>${escapeXml(title)}</title>`,
    `<defs><marker id="arrow" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="6" markerHeight="6" orient="auto-start-reverse"><path d="M0,0L10,5L0,10z" fill="${escapeXml(colors.edge)}"/></marker></defs>`,
    `<rect x="${r(minX)}" y="${r(minY)}" width="${r(maxX - minX)}" height="${r(maxY - minY)}" fill="${escapeXml(colors.background)}"/>`,
    `<g class="edges" stroke="${escapeXml(colors.edge)}" stroke-width="1.5" fill="none">`,
  ];
  for (const e of edges) {
    const a = byId.get(e.source);
    const b = byId.get(e.target);
    if (a === undefined || b === undefined) continue;
    // stop the line at the target's border so the arrow head stays visible
    const dx = b.x - a.x;
    const dy = b.y - a.y;
    const length = Math.hypot(dx, dy) || 1;
    const ex = b.x - (dx / length) * (b.size / 2 + 2);
    const ey = b.y - (dy / length) * (b.size / 2 + 2);
    out.push(`<line x1="${r(a.x)}" y1="${r(a.y)}" x2="${r(ex)}" y2="${r(ey)}" marker-end="url(#arrow)"/>`);
  }
  out.push(`</g>`, `<g class="nodes">`);
  for (const n of nodes) {
    const half = n.size / 2;
    const stroke = n.mark !== null ? ` stroke="${escapeXml(colors.mark)}" stroke-width="4" stroke-dasharray="6 3"` : n.goal ? ` stroke="${escapeXml(colors.text)}" stroke-width="3"` : "";
    const shape =
      n.kind === "object"
        ? `<circle cx="${r(n.x)}" cy="${r(n.y)}" r="${r(half)}" fill="${escapeXml(colors.object)}"${stroke}/>`
        : `<rect x="${r(n.x - half)}" y="${r(n.y - half)}" width="${r(n.size)}" height="${r(n.size)}" fill="${escapeXml(colors.motion)}"${stroke}/>`;
    const mark = n.mark === null ? "" : ` data-mark="${escapeXml(n.mark)}"`;
    out.push(
      `<g class="${n.kind}"${mark}><title>${escapeXml(n.detail === "" ? n.label : `${n.label} (${n.detail})`)}</title>${shape}` +
        `<text x="${r(n.x)}" y="${r(n.y + half + 13)}" text-anchor="middle" fill="${escapeXml(colors.text)}">${escapeXml(n.label)}</text>` +
        (n.detail === "" ? "" : `<text x="${r(n.x)}" y="${r(n.y + half + 26)}" text-anchor="middle" fill="${escapeXml(colors.text)}" opacity="0.75" font-size="9">${escapeXml(n.detail)}</text>`) +
        `</g>`,
    );
  }
  out.push(`</g>`, `</svg>`);
  return `${out.join("\n")}\n`;
}
