// The workbench's state: settings, the current batch with its plans, and the ratings, written
// through to IndexedDB on every change. If the browser cannot store them (storage full, blocked),
// ratings stay in the page and the user is told to export them.

import { EvalStore, StorageError, type PlanEntry, type Settings, type StoredBatch } from "../eval/storage";
import { mergeRatings, ratingKey, type MergeReport, type Rating } from "../eval/ratings";
import type { Plan } from "../planner/types";
import type { Variant } from "../eval/types";

export type SaveState = "saved" | "saving" | "error";

type Listener = () => void;

const defaultSettings = (): Settings => ({ rater: "rater", blind: false, seed: Math.random().toString(36).slice(2), position: null });

export class Workbench {
  settings: Settings = defaultSettings();
  batch: StoredBatch | null = null;
  /** Plans of the current batch kept in memory (the store has them all). */
  readonly plans = new Map<string, Plan>();
  private readonly ratings = new Map<string, Rating>();
  private readonly unsaved = new Set<string>();
  saveState: SaveState = "saved";
  storageProblem: string | null = null;
  private readonly listeners = new Set<Listener>();

  private constructor(private readonly store: EvalStore | null) {}

  static async open(): Promise<Workbench> {
    let store: EvalStore | null = null;
    let problem: string | null = null;
    try {
      store = await EvalStore.open();
    } catch (e) {
      problem = `Ratings cannot be stored in this browser (${e instanceof Error ? e.message : String(e)}). Export them before you leave the page.`;
    }
    const bench = new Workbench(store);
    bench.storageProblem = problem;
    if (store !== null) {
      bench.settings = (await store.settings()) ?? defaultSettings();
      for (const r of await store.allRatings()) bench.ratings.set(ratingKey(r), r);
      bench.batch = await store.batch();
    }
    return bench;
  }

  onChange(listener: Listener): void {
    this.listeners.add(listener);
  }

  changed(): void {
    for (const l of this.listeners) l();
  }

  allRatings(): Rating[] {
    return [...this.ratings.values()];
  }

  rating(r: Pick<Rating, "rater" | "type" | "id" | "variant" | "object" | "state">): Rating | undefined {
    return this.ratings.get(ratingKey(r));
  }

  hasUnsaved(): boolean {
    return this.unsaved.size > 0;
  }

  /** Records ratings and writes them through to IndexedDB. */
  async rate(ratings: readonly Rating[]): Promise<void> {
    for (const r of ratings) {
      const key = ratingKey(r);
      this.ratings.set(key, r);
      this.unsaved.add(key);
    }
    await this.flush();
  }

  /** Writes every unsaved rating; on failure keeps them unsaved and reports the problem. */
  async flush(): Promise<void> {
    if (this.store === null) {
      this.saveState = "error";
      this.changed();
      return;
    }
    const pending = [...this.unsaved].map((k) => this.ratings.get(k)).filter((r): r is Rating => r !== undefined);
    if (pending.length === 0) return;
    this.saveState = "saving";
    this.changed();
    try {
      await this.store.putRatings(pending);
      for (const r of pending) if (this.ratings.get(ratingKey(r)) === r) this.unsaved.delete(ratingKey(r));
      this.saveState = this.unsaved.size === 0 ? "saved" : "saving";
      if (this.storageProblem !== null && this.unsaved.size === 0) this.storageProblem = null;
    } catch (e) {
      this.saveState = "error";
      this.storageProblem =
        e instanceof StorageError && e.quota
          ? "The browser's storage is full: your latest ratings are only in this page. Export them now, then free some space."
          : `Your latest ratings could not be saved (${e instanceof Error ? e.message : String(e)}). Export them now.`;
    }
    this.changed();
  }

  /** Merges imported ratings (several raters' files), saving them. */
  async importRatings(incoming: readonly Rating[]): Promise<MergeReport> {
    const report = mergeRatings(this.allRatings(), incoming);
    this.ratings.clear();
    for (const r of report.ratings) this.ratings.set(ratingKey(r), r);
    const changedKeys = new Set(incoming.map(ratingKey));
    for (const r of report.ratings) if (changedKeys.has(ratingKey(r))) this.unsaved.add(ratingKey(r));
    await this.flush();
    this.changed();
    return report;
  }

  /** Deletes every rating (the caller exports them first). */
  async clearRatings(): Promise<void> {
    await this.store?.clearRatings();
    this.ratings.clear();
    this.unsaved.clear();
    this.saveState = "saved";
    this.changed();
  }

  async saveSettings(patch: Partial<Settings>): Promise<void> {
    this.settings = { ...this.settings, ...patch };
    try {
      await this.store?.putSettings(this.settings);
    } catch (e) {
      this.storageProblem = `Settings could not be saved: ${e instanceof Error ? e.message : String(e)}`;
    }
    this.changed();
  }

  async startBatch(batch: StoredBatch): Promise<void> {
    this.batch = batch;
    this.plans.clear();
    await this.guard(() => this.store?.startBatch(batch));
    this.changed();
  }

  /** Adds results to the current batch and stores them. */
  async addResults(entries: readonly PlanEntry[], status: StoredBatch["status"]): Promise<void> {
    const batch = this.batch;
    if (batch === null) return;
    batch.status = status;
    for (const e of entries) this.plans.set(planCacheKey(e.recipe.type, e.recipe.id, e.variant), e.plan);
    await this.guard(() => this.store?.saveBatch(batch, entries));
    this.changed();
  }

  async plan(type: string, id: string, variant: Variant): Promise<Plan | null> {
    const key = planCacheKey(type, id, variant);
    const cached = this.plans.get(key);
    if (cached !== undefined) return cached;
    if (this.store === null || this.batch === null) return null;
    const plan = await this.store.plan(this.batch.id, type, id, variant);
    if (plan !== null) this.plans.set(key, plan);
    return plan;
  }

  private async guard(write: () => Promise<void> | undefined): Promise<void> {
    try {
      await write();
    } catch (e) {
      this.storageProblem =
        e instanceof StorageError && e.quota
          ? "The browser's storage is full: the batch's plans are only in this page (your ratings are not affected). Export your ratings and free some space."
          : `The batch could not be stored: ${e instanceof Error ? e.message : String(e)}`;
    }
  }
}

export const planCacheKey = (type: string, id: string, variant: Variant): string => JSON.stringify([type, id, variant]);
