// Which knowledge base the planner uses: the bundled one or the user's files, restored after a reload,
// saved in the browser and followed across tabs. A failed load keeps the previous knowledge base.

import { describeError } from "../planner/errors";
import type { KnowledgeBaseFile } from "../planner/types";
import type { PlannerService } from "../worker/client";
import { download, plural } from "./dom";
import { StaleSaveError, type KbPersistence, type SavedKnowledgeBase } from "./kb-store";
import type { PlanController } from "./plan-controller";
import type { Store } from "./store";

async function readFiles(files: File[]): Promise<KnowledgeBaseFile[]> {
  return Promise.all(files.map(async (f) => ({ name: f.name, bytes: new Uint8Array(await f.arrayBuffer()) })));
}

const filesNotice = (n: number, what: string): string => `Your knowledge base (${plural(n, "file")}) ${what}`;

export interface KbSources {
  /** The bundled knowledge base. */
  kbUrl: string;
  /** The food embedding table; none: substitutes by exact names only. */
  embeddingsUrl?: string;
  /** Where the user's own knowledge base is saved across reloads; none: memory only. */
  persistence?: Promise<KbPersistence>;
}

export class KbController {
  private persistence: KbPersistence | null = null;
  /** The user's files in the planner now (null: a knowledge base from a URL), kept for downloading. */
  private customFiles: KnowledgeBaseFile[] | null = null;
  private seq = 0;
  /** The knowledge base's URL when it is not the user's files (an embedding page may load another). */
  private url: string;
  private stopWatching: () => void = () => undefined;

  constructor(
    private readonly store: Store,
    private readonly planner: PlannerService,
    private readonly plans: PlanController,
    private readonly sources: KbSources,
  ) {
    this.url = sources.kbUrl;
  }

  private get destroyed(): boolean {
    return this.plans.destroyed;
  }

  /** On start: the user's saved knowledge base if there is one, else the bundled one. */
  async start(): Promise<void> {
    if (this.sources.persistence !== undefined) {
      // reading the browser's storage takes 100-200 ms on a first visit: the bundled files download meanwhile
      // (wasted only on a visit that restores the user's own files)
      this.planner.prefetch(this.url, this.sources.embeddingsUrl);
      this.persistence = await this.sources.persistence;
      if (this.destroyed) return;
      this.stopWatching = this.persistence.onRemoteChange((saved) => void this.applySaved(saved));
      const saved = await this.persistence.restore().catch(() => null);
      if (saved !== null && (await this.applyFiles(saved, filesNotice(saved.length, "restored.")))) return;
    }
    await this.loadUrl(this.url);
  }

  async loadUrl(url: string, notice: string | null = null): Promise<boolean> {
    this.url = url;
    const seq = ++this.seq;
    try {
      const kb = await this.planner.loadUrl(url, this.sources.embeddingsUrl);
      if (seq !== this.seq || this.destroyed) return false;
      this.customFiles = null;
      this.store.set({ kb, kbSource: "bundled", kbError: null, kbNotice: notice, kbUnsaved: null });
      await this.plans.replan();
      return true;
    } catch (e) {
      this.store.set({ kbError: `Could not load ${url}: ${describeError(this.plans.reportError(e))}` });
      return false;
    }
  }

  /** The user's files, loaded and saved; the previous knowledge base stays when they do not load. */
  async loadFiles(files: File[]): Promise<void> {
    const savedAt = Date.now();
    const read = await readFiles(files);
    if (await this.applyFiles(read, null)) await this.persist(read, savedAt);
  }

  async useBundled(): Promise<void> {
    const savedAt = Date.now();
    if (await this.loadUrl(this.sources.kbUrl)) await this.persist(null, savedAt);
  }

  downloadFile(index: number): void {
    const file = this.customFiles?.[index];
    if (file !== undefined) download(file.name, new Blob([file.bytes as Uint8Array<ArrayBuffer>], { type: "text/plain" }));
  }

  close(): void {
    this.stopWatching();
    this.persistence?.close();
  }

  /** Loads files into the planner; false (and the previous knowledge base stays) when they do not load. */
  private async applyFiles(files: KnowledgeBaseFile[], notice: string | null): Promise<boolean> {
    const seq = ++this.seq;
    try {
      const kb = await this.planner.loadFiles(files, this.sources.embeddingsUrl);
      if (seq !== this.seq || this.destroyed) return false;
      this.customFiles = files;
      this.store.set({ kb, kbSource: "custom", kbError: null, kbNotice: notice });
      await this.plans.replan();
      return true;
    } catch (e) {
      this.store.set({ kbError: `Not loaded: ${describeError(this.plans.reportError(e))}` });
      return false;
    }
  }

  /** Another tab saved a newer choice: load it here too. */
  private async applySaved(saved: SavedKnowledgeBase): Promise<void> {
    if (saved.files === null) await this.loadUrl(this.sources.kbUrl, "Another tab switched back to the bundled knowledge base; so did this one.");
    else if (await this.applyFiles(saved.files, filesNotice(saved.files.length, "was loaded in another tab; it is loaded here too."))) this.store.set({ kbUnsaved: null });
  }

  /** Writes the choice through to the browser's storage; when it cannot, the files stay in memory and the panel says so. */
  private async persist(files: KnowledgeBaseFile[] | null, savedAt: number): Promise<void> {
    if (this.persistence === null) return;
    try {
      await this.persistence.save(files, savedAt);
      if (!this.destroyed) this.store.set({ kbUnsaved: null });
    } catch (e) {
      if (this.destroyed) return;
      if (e instanceof StaleSaveError) {
        await this.applySaved(e.current);
        return;
      }
      const reason = e instanceof Error ? e.message : String(e);
      this.store.set({ kbUnsaved: files === null ? null : { reason, names: files.map((f) => f.name) } });
    }
  }
}
