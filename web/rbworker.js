// rb.run's runs on a page (web/rb.js): rb's core without Asyncify (rbcore_fast) in a Web Worker,
// so that a long run never freezes the page; rb.stop() ends the worker.
importScripts('rbcore_fast.js', 'rb.js');
let core = null;
onmessage = async (e) => {
  if (!core) core = self.rb.warmUp(await createRbCoreFast({}));
  const r = self.rb.runHeadless(core, e.data.source, e.data.options);
  postMessage(r, [r.frame && r.frame.rgba.buffer, r.svg && r.svg.rgba && r.svg.rgba.buffer].filter(Boolean));
};
