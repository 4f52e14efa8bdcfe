// The page's service worker: the browser keeps the site's files once the page has loaded, so the
// page works offline, a reload too (docs/web.md). scripts/web.sh fills in the files and a version
// made from their contents: a new build is a new cache, and the old one is dropped.
'use strict';
const VERSION = '@VERSION@';
const FILES = @FILES@;
const CACHE = 'rb-site-' + VERSION;

self.addEventListener('install', (e) => {
  e.waitUntil(caches.open(CACHE).then((c) => c.addAll(FILES)).then(() => self.skipWaiting()));
});
self.addEventListener('activate', (e) => {
  e.waitUntil(caches.keys()
    .then((keys) => Promise.all(keys.filter((k) => k.startsWith('rb-site-') && k !== CACHE).map((k) => caches.delete(k))))
    .then(() => self.clients.claim()));
});
// The site's files from the cache (a share link's fragment never reaches here); anything else
// from the network. Every answer of the site's own gets the headers that make the page
// cross-origin isolated (COOP and COEP; static hosts such as GitHub Pages cannot send them), so
// that the page may share memory with the worker of its live runs (web/rblive.js); files from
// elsewhere are not the page's to change.
const ISOLATION = {
  'Cross-Origin-Opener-Policy': 'same-origin',
  'Cross-Origin-Embedder-Policy': 'require-corp',
  'Cross-Origin-Resource-Policy': 'same-origin',
};
function isolated(response) {
  if (!response || response.type === 'opaque' || response.status === 0) return response;
  const headers = new Headers(response.headers);
  for (const [k, v] of Object.entries(ISOLATION)) headers.set(k, v);
  return new Response(response.body, {status: response.status, statusText: response.statusText, headers});
}
self.addEventListener('fetch', (e) => {
  if (e.request.method !== 'GET') return;
  const own = new URL(e.request.url).origin === self.location.origin;
  e.respondWith(caches.open(CACHE)
    .then((c) => c.match(e.request, {ignoreSearch: true}))
    .then((hit) => hit || fetch(e.request))
    .then((r) => (own ? isolated(r) : r)));
});
