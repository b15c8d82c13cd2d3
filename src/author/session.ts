// The editor page's work with the planner and the user's knowledge base: checks of the text (one at a time,
// only the newest waiting one runs), the words to complete, and "use in planner". One worker serves all
// three, so they run one after another: a check loads the text alone, the others the whole knowledge base.

import type { KbPersistence } from "../app/kb-store";
import type { KnowledgeBaseFile } from "../planner/types";
import type { LoadedKnowledgeBase } from "../worker/protocol";
import { authoredFile, checkText, type CheckPlanner, type CheckResult } from "./check";
import type { CompletionWords } from "./complete";
import { withAuthored } from "./merge";
import { motionsOf } from "./tokens";

export interface AuthorSession {
  /** Checks the text; null when a newer check replaced this one before it ran. */
  check(name: string, text: string): Promise<CheckResult | null>;
  /** The words of the user's knowledge base (else the bundled one). */
  words(): Promise<CompletionWords>;
  /** The user's knowledge base with the authored file in it, as saved for the planner. */
  knowledgeBaseWith(name: string, text: string): Promise<KnowledgeBaseFile[]>;
  /** Adds the file to the user's knowledge base once the merged knowledge base loads; resolves with its words. */
  useInPlanner(name: string, text: string): Promise<{ files: KnowledgeBaseFile[]; words: CompletionWords }>;
}

export interface SessionOptions {
  planner: CheckPlanner;
  persistence: Promise<KbPersistence>;
  bundled(): Promise<KnowledgeBaseFile>;
}

function wordsOf(kb: LoadedKnowledgeBase, files: readonly KnowledgeBaseFile[]): CompletionWords {
  const decoder = new TextDecoder();
  const motions = [...new Set(files.flatMap((f) => motionsOf(decoder.decode(f.bytes))))].sort();
  return { labels: kb.vocabulary.labels, states: kb.vocabulary.states, motions };
}

export function createAuthorSession({ planner, persistence, bundled }: SessionOptions): AuthorSession {
  let chain: Promise<unknown> = Promise.resolve();
  const exclusive = <T>(job: () => Promise<T>): Promise<T> => {
    const run = chain.then(job, job);
    chain = run.catch(() => undefined);
    return run;
  };
  let latest = 0;
  const saved = async (): Promise<KnowledgeBaseFile[] | null> => (await persistence).restore().catch(() => null);
  const withText = async (name: string, text: string): Promise<KnowledgeBaseFile[]> => withAuthored(await saved(), bundled, authoredFile(name, text));

  return {
    check(name, text) {
      const seq = ++latest;
      return exclusive(async () => (seq === latest ? checkText(planner, name, text) : null));
    },
    words() {
      return exclusive(async () => {
        const files = (await saved()) ?? [await bundled()];
        return wordsOf(await planner.loadFiles(files), files);
      });
    },
    knowledgeBaseWith: withText,
    useInPlanner(name, text) {
      return exclusive(async () => {
        const files = await withText(name, text);
        const kb = await planner.loadFiles(files); // the merged knowledge base must load too (cycles, clashes)
        await (await persistence).save(files);
        return { files, words: wordsOf(kb, files) };
      });
    },
  };
}
