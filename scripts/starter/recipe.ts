// A small recipe builder for the starter knowledge base: each call is one cooking step and writes one
// functional unit in the plain FOON dialect, while the builder keeps track of where every ingredient is and
// what every container holds. That bookkeeping is what hand-written FOON gets wrong (a stale
// `contains {..}`, an ingredient that never reaches the dish), so the rules of public/kb/VOCABULARY.md are
// enforced here and a broken recipe throws with its file name and step.

/** The dish classes the starter recipes use (index as in wasm/core/data/dish_classes.tsv). */
export const DISH_CLASS = {
  bread: 0, soup: 1, sandwich: 4, cake: 5, sauce: 7, dessert: 8, drinks: 9, pasta: 13, noodle: 14,
  salad: 15, rice: 19, omelette: 23,
} as const;
export type DishType = keyof typeof DISH_CLASS;

/** A kitchen ingredient as it starts: label, then its states; a state with `[..]` is where it is. */
export type Kitchen = readonly [string, ...string[]];

interface Thing {
  label: string;
  states: string[];
  contains: string[] | null; // a mixture's ingredients
  where: string | null; // "in [bowl]", "on [cutting board]", "in [package]", ...
  flag: 0 | 1;
}

interface Vessel {
  label: string;
  states: string[]; // hot, greased, covered ...
  contents: Set<string>;
  where: string | null; // "on [stove]"
  items: string[]; // labels of the things in it now
  stale: boolean; // something was taken out: its contains {..} would no longer be true
}

/** Places whose contents are not tracked (VOCABULARY.md: cutting board, colander, strainer, packaging). */
const SURFACES = new Set(["cutting board", "colander", "strainer", "paper towel"]);

/** Places a thing lies on rather than in. */
const ON_TOP = new Set(["cutting board", "paper towel", "plate", "baking tray", "wire rack"]);

/** Tools and appliances: their flag and the states they are used in. */
const TOOLS: Record<string, { flag: 0 | 1; states: string[] }> = {
  oven: { flag: 0, states: ["on", "preheated"] },
  refrigerator: { flag: 0, states: ["on"] },
  microwave: { flag: 0, states: ["off"] },
  blender: { flag: 0, states: ["off"] },
  "food processor": { flag: 0, states: ["off"] },
  "wire rack": { flag: 0, states: ["clean"] },
  towel: { flag: 0, states: ["clean"] },
  "pot lid": { flag: 0, states: ["clean"] },
  squeezer: { flag: 0, states: ["empty"] },
  toaster: { flag: 0, states: ["off"] },
};

/** Cutting-board motions done without a knife, or with another tool. */
const DEFAULT_TOOL: Record<string, string> = { peel: "-", tear: "-", grate: "grater", mash: "masher", core: "knife" };

/** Motions that cook what is in a container: the container (hot, on the stove or in the oven) is an input. */
const HEATING = new Set([
  "bake", "boil", "cook", "cook and stir", "fry", "heat", "melt", "simmer", "stir and melt", "toast", "brew",
]);

export interface StepOptions {
  /** tools and appliances used (labels; see TOOLS, others are `clean` hand tools) */
  with?: string[];
  /** the thing's plain states after the step (replacing the old ones) */
  set?: string[];
  /** plain states the step adds */
  plus?: string[];
  /** plain states the step removes */
  minus?: string[];
  /** the thing's new label (squeezed lemon → lemon juice, dough → bread) */
  as?: string;
  /** include the container as an input (default: for heating motions) */
  vessel?: boolean;
}

export class Recipe {
  private readonly units: string[] = [];
  private readonly things = new Map<string, Thing>();
  private readonly vessels = new Map<string, Vessel>();
  private readonly ingredients = new Set<string>();
  private readonly dropped = new Set<string>();
  private ovenReady = false;

  constructor(readonly file: string, readonly title: string, readonly dish: DishType) {}

  /** Move a thing (a kitchen ingredient given as `[label, ...states]`, or one already in use) to a place. */
  put(motion: string, what: string | Kitchen, to: string, opts: StepOptions = {}): this {
    const thing = this.take(what);
    const ins = [this.node(thing)];
    const outs: string[] = [];
    const from = thing.where ? this.vessels.get(placeOf(thing.where)) : undefined;
    if (from) {
      from.items = from.items.filter((l) => l !== thing.label);
      from.stale = true;
    }
    if (SURFACES.has(to)) {
      ins.unshift(obj(to, 0, ["empty"]));
    } else {
      const v = this.vessel(to);
      ins.unshift(this.vesselNode(v));
      for (const i of thing.contains ?? [thing.label]) v.contents.add(i);
      v.items.push(opts.as ?? thing.label);
      outs.push(this.vesselNode(v));
    }
    ins.push(...this.tools(opts.with));
    this.change(thing, opts);
    thing.where = `${ON_TOP.has(to) ? "on" : "in"} [${to}]`;
    outs.push(this.node(thing));
    return this.unit(ins, motion, outs);
  }

