// The iframe page (widget.html): one planner from the URL's parameters, its events and its height posted
// to the parent page (shapes in src/widget/frame.ts).

import { frameSettings, type FrameEvent, type FrameMessage } from "./widget/frame";
import { mount } from "./widget/mount";

const settings = frameSettings(location.search);
const host = document.getElementById("widget");

function post(event: FrameEvent): void {
  if (window.parent === window) return; // opened on its own: nobody to tell
  const message: FrameMessage = { source: "foon-planner", version: 1, frame: settings.frame, ...event };
  window.parent.postMessage(message, settings.targetOrigin);
}

if (host !== null) {
  mount(host, settings.widget, {
    onPlan: (detail) => post({ type: "plan", detail }),
    onSelect: (detail) => post({ type: "select", detail }),
    onError: (detail) => post({ type: "error", detail }),
  });
  let height = -1;
  new ResizeObserver(() => {
    const next = Math.ceil(document.body.getBoundingClientRect().height);
    if (next === height) return;
    height = next;
    post({ type: "resize", detail: { height } });
  }).observe(document.body);
}
