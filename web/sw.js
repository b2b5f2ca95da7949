// The page's service worker: on the first visit it keeps every file of the page (the page, the
// style, every module, the WebAssembly) in a cache named by the build, so that afterwards the
// page, every view and every command work with no network, a reload included. Files whose
// names carry the build's hash never change and are answered from the cache; the page itself
// is asked of the network first (a new build is seen at once) and answered from the cache when
// the network fails. web/build.sh writes the build and the list of files below.

const BUILD = "__BUILD__";
const FILES = __FILES__;
const CACHE = `cagd-${BUILD}`;
const HASHED = /\.[0-9a-f]{8,64}\.[a-z]+$/;

self.addEventListener("install", (event) => {
  // The files come from the browser's HTTP cache when the page has just loaded them (their
  // names are hashed and immutable), so keeping them costs no second download.
  event.waitUntil(
    caches
      .open(CACHE)
      .then((cache) => cache.addAll(FILES))
      .then(() => self.skipWaiting()),
  );
});

self.addEventListener("activate", (event) => {
  event.waitUntil(
    caches
      .keys()
      .then((names) => Promise.all(names.filter((n) => n.startsWith("cagd-") && n !== CACHE).map((n) => caches.delete(n))))
      .then(() => self.clients.claim()),
  );
});

async function fromNetwork(request) {
  const response = await fetch(request);
  if (response.ok && response.type === "basic") {
    const copy = response.clone();
    caches.open(CACHE).then((cache) => cache.put(request, copy));
  }
  return response;
}

self.addEventListener("fetch", (event) => {
  const request = event.request;
  const url = new URL(request.url);
  if (request.method !== "GET" || url.origin !== self.location.origin) return;
  if (HASHED.test(url.pathname)) {
    event.respondWith(caches.match(request).then((hit) => hit ?? fromNetwork(request)));
    return;
  }
  event.respondWith(
    fromNetwork(request).catch(async () => {
      const hit = (await caches.match(request, { ignoreSearch: true })) ?? (request.mode === "navigate" ? await caches.match("./") : undefined);
      if (hit) return hit;
      throw new Error(`offline and not cached: ${url.pathname}`);
    }),
  );
});
