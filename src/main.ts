// Demo page entry: the full planner app, the query in the URL, the theme picker, and the service worker
// that makes the page work offline after the first visit.

import { ALL_VIEWS, createPlannerApp } from "./app/app";
import { openKbPersistence } from "./app/kb-store";
import { EXAMPLES, queryFromSearch, queryToSearch } from "./app/query";
import { bindThemePicker } from "./app/theme";
import { syncQueryWithUrl } from "./app/url-sync";
import { PagePlanner } from "./app/page-planner";
import { WorkerPlanner } from "./worker/client";
import "./app/style.css";
import "./app/page.css";

const KB_URL = new URL("kb/default.foon", document.baseURI).href;
const EMBEDDINGS_URL = new URL("data/food-embeddings.bin", document.baseURI).href;

function start(): void {
  const host = document.getElementById("app");
  const themePicker = document.getElementById("theme");
  if (host === null || !(themePicker instanceof HTMLSelectElement)) return;
  const fromUrl = queryFromSearch(location.search);
  const initial = fromUrl ?? EXAMPLES[0]!.query;
  // the URL always shows the query, the first example's included (so "back" to it shows it again)
  if (fromUrl === null) history.replaceState(null, "", `${location.pathname}${queryToSearch(initial)}${location.hash}`);
  const app = createPlannerApp(host, {
    planner: new PagePlanner(new WorkerPlanner()),
    kbUrl: KB_URL,
    embeddingsUrl: EMBEDDINGS_URL,
    views: ALL_VIEWS,
    persistence: openKbPersistence(),
    query: initial,
    // the service worker precaches every file: started after the first plan, so it never competes with it
    events: { plan: () => registerServiceWorker() },
  });
  syncQueryWithUrl(app.store, (q) => app.setQuery(q));
  bindThemePicker(themePicker, document.documentElement, () => app.restyle());
}

let registered = false;
function registerServiceWorker(): void {
  if (registered || !import.meta.env.PROD || !("serviceWorker" in navigator)) return;
  registered = true;
  // relative to the page, so the app works from any static sub-path
  navigator.serviceWorker.register(new URL("sw.js", document.baseURI), { scope: "./" }).catch((e: unknown) => {
    console.warn("service worker not registered:", e);
  });
}

start();
