// The query lives in the URL: every change updates it (a burst of typing is one history entry), and
// back/forward restore the query they point at.

import { queryFromSearch, queryToSearch, type AppQuery } from "./query";
import type { Store } from "./store";

/** Edits closer together than this share one history entry. */
const COALESCE_MS = 1500;

export function syncQueryWithUrl(store: Store, setQuery: (query: AppQuery) => void, win: Window = window): () => void {
  let lastPush = 0;
  let restoring = false;
  const unsubscribe = store.subscribe((state, previous) => {
    if (state.query === previous.query || restoring) return;
    const search = queryToSearch(state.query);
    if (search === win.location.search) return;
    const url = `${win.location.pathname}${search}${win.location.hash}`;
    const now = Date.now();
    if (now - lastPush < COALESCE_MS) win.history.replaceState(null, "", url);
    else win.history.pushState(null, "", url);
    lastPush = now;
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
    unsubscribe();
    win.removeEventListener("popstate", onPop);
  };
}