  /** Change a thing where it is: cut, peel, knead, bake, chill, fold ... */
  alter(motion: string, label: string, opts: StepOptions = {}): this {
    const thing = this.get(label);
    const ins = [this.node(thing)];
    const at = thing.where ? placeOf(thing.where) : "";
    const v = this.vessels.has(at) ? this.vessel(at) : undefined;
    if (v && (opts.vessel ?? HEATING.has(motion))) ins.unshift(this.vesselNode(v));
    ins.push(...this.tools(opts.with));
    if (v && opts.as) v.items = v.items.map((l) => (l === label ? opts.as! : l));
    this.change(thing, opts);
    return this.unit(ins, motion, [this.node(thing)]);
  }

  /** Everything in a container becomes one mixture (a dressing, a batter, a soup). */
  mix(motion: string, vesselLabel: string, label: string, states: string[], opts: StepOptions = {}): this {
    const v = this.vessel(vesselLabel);
    if (v.items.length === 0) throw this.fail(`nothing in ${vesselLabel} to ${motion}`);
    const ins = [this.vesselNode(v), ...v.items.map((l) => this.node(this.get(l)))];
    ins.push(...this.tools(opts.with));
    for (const l of v.items) this.things.delete(l);
    const where = `${ON_TOP.has(vesselLabel) ? "on" : "in"} [${vesselLabel}]`;
    const mixture: Thing = { label, states, contains: [...v.contents], where, flag: 1 };
    if (this.things.has(label)) throw this.fail(`two things named ${label}`);
    this.things.set(label, mixture);
    v.items = [label];
    return this.unit(ins, motion, [this.node(mixture)]);
  }

  /** Cook some of the things in a container, each keeping its identity (onions sauteed in the oil). */
  cookEach(motion: string, vesselLabel: string, labels: string[], opts: StepOptions = {}): this {
    const v = this.vessel(vesselLabel);
    const things = labels.map((l) => this.get(l));
    const ins = [this.vesselNode(v), ...things.map((t) => this.node(t)), ...this.tools(opts.with)];
    for (const t of things) this.change(t, opts);
    return this.unit(ins, motion, things.map((t) => this.node(t)));
  }

  /** Top a dish or mixture with an ingredient (cheese on an omelette, butter on bread): the dish grows. */
  top(motion: string, what: string | Kitchen, onto: string, opts: StepOptions = {}): this {
    const topping = this.take(what);
    const dish = this.get(onto);
    const ins = [this.node(dish), this.node(topping), ...this.tools(opts.with)];
    const from = topping.where ? this.vessels.get(placeOf(topping.where)) : undefined;
    if (from) from.stale = true;
    const v = dish.where ? this.vessels.get(placeOf(dish.where)) : undefined;
    const added = topping.contains ?? [topping.label];
    const outs: string[] = [];
    if (v) {
      ins.unshift(this.vesselNode(v));
      for (const i of added) v.contents.add(i);
      outs.push(this.vesselNode(v));
    }
    this.things.delete(topping.label);
    dish.contains = [...new Set([...(dish.contains ?? [dish.label]), ...added])];
    this.change(dish, opts);
    return this.unit(ins, motion, [...outs, this.node(dish)]);
  }

  /** Several kitchen ingredients join one container, one step each. */
  putAll(motion: string, items: Kitchen[], to: string): this {
    for (const i of items) this.put(motion, i, to);
    return this;
  }

  /**
   * Place a whole ingredient on the cutting board and work it there, one step per "motion:states[:tool]"
   * (states comma-separated; tool defaults to the knife for cutting motions, "-" for none).
   */
  prep(item: Kitchen, ...steps: string[]): this {
    this.put("pick-and-place", item, "cutting board");
    for (const step of steps) {
      const [motion, states, tool] = step.split(":");
      const use = tool ?? DEFAULT_TOOL[motion] ?? "knife";
      this.alter(motion, item[0], { set: states.split(","), with: use === "-" ? [] : [use] });
    }
    return this;
  }

  /** Put a pot or pan on the stove and turn the burner on. */
  heat(vesselLabel: string): this {
    const v = this.vessel(vesselLabel);
    const before = this.vesselNode(v, true);
    v.where = "on [stove]";
    this.unit([obj("stove", 0, ["off"]), before], "pick-and-place", [this.vesselNode(v, true)]);
    const ins = [obj("stove", 0, ["off"]), this.vesselNode(v)];
    v.states.push("hot");
    return this.unit(ins, "turn on", [obj("stove", 0, ["on", `under [${vesselLabel}]`]), this.vesselNode(v)]);
  }

  preheat(): this {
    this.ovenReady = true;
    return this.unit([obj("oven", 0, ["off"])], "preheat", [obj("oven", 0, ["on", "preheated"])]);
  }

