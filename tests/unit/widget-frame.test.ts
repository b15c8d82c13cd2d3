// The iframe page's URL parameters (dist/widget.html?…) and the messages a parent page accepts from it.
import { describe, expect, it } from "vitest";
import { asFrameMessage, frameSettings } from "../../src/widget/frame";
import { widgetIngredients } from "../../src/widget/options";

describe("widget.html parameters", () => {
  it("reads the app's URL form: dish, object~state rows, view, theme", () => {
    const s = frameSettings("?dish=salad&i=chili+pepper~chopped&i=cool+whip&view=progress&theme=dark");
    expect(s.widget).toMatchObject({ dishType: "salad", view: "progress", theme: "dark", kbUrl: undefined });
    expect(widgetIngredients(s.widget.ingredients, ["chopped"])).toEqual([
      { object: "chili pepper", state: "chopped" },
      { object: "cool whip", state: "" },
    ]);
    expect(s).toMatchObject({ frame: "", targetOrigin: "*" });
  });

  it("takes the element's ingredient list, a knowledge base, the frame's id and the parent's origin", () => {
    const s = frameSettings("?ingredients=chopped+carrot,+diced+onion&kb-url=kb/mine.foon&id=lesson-4&origin=https://course.example");
    expect(widgetIngredients(s.widget.ingredients, ["chopped", "diced"])).toEqual([
      { object: "carrot", state: "chopped" },
      { object: "onion", state: "diced" },
    ]);
    expect(s).toMatchObject({ widget: { kbUrl: "kb/mine.foon", view: "all", theme: "system" }, frame: "lesson-4", targetOrigin: "https://course.example" });
  });

  it("tells the frame's messages from other pages' messages", () => {
    expect(asFrameMessage({ source: "foon-planner", version: 1, frame: "a", type: "resize", detail: { height: 300 } })?.type).toBe("resize");
    expect(asFrameMessage({ source: "other", version: 1 })).toBeNull();
    expect(asFrameMessage("foon-planner")).toBeNull();
    expect(asFrameMessage(null)).toBeNull();
  });
});
