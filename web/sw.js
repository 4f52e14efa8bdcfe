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
// from the network.
self.addEventListener('fetch', (e) => {
  if (e.request.method !== 'GET') return;
  e.respondWith(caches.open(CACHE)
    .then((c) => c.match(e.request, {ignoreSearch: true}))
    .then((hit) => hit || fetch(e.request)));
});
