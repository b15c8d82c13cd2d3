// Undo and redo of the editor's text. The textarea's own undo is lost whenever the page sets its value
// (a draft, a completion, a restore), so the editor keeps its own: a snapshot per edit, where a run of
// typing inside one word is one step, as in a text editor.

export interface Snapshot {
  text: string;
  /** Caret (selection start and end) after the edit. */
  start: number;
  end: number;
}

/** How an edit came about: typed edits of the same run merge into one undo step. */
export type EditKind = "type" | "delete" | "replace";

const LIMIT = 500;

export class EditHistory {
  private readonly past: Snapshot[] = [];
  private future: Snapshot[] = [];
  private lastKind: EditKind | null = null;

  constructor(private present: Snapshot) {}

  get current(): Snapshot {
    return this.present;
  }

  get canUndo(): boolean {
    return this.past.length > 0;
  }

  get canRedo(): boolean {
    return this.future.length > 0;
  }

  /** Records an edit; consecutive typing (no whitespace typed) or deleting merges into the last step. */
  record(next: Snapshot, kind: EditKind): void {
    if (next.text === this.present.text) {
      this.present = next;
      return;
    }
    const typedSpace = kind === "type" && /\s$/.test(next.text.slice(0, next.end));
    const merge = kind !== "replace" && kind === this.lastKind && !typedSpace && this.past.length > 0;
    if (!merge) {
      this.past.push(this.present);
      if (this.past.length > LIMIT) this.past.shift();
    }
    this.present = next;
    this.future = [];
    this.lastKind = typedSpace ? null : kind;
  }

  undo(): Snapshot | null {
    const previous = this.past.pop();
    if (previous === undefined) return null;
    this.future.push(this.present);
    this.present = previous;
    this.lastKind = null;
    return previous;
  }

  redo(): Snapshot | null {
    const next = this.future.pop();
    if (next === undefined) return null;
    this.past.push(this.present);
    this.present = next;
    this.lastKind = null;
    return next;
  }
}
