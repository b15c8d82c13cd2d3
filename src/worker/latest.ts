// Keeps only the newest pending job: a plan request that arrives while another waits replaces it (the
// replaced one is returned so that its caller can be told). WASM calls cannot be interrupted, so this is
// how stale requests are cancelled: the ones queued behind a running plan never run.

export class LatestOnly<T extends { id: number }> {
  private pending: T | null = null;

  /** Queues `job`; returns the job it replaced, if any. */
  push(job: T): T | null {
    const replaced = this.pending;
    this.pending = job;
    return replaced;
  }

  /** The newest job, removed from the queue. */
  take(): T | null {
    const job = this.pending;
    this.pending = null;
    return job;
  }
}
