import { describe, expect, it } from "vitest";
import { CsvError, parseCsv, parseCsvRecords, toCsv } from "../../src/eval/csv";

describe("CSV", () => {
  it("round-trips hostile fields", () => {
    const rows = [["a,b", 'say "hi"', "two\nlines", "=1+1", "<img src=x onerror=alert(1)>"], ["", "x", "y", "z", "ü"]];
    const text = toCsv(["c1", "c2", "c3", "c4", "c5"], rows);
    expect(parseCsv(text)).toEqual([["c1", "c2", "c3", "c4", "c5"], ...rows]);
  });

  it("reads LF and CRLF, a BOM, and records by column", () => {
    expect(parseCsvRecords("\uFEFFa,b\n1,2\r\n3,4", ["a"])).toEqual([{ a: "1", b: "2" }, { a: "3", b: "4" }]);
  });

  it("rejects broken files with a line number", () => {
    expect(() => parseCsv('a,"b')).toThrow(CsvError);
    expect(() => parseCsv('"a"x,b')).toThrow(/line 1/);
    expect(() => parseCsvRecords("a,b\n1", ["a"])).toThrow(/line 2: 1 fields/);
    expect(() => parseCsvRecords("a\n1", ["a", "b"])).toThrow(/missing column/);
  });
});
