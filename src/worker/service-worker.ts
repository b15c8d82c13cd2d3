// The demo page's service worker: precaches the built app (pages, scripts, styles, the WASM module, the
// knowledge base, the embedding table) at install, so the page works offline after the first visit.
// Pages are network-first (a new deploy shows at once online), everything else cache-first (hashed
// names never change). The build fills in the file list and the version (src/worker/sw-build.ts).

const sw = self as unknown as ServiceWorkerGlobalScope;

const VERSION = "__FOON_SW_VERSION__";
const MANIFEST = "__FOON_SW_MANIFEST__"; // base64 JSON: paths relative to the scope
const CACHE = `foon-planner-${VERSION}`;

function precacheList(): string[] {
  try {
    const list: unknown = JSON.parse(atob(MANIFEST));
    return Array.isArray(list) ? list.filter((x): x is string => typeof x === "string") : [];
  } catch {
    return []; // an unbuilt worker (dev server): cache nothing up front
  }
}

const scopeUrl = (path: string): string => new URL(path, sw.registration.scope).href;

sw.addEventListener("install", (event) => {
  event.waitUntil(
    caches
      .open(CACHE)
      .then((cache) => cache.addAll(precacheList().map(scopeUrl)))
      .then(() => sw.skipWaiting()),
  );
});

sw.addEventListener("activate", (event) => {
  event.waitUntil(
    caches
      .keys()
      .then((keys) => Promise.all(keys.filter((k) => k.startsWith("foon-planner-") && k !== CACHE).map((k) => caches.delete(k))))
      .then(() => sw.clients.claim()),
  );
});

/** The cached page for a navigation: "…/" is "…/index.html"; the query string never matters. */
async function cachedPage(request: Request): Promise<Response | undefined> {
  const url = new URL(request.url);
  url.search = "";
  url.hash = "";
  if (url.pathname.endsWith("/")) url.pathname += "index.html";
  return (await caches.match(url.href, { cacheName: CACHE, ignoreVary: true })) ?? undefined;
}

async function networkFirstPage(request: Request): Promise<Response> {
  try {
    const response = await fetch(request);
    if (response.ok) return response;
    return (await cachedPage(request)) ?? response;
  } catch (e) {
    const cached = await cachedPage(request);
    if (cached !== undefined) return cached;
    throw e;
  }
}

// ignoreVary: servers answer `Vary: Origin`, and module scripts are requested with an Origin header that the
// precache requests did not have.
async function cacheFirst(request: Request): Promise<Response> {
  const cached = await caches.match(request, { cacheName: CACHE, ignoreSearch: true, ignoreVary: true });
  if (cached !== undefined) return cached;
  const response = await fetch(request);
  // files that were not precached (e.g. a knowledge base added later) are kept for the next offline visit
  // (never a page sent in place of a missing file by a host's fallback)
  const page = (response.headers.get("content-type") ?? "").includes("text/html");
  if (response.ok && !page && new URL(request.url).origin === sw.location.origin) {
    const copy = response.clone();
    void caches.open(CACHE).then((cache) => cache.put(request, copy));
  }
  return response;
}

sw.addEventListener("fetch", (event) => {
  const request = event.request;
  if (request.method !== "GET" || !request.url.startsWith(sw.registration.scope)) return;
  event.respondWith(request.mode === "navigate" ? networkFirstPage(request) : cacheFirst(request));
});