  /** Grease an empty pan or tray with a fat that is not counted as an ingredient of the dish. */
  grease(vesselLabel: string, fat: Kitchen, tool = "brush"): this {
    const v = this.vessel(vesselLabel);
    if (v.contents.size > 0) throw this.fail(`${vesselLabel} is not empty`);
    const ins = [this.vesselNode(v, true), obj(tool, 1, ["clean"]), obj(fat[0], 0, fat.slice(1))];
    v.states.push("greased");
    return this.unit(ins, "brush", [this.vesselNode(v, true)]);
  }

  /** An ingredient that is poured away (pasta water) and so need not be in the dish. */
  drop(label: string): this {
    this.dropped.add(label);
    return this;
  }

  /** The FOON text; the last unit's output `goal` is the goal node. */
  text(goal: string): string {
    const last = this.units.at(-1);
    const goalThing = this.things.get(goal);
    if (!last || !goalThing) throw this.fail(`no goal ${goal}`);
    const head = `O\t${goal}\t1\n`;
    const at = last.lastIndexOf(head);
    if (at < 0 || at < last.indexOf("M\t")) throw this.fail(`the last step does not make ${goal}`);
    const dish = new Set(goalThing.contains ?? []);
    const missing = [...this.ingredients].filter((i) => !dish.has(i) && !this.dropped.has(i));
    if (missing.length > 0) throw this.fail(`not in the dish: ${missing.join(", ")}`);
    this.units[this.units.length - 1] =
      last.slice(0, at) + `O\t${goal}\t1\t${DISH_CLASS[this.dish]}\n` + last.slice(at + head.length);
    return `# title: ${this.title}\n//\n${this.units.join("")}`;
  }

  private take(what: string | Kitchen): Thing {
    if (typeof what === "string") return this.get(what);
    const [label, ...states] = what;
    if (this.things.has(label)) throw this.fail(`${label} is already in use`);
    const where = states.find((s) => s.includes("[")) ?? null;
    const thing: Thing = { label, states: states.filter((s) => s !== where), contains: null, where, flag: 1 };
    this.things.set(label, thing);
    this.ingredients.add(label);
    return thing;
  }

  private change(thing: Thing, opts: StepOptions): void {
    let states = opts.set ? [...opts.set] : thing.states.filter((s) => !(opts.minus ?? []).includes(s));
    for (const s of opts.plus ?? []) if (!states.includes(s)) states.push(s);
    if (opts.as && opts.as !== thing.label) {
      if (this.things.has(opts.as)) throw this.fail(`two things named ${opts.as}`);
      this.things.delete(thing.label);
      thing.label = opts.as;
      this.things.set(opts.as, thing);
    }
    thing.states = states;
  }

  private get(label: string): Thing {
    const t = this.things.get(label);
    if (!t) throw this.fail(`no ${label} in use`);
    return t;
  }

  private vessel(label: string): Vessel {
    let v = this.vessels.get(label);
    if (!v) {
      v = { label, states: [], contents: new Set(), where: null, items: [], stale: false };
      this.vessels.set(label, v);
    }
    if (v.stale) throw this.fail(`${label} is reused after something was taken out of it`);
    return v;
  }

  private tools(labels: string[] = []): string[] {
    return labels.map((l) => {
      if (l === "oven" && !this.ovenReady) throw this.fail("the oven is not preheated");
      const t = TOOLS[l] ?? { flag: 1, states: ["clean"] };
      return obj(l, t.flag, t.states);
    });
  }

  private node(t: Thing): string {
    const states = [...t.states];
    if (t.contains) states.push(`contains\t{${sorted(t.contains)}}`);
    if (t.where) states.push(relation(t.where));
    return obj(t.label, t.flag, states);
  }

  private vesselNode(v: Vessel, moving = false): string {
    const states = [...v.states];
    if (v.contents.size === 0) states.unshift("empty");
    else states.push(`contains\t{${sorted([...v.contents])}}`);
    if (v.where) states.push(relation(v.where));
    return obj(v.label, moving ? 1 : 0, states);
  }

  private unit(ins: string[], motion: string, outs: string[]): this {
    this.units.push(`${ins.join("")}M\t${motion}\t<Assumed>\n${outs.join("")}//\n`);
    return this;
  }

  private fail(reason: string): Error {
    return new Error(`${this.file} (step ${this.units.length + 1}): ${reason}`);
  }
}

function sorted(labels: string[]): string {
  return [...new Set(labels)].sort().join(",");
}

function placeOf(where: string): string {
  return where.slice(where.indexOf("[") + 1, -1);
}

/** "in [bowl]" → "in\t[bowl]" */
function relation(where: string): string {
  const at = where.indexOf(" [");
  return `${where.slice(0, at)}\t${where.slice(at + 1)}`;
}

function obj(label: string, flag: 0 | 1, states: string[]): string {
  return `O\t${label}\t${flag}\n${states.map((s) => `S\t${s.includes("[") && !s.includes("\t") ? relation(s) : s}\n`).join("")}`;
}
