// The embeddable planner: `<foon-planner>` (defined on import) and `mount(element, options)`.

import { defineFoonPlanner } from "./element";

export { FoonPlannerElement, defineFoonPlanner } from "./element";
export type { FoonPlannerEventMap } from "./element";
export { mount, DEFAULT_KB_URL } from "./mount";
export type { ErrorEventDetail, MountCallbacks, PlanEventDetail, PlannerHandle, SelectEventDetail, WidgetOptions, WidgetView } from "./mount";

export { asFrameMessage } from "./frame";
export type { FrameEvent, FrameMessage } from "./frame";

defineFoonPlanner();
