// The iframe page's contract (dist/widget.html): its URL parameters, and the messages it posts to the
// parent page. Pure, so the page script stays a few lines and the shapes are typed for npm users.

import { parseMode } from "../app/query";
import type { ErrorEventDetail, PlanEventDetail, SelectEventDetail } from "./mount";
import { parseTheme, parseView, type WidgetOptions } from "./options";

/** One of the frame's events: the element's three, and its content height. */
export type FrameEvent =
  | { type: "plan"; detail: PlanEventDetail }
  | { type: "select"; detail: SelectEventDetail }
  | { type: "error"; detail: ErrorEventDetail }
  /** The frame's content height in CSS pixels: set the iframe's height to it to fit. */
  | { type: "resize"; detail: { height: number } };

/** What the parent page receives, as `message` events from the frame's window. */
export type FrameMessage = { source: "foon-planner"; version: 1; frame: string } & FrameEvent;

export interface FrameSettings {
  widget: WidgetOptions;
  /** The `id` parameter, repeated in every message so a page with several frames can tell them apart. */
  frame: string;
  /** Where messages may go: the `origin` parameter (the parent's origin), else any ("*"). */
  targetOrigin: string;
}

/**
 * Reads `?dish=salad&i=chili+pepper~chopped&ingredients=whole+tomato&view=progress&theme=dark&kb-url=…&mode=…&id=…&origin=…`.
 * `i` is one row as object~state (the app's own URL form); `ingredients` the attribute's comma-separated list.
 */
export function frameSettings(search: string): FrameSettings {
  const params = new URLSearchParams(search);
  const rows = params.getAll("i").map((row) => (row.includes("~") ? row : `${row}~`));
  const phrases = params.get("ingredients");
  return {
    widget: {
      dishType: params.get("dish") ?? "",
      ingredients: [...rows, ...(phrases === null ? [] : [phrases])].join(", "),
      view: parseView(params.get("view")),
      theme: parseTheme(params.get("theme")),
      kbUrl: params.get("kb-url") ?? undefined,
      mode: parseMode(params.get("mode")),
    },
    frame: params.get("id") ?? "",
    targetOrigin: params.get("origin") ?? "*",
  };
}

/** A message of the frame, or `null` for any other page's message (check `event.origin` too). */
export function asFrameMessage(data: unknown): FrameMessage | null {
  if (typeof data !== "object" || data === null) return null;
  const message = data as Partial<FrameMessage>;
  return message.source === "foon-planner" && message.version === 1 ? (message as FrameMessage) : null;
}
