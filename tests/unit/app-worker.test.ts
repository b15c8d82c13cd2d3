import { describe, expect, it } from "vitest";
import { LatestOnly } from "../../src/worker/latest";

describe("stale plan requests", () => {
  it("keep only the newest pending request and report the ones replaced", () => {
    const queue = new LatestOnly<{ id: number }>();
    expect(queue.take()).toBeNull();
    expect(queue.push({ id: 1 })).toBeNull();
    expect(queue.push({ id: 2 })).toEqual({ id: 1 });
    expect(queue.push({ id: 3 })).toEqual({ id: 2 });
    expect(queue.take()).toEqual({ id: 3 });
    expect(queue.take()).toBeNull();
  });
});
