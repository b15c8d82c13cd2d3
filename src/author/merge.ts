// "Use in planner": the authored file joins the user's knowledge base — the files they saved, or the
// bundled knowledge base when they have none — replacing an earlier version of itself (same name).

import type { KnowledgeBaseFile } from "../planner/types";

/** The bundled knowledge base as a file of the user's knowledge base (the planner reads bundles). */
export const BUNDLED_NAME = "default.foon";

export function withAuthored(saved: readonly KnowledgeBaseFile[] | null, bundled: () => Promise<KnowledgeBaseFile>, authored: KnowledgeBaseFile): Promise<KnowledgeBaseFile[]> {
  const keep = async (): Promise<KnowledgeBaseFile[]> => (saved === null ? [await bundled()] : saved.filter((f) => f.name !== authored.name));
  return keep().then((files) => [...files, authored]);
}

/** A file name the knowledge base can hold: `.txt`, no path, something left when cleaned. */
export function cleanFileName(name: string): string {
  const base = name.trim().replace(/[/\\]/g, "-").replace(/\.txt$/i, "");
  return `${base === "" ? "my-recipe" : base}.txt`;
}
