// A build that bundles the public FOON-111 instead of the starter knowledge base (E2E_DIST=dist-foon111,
// see scripts/test.sh) loads it in the browser and plans a dev query from ../shared.
import { readFileSync, readdirSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, inject, it } from "vitest";
import type { Browser } from "playwright-core";
import { launch, screenshot, watchErrors } from "./browser";
import { waitForPlan } from "./app-helpers";
import { SHARED } from "../unit/helpers";
import type { Query } from "../../src/planner/types";

let browser: Browser;
beforeAll(async () => {
  browser = await launch();
});
afterAll(async () => {
  await browser?.close();
});

function devQuery(dish: string): Query {
  const dir = join(SHARED, "recipes/dev", dish);
  const first = readdirSync(dir).filter((f) => f.endsWith(".json")).sort()[0];
  if (first === undefined) throw new Error(`${dir}: no queries`);
  return JSON.parse(readFileSync(join(dir, first), "utf8")) as Query;
}

describe("demo built with FOON-111", () => {
  it("bundles FOON-111 and plans a dev soup query in the browser", async () => {
    const query = devQuery("soup");
    const search = new URLSearchParams([["dish", query.type], ...query.ingredients.map((i): [string, string] => ["i", `${i.object}~${i.state}`])]);
    const page = await browser.newPage();
    const errors = watchErrors(page);
    await page.goto(`${inject("baseUrl")}?${search.toString()}`);
    await waitForPlan(page);
    // the knowledge-base panel reports FOON-111's 111 recipes, not the starter knowledge base's
    await expect.poll(async () => page.locator("body").textContent()).toMatch(/111 recipes/);
    const steps = await page.locator("ol li").count();
    expect(steps).toBeGreaterThan(2);
    await screenshot(page, "foon111-soup");
    expect(errors).toEqual([]);
  });
});
