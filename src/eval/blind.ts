// Blind rating: the two plans of a recipe shown as "Plan A" and "Plan B" in an order that depends
// only on the recipe and the rater's seed (stable across reloads), so raters cannot tell which is
// the modified tree.

import type { Variant } from "./types";

/** FNV-1a 32-bit hash of a string. */
export function hash32(text: string): number {
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; i += 1) {
    h ^= text.charCodeAt(i);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h >>> 0;
}

/** The two variants of a recipe in presentation order. */
export function variantOrder(recipeKey: string, seed: string, blind: boolean): [Variant, Variant] {
  if (!blind) return ["modified", "unmodified"];
  return hash32(`${seed}\u0000${recipeKey}`) % 2 === 0 ? ["modified", "unmodified"] : ["unmodified", "modified"];
}

export const BLIND_NAMES = ["Plan A", "Plan B"] as const;
