// The query lives in the URL: every change updates it (a burst of typing is one history entry), and
// back/forward restore the query they point at. The URL follows the query once the page is idle after an
// edit: a history update takes 0.6-9 ms on a loaded 2-core VM, which the edit's re-plan would wait for.

import { whenIdle } from "./draw-schedule";
import { queryFromSearch, queryToSearch, type AppQuery } from "./query";
import type { Store } from "./store";

/** Edits closer together than this share one history entry. */
const COALESCE_MS = 1500;

export function syncQueryWithUrl(store: Store, setQuery: (query: AppQuery) => void, win: Window = window): () => void {
  let lastPush = 0;
  let restoring = false;
  let scheduled = false;
  let stopped = false;
  /** The URL of the query now (a query restored from the history in the meantime is already there). */
  const update = (): void => {
    scheduled = false;
    if (stopped) return;
    const search = queryToSearch(store.state.query);
    if (search === win.location.search) return;
    const url = `${win.location.pathname}${search}${win.location.hash}`;
    const now = Date.now();
    if (now - lastPush < COALESCE_MS) win.history.replaceState(null, "", url);
    else win.history.pushState(null, "", url);
    lastPush = now;
  };
  const unsubscribe = store.subscribe((state, previous) => {
    if (state.query === previous.query || restoring || scheduled) return;
    scheduled = true;
    whenIdle(update);
  });
  const onPop = (): void => {
    const query = queryFromSearch(win.location.search) ?? { dish: "", ingredients: [], overrides: {} };
    restoring = true;
    try {
      setQuery(query);
    } finally {
      restoring = false;
    }
    lastPush = 0;
  };
  win.addEventListener("popstate", onPop);
  return () => {
    stopped = true;
    unsubscribe();
    win.removeEventListener("popstate", onPop);
  };
}
