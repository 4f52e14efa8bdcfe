// rb's JavaScript API: the core (rbcore.js + rbcore.wasm, built by scripts/web.sh) behind two
// promises, on the page's window.rb and as a node module (require('./rb.js')). docs/web.md.
//
//   await rb.check(source)             -> [{severity, line, col, message, code, text}, ...]
//   await rb.run(source, {stdin, seed, maxSteps, timeout, maxMemory, keys, svg})
//                                      -> {output, error, errorLine, errorMessage, png, svg, status,
//                                          steps, diagnostics, state}
//   rb.start(source, options)          a live run for the page (web/app.js): {done, stop()}
//   rb.stop()                          stops the run in progress (within one slice)
//
// Two builds of the core: rbcore (Asyncify: a live run yields to the page and waits for input,
// keys, clicks, dialogs and Step) for rb.start, and rbcore_fast (no Asyncify, wasm exceptions;
// two to three times as fast) for rb.run, which waits for nothing: on a page it runs in a Web
// Worker (rbworker.js), so the page never freezes and Stop ends the worker; under node it runs
// directly.
(function (global) {
  'use strict';
  const isWorker = typeof importScripts === 'function' && typeof window === 'undefined';
  const isNode = typeof window === 'undefined' && !isWorker;
  // Where the page loaded rb.js from: the worker's script is beside it.
  const scriptBase = typeof document !== 'undefined' && document.currentScript ? document.currentScript.src : '';
  let corePromise = null;
  let fastPromise = null;

  // The browser (V8) runs a wasm function in its baseline tier until it has run for a while,
  // and a call under way never changes tier. The interpreter's loop is one call a run, so a
  // program's whole first run went at baseline speed (matmul: 1.9 s, then 0.6 s a run). A short
  // run as soon as a core is loaded has that loop compiled by the optimizing tier, in the
  // background, before the user's first run.
  const WARM_UP = 'x = 0\nfor i = 1 to 20000\n  x = x + i * 2\nnext\n';

  function core() {
    if (!corePromise) {
      if (isNode) {
        const fs = require('fs'), path = require('path');
        const create = require(path.join(__dirname, 'rbcore.js'));
        corePromise = create({wasmBinary: fs.readFileSync(path.join(__dirname, 'rbcore.wasm'))});
      } else {
        corePromise = global.createRbCore({});
      }
      corePromise.then(() => runWith(WARM_UP, {seed: 1, png: false}, false));  // queued first
    }
    return corePromise;
  }

  // rb.run's core under node.
  function fastCore() {
    if (!fastPromise) {
      const fs = require('fs'), path = require('path');
      const create = require(path.join(__dirname, 'rbcore_fast.js'));
      fastPromise = create({wasmBinary: fs.readFileSync(path.join(__dirname, 'rbcore_fast.wasm'))})
        .then((M) => warmUp(M));
    }
    return fastPromise;
  }

  // A fast core (under node, or in the worker) after its warm-up run.
  function warmUp(M) {
    runHeadless(M, WARM_UP, {seed: 1});
    return M;
  }

  // A turn of the event loop without a timer's clamp.
  const fastYield = isNode
    ? () => new Promise((r) => setImmediate(r))
    : (() => {
        const channel = new MessageChannel();
        const waiting = [];
        channel.port1.onmessage = () => { const r = waiting.shift(); if (r) r(); };
        return () => new Promise((r) => { waiting.push(r); channel.port2.postMessage(0); });
      })();

  function cString(M, s) {
    const size = M.lengthBytesUTF8(s) + 1;
    const p = M._malloc(size);
    M.stringToUTF8(s, p, size);
    return p;
  }
  function takeString(M, p) {
    const s = M.UTF8ToString(p);
    M._free(p);
    return s;
  }

  // ---- PNG: the frame's RGBA pixels, written with the platform's deflate (CompressionStream).
  const crcTable = (() => {
    const t = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      t[n] = c >>> 0;
    }
    return t;
  })();
  function crc32(bytes) {
    let c = 0xffffffff;
    for (let i = 0; i < bytes.length; i++) c = crcTable[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  }
  async function deflate(bytes) {
    const stream = new Blob([bytes]).stream().pipeThrough(new CompressionStream('deflate'));
    return new Uint8Array(await new Response(stream).arrayBuffer());
  }
  async function pngDataUrl(rgba, width, height) {
    const raw = new Uint8Array((width * 3 + 1) * height);
    for (let y = 0, o = 0; y < height; y++) {
      raw[o++] = 0;  // no filter
      for (let x = 0; x < width; x++) {
        const i = (y * width + x) * 4;
        raw[o++] = rgba[i]; raw[o++] = rgba[i + 1]; raw[o++] = rgba[i + 2];
      }
    }
    const chunks = [];
    const chunk = (type, body) => {
      const b = new Uint8Array(12 + body.length);
      const v = new DataView(b.buffer);
      v.setUint32(0, body.length);
      for (let i = 0; i < 4; i++) b[4 + i] = type.charCodeAt(i);
      b.set(body, 8);
      v.setUint32(8 + body.length, crc32(b.subarray(4, 8 + body.length)));
      chunks.push(b);
    };
    const ihdr = new Uint8Array(13);
    const hv = new DataView(ihdr.buffer);
    hv.setUint32(0, width); hv.setUint32(4, height);
    ihdr[8] = 8; ihdr[9] = 2;  // 8 bits, RGB
    chunk('IHDR', ihdr);
    chunk('IDAT', await deflate(raw));
    chunk('IEND', new Uint8Array(0));
    const all = new Uint8Array(8 + chunks.reduce((n, c) => n + c.length, 0));
    all.set([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
    for (let i = 0, o = 8; i < chunks.length; o += chunks[i].length, i++) all.set(chunks[i], o);
    let bin = '';
    for (let i = 0; i < all.length; i += 0x8000) bin += String.fromCharCode.apply(null, all.subarray(i, i + 0x8000));
    return 'data:image/png;base64,' + (isNode ? Buffer.from(all).toString('base64') : btoa(bin));
  }

  // ---- runs: one at a time (the core has one suspended run at most); later ones queue.
  let queue = Promise.resolve();
  let current = null;  // {stopped}

  const noInput = {
    inputLine: async () => null,
    heldKey: () => 0,
    waitKey: async () => 0,
    mouse: () => [0, 0, 0],
    takeClick: () => null,
    waitClick: async () => [0, 0, 0],
    messageBox: async () => {},
    takeTyped: () => 0,
    controls: () => {},
    serialOpen: async () => ({error: 'no serial port here'}),
    serialSend: async () => false,
    serialTake: async () => null,
    serialClose: () => {},
    state: () => {},
  };

  // What rb.run's options may carry into a worker.
  function runOptions(options) {
    return {stdin: options.stdin || [], seed: options.seed, maxSteps: options.maxSteps, timeout: options.timeout,
            maxMemory: options.maxMemory, keys: options.keys || '', svg: !!options.svg};
  }

  // What a run hands the page through its hooks: the output, the last frame, the final SVG.
  function collector(M, onOutput, onFrame) {
    const got = {output: '', frame: null, svg: null};
    got.hooks = {
      output: (text) => { got.output += text; if (onOutput) onOutput(text); },
      frame: (p, w, h) => {
        got.frame = {rgba: new Uint8ClampedArray(M.HEAPU8.subarray(p, p + w * h * 4)), width: w, height: h};
        if (onFrame) onFrame(got.frame);
      },
      svg: (text, rgba, width, height) => { got.svg = {text, rgba, width, height}; },
    };
    return got;
  }

  // rb_run's arguments for a run of `source` (api.cpp): the strings are copied into the core
  // and free() releases them.
  const RUN_TYPES = Array(9).fill('number');
  function runArgs(M, source, options, live) {
    const stdin = (options.stdin || []).map((l) => String(l) + '\n').join('');
    const seed = options.seed !== undefined ? Number(options.seed) : Math.floor(Math.random() * 2 ** 32);
    const strings = [cString(M, source), cString(M, stdin), cString(M, options.keys || '')];
    return {
      values: [...strings, seed, options.maxSteps || 0, options.timeout || 0,
               options.maxMemory !== undefined ? options.maxMemory : 1024, live ? 1 : 0, options.svg ? 1 : 0],
      free: () => strings.forEach((p) => M._free(p)),
    };
  }

  // A headless run on rbcore_fast (in the worker, or under node): {result, output, frame, svg}.
  function runHeadless(M, source, options) {
    const got = collector(M);
    M.rbHooks = Object.assign({}, noInput, got.hooks, {stopped: () => false, stepMs: () => 0, stepping: () => false});
    const args = runArgs(M, source, options, false);
    try {
      const result = JSON.parse(takeString(M, M.ccall('rb_run', 'number', RUN_TYPES, args.values)));
      return {result, output: got.output, frame: got.frame, svg: got.svg};
    } finally {
      args.free();
    }
  }

  // The final screen as SVG (options.svg): the host's SVG, with the PNG of the screen's pixels
  // where it embeds them (WebHost::presentSvg).
  async function svgText(svg) {
    if (!svg) return null;
    if (!svg.rgba) return svg.text;
    const href = await pngDataUrl(svg.rgba, svg.width, svg.height);
    return svg.text.replace('xlink:href="rb:screen.png"', () => `xlink:href="${href}"`);
  }

  // The result as rb.run and rb.start give it: the output, the error's text and line, the
  // final frame and its PNG, and the SVG when asked for (`got`: what the run's hooks collected).
  async function finish(result, got, options) {
    const {output, frame, svg} = got;
    const errors = (result.diagnostics || []).filter((d) => d.severity === 'error');
    let error = null;
    if (result.error) error = result.error.text || result.error.message;
    else if (result.status === 'rejected') error = errors.map((d) => d.text).join('');
    const first = result.error || errors[0];
    return Object.assign(result, {
      output,
      error,
      errorMessage: first ? first.message : null,
      errorLine: result.error ? result.error.line : errors.length ? errors[0].line : null,
      frame,
      png: frame && options.png !== false ? await pngDataUrl(frame.rgba, frame.width, frame.height) : null,
      svg: options.svg ? await svgText(svg) : null,
    });
  }

  // rb.run on a page: one worker, made when first needed; Stop ends it (the next run makes
  // another).
  let worker = null;
  let workerJob = null;  // {resolve}
  function workerRun(source, options) {
    return new Promise((resolve, reject) => {
      if (!worker) worker = new Worker(new URL('rbworker.js', scriptBase || global.location.href));
      workerJob = {resolve};
      worker.onmessage = (e) => { workerJob = null; resolve(e.data); };
      worker.onerror = (e) => {
        workerJob = null;
        worker.terminate();
        worker = null;
        reject(new Error(e.message || 'the run failed'));
      };
      worker.postMessage({source, options: runOptions(options)});
    });
  }
  function stopWorker() {
    if (!workerJob) return false;
    const job = workerJob;
    workerJob = null;
    worker.terminate();
    worker = null;
    job.resolve({result: {status: 'stopped', steps: 0, diagnostics: []}, output: '', frame: null});
    return true;
  }

  // Runs `source`; `live`: the page's live run with its hooks (see web/app.js).
  function runWith(source, options, live) {
    const state = {stopped: false, wake: new Set()};
    const job = queue.then(async () => {
      const M = await core();
      current = {stop: () => { state.stopped = true; [...state.wake].forEach((w) => w()); }};
      const got = collector(M, options.onOutput, options.onFrame);
      const io = Object.assign({}, noInput, options.io || {});
      M.rbHooks = Object.assign({}, io, got.hooks, {
        stopped: () => state.stopped,
        stepMs: () => (options.stepMs ? options.stepMs() : 0),
        // Stepping (live runs, compiled with a hook before each statement): the host asks
        // stepping() whenever it has been to the page, and while it is true waits in
        // atLine(line) before each statement of the program's file.
        stepping: () => (options.stepping ? options.stepping() : false),
        atLine: (line) => (options.atLine ? options.atLine(line) : Promise.resolve()),
        // The state the page's text alternative of the screen reads (WebHost::stateJson): sent
        // when it changed, at most every 250 ms, and whenever the run waits for the page.
        state: (json) => { if (options.onState) options.onState(JSON.parse(json)); },
        // A sleep ends early when the run is stopped.
        yield: (options.wrapYield || ((f) => f))((ms) => (ms > 0 ? new Promise((r) => {
          const done = () => { clearTimeout(timer); state.wake.delete(done); r(); };
          const timer = setTimeout(done, ms);
          state.wake.add(done);
        }) : fastYield())),
      });
      const args = runArgs(M, source, options, live);
      let result;
      try {
        result = JSON.parse(takeString(M, await M.ccall('rb_run', 'number', RUN_TYPES, args.values, {async: true})));
      } finally {
        args.free();
        current = null;
      }
      return finish(result, got, options);
    });
    queue = job.catch(() => {});
    const stop = () => { state.stopped = true; [...state.wake].forEach((w) => w()); };
    return {done: job, stop, state};
  }

  const rb = {
    // The core takes no call while a run is suspended in it: a check waits for the runs
    // before it.
    async check(source) {
      await queue;
      const M = await core();
      const p = cString(M, source);
      try {
        return JSON.parse(takeString(M, M.ccall('rb_check', 'number', ['number'], [p])));
      } finally {
        M._free(p);
      }
    },
    run(source, options = {}) {
      const job = queue.then(async () => {
        const raw = isNode ? runHeadless(await fastCore(), source, options) : await workerRun(source, options);
        return finish(raw.result, raw, options);
      });
      queue = job.catch(() => {});
      return job;
    },
    start(source, options = {}) {
      return runWith(source, options, true);
    },
    stop() {
      if (stopWorker()) return;
      if (current) current.stop();
    },
    ready() {
      return core().then(() => true);
    },
    pngDataUrl,
    runHeadless,  // for rbworker.js
    warmUp,
  };

  if (isNode) module.exports = rb;
  else global.rb = rb;
})(typeof window !== 'undefined' ? window : globalThis);
