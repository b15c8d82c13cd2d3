// A bundle: several FOON files in one text file, each behind a `#@file <name>` line (a FOON comment,
// so the bundle is itself valid FOON). The WASM loader splits it again (`foon_core::bundle`).

import type { KnowledgeBaseFile } from "./types";

export const FILE_MARK = "#@file ";

/** The files as one bundle (a file that is a bundle already is kept as it is); throws on a file that is not UTF-8 text. */
export function bundleText(files: readonly KnowledgeBaseFile[]): string {
  const decoder = new TextDecoder("utf-8", { fatal: true });
  return files
    .map((f) => {
      const text = decoder.decode(f.bytes);
      const ended = text.endsWith("\n") ? text : `${text}\n`;
      if (text.startsWith(FILE_MARK)) return ended;
      return `${FILE_MARK}${f.name}\n${ended}`;
    })
    .join("");
}
