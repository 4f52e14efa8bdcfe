// rb's JavaScript API: the core (rbcore.js + rbcore.wasm, built by scripts/web.sh) behind two
// promises, on the page's window.rb and as a node module (require('./rb.js')). docs/web.md.
//
//   await rb.check(source)             -> [{severity, line, col, message, code, text}, ...]
//   await rb.run(source, {stdin, seed, maxSteps, timeout, maxMemory, keys, svg})
//                                      -> {output, error, errorLine, errorMessage, png, svg, status,
//                                          steps, diagnostics, state}
//   rb.start(source, options)          a live run for the page (web/app.js): {done, stop(), ...}
//   rb.stop()                          stops the run in progress
//
// Two builds of the core: rbcore_fast (no Asyncify, wasm exceptions; two to three times as
// fast) and rbcore (Asyncify: a run can yield to its thread's event loop and wait there).
// Nothing runs a program on the page's thread, so the page never freezes:
// - rb.run waits for nothing: on a page it runs on rbcore_fast in a Web Worker (rbworker.js),
//   and Stop ends the worker; under node it runs directly. rb.check runs on the page's thread
//   (a check takes milliseconds).
// - rb.start (the page's Run) runs in a Web Worker of its own (rblive.js). When the page is
//   cross-origin isolated (its service worker adds the headers, web/sw.js), on rbcore_fast: the
//   run waits synchronously (Atomics.wait) for what the page sends through a SharedArrayBuffer
//   (keys, clicks, the answers to input and dialogs, Pause, Step, Stop). Otherwise (the first
//   visit, before the service worker is in control) on rbcore, which yields to the worker's
//   event loop every few milliseconds, where the same things arrive as messages.
(function (global) {
  'use strict';
  const isWorker = typeof importScripts === 'function' && typeof window === 'undefined';
  const isNode = typeof window === 'undefined' && !isWorker;
  // Where the page loaded rb.js from: the workers' scripts are beside it.
  const scriptBase = typeof document !== 'undefined' && document.currentScript ? document.currentScript.src : '';
  let corePromise = null;

  // The browser (V8) runs a wasm function in its baseline tier until it has run for a while,
  // and a call under way never changes tier. The interpreter's loop is one call a run, so a
  // program's whole first run went at baseline speed (matmul: 1.9 s, then 0.6 s a run). A short
  // run as soon as a core is loaded has that loop compiled by the optimizing tier, in the
  // background, before the user's first run.
  const WARM_UP = 'x = 0\nfor i = 1 to 20000\n  x = x + i * 2\nnext\n';

  // The core of rb.check (on the page's thread) and, under node, of rb.run: rbcore_fast.
  function core() {
    if (!corePromise) {
      if (isNode) {
        const fs = require('fs'), path = require('path');
        const create = require(path.join(__dirname, 'rbcore_fast.js'));
        corePromise = create({wasmBinary: fs.readFileSync(path.join(__dirname, 'rbcore_fast.wasm'))})
          .then((M) => warmUp(M));
      } else {
        corePromise = global.createRbCoreFast({});
      }
    }
    return corePromise;
  }

  // A fast core (under node, or in the worker) after its warm-up run.
  function warmUp(M) {
    runHeadless(M, WARM_UP, {seed: 1});
    return M;
  }

  // A hook's answer or a promise of it, then f of it (web/host/web_host.cpp: the same hooks
  // serve both builds).
  function then(value, f) {
    return value && typeof value.then === 'function' ? value.then(f) : f(value);
  }

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

  // ---- runs
  let queue = Promise.resolve();  // rb.run's: one at a time

  const noInput = {
    inputLine: () => null,
    heldKey: () => 0,
    waitKey: () => 0,
    mouse: () => [0, 0, 0],
    takeClick: () => null,
    waitClick: () => [0, 0, 0],
    messageBox: () => {},
    takeTyped: () => 0,
    controls: () => {},
    pause: () => 0,
    watches: () => '',
    yield: () => {},
    serialOpen: () => ({error: 'no serial port here'}),
    serialSend: () => false,
    serialTake: () => null,
    serialClose: () => {},
    state: () => {},
  };

  // What rb.run's options may carry into a worker.
  function runOptions(options) {
    return {stdin: options.stdin || [], seed: options.seed, maxSteps: options.maxSteps, timeout: options.timeout,
            maxMemory: options.maxMemory, keys: options.keys || '', svg: !!options.svg};
  }

  // What a run hands over through its hooks: the output, the last frame, the final SVG.
  function collector(M) {
    const got = {output: '', frame: null, svg: null};
    got.hooks = {
      output: (text) => { got.output += text; },
      frame: (p, w, h) => {
        got.frame = {rgba: new Uint8ClampedArray(M.HEAPU8.subarray(p, p + w * h * 4)), width: w, height: h};
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
    M.rbThen = then;
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
      errorDiagnostic: result.error && result.error.line ? result.error : null,
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

  // ---- the page's live runs (rb.start): a worker of their own (rblive.js), on rbcore_fast
  // with a SharedArrayBuffer when the page is cross-origin isolated, else on rbcore with
  // messages (see the top). What the page sends (LIVE: the layout of the shared Int32Array):
  // fields it sets (the held key, the mouse, Stop, stepping and Step, the speed), events it
  // queues in a ring (key presses, clicks, keys typed into an edit box), the answers to the
  // run's calls (input lines, dialogs, the serial port) and the watch expressions.
  const LIVE = {
    SEQ: 0, STOP: 1, STEPPING: 2, STEPGO: 3, STEPUS: 4, HELD: 5, MX: 6, MY: 7, MB: 8, WIDX: 9, RIDX: 10,
    ANSWER_ID: 11, ANSWER_LEN: 12, REFRESH: 13, WATCH_LEN: 14, DRAWN: 15,
    RING: 64, RING_N: 256,                 // events: 4 ints each (kind, a, b, c)
    ANSWER_AT: 8192, ANSWER_MAX: 24576,    // bytes: the last answer, JSON
    WATCH_AT: 32768, WATCH_MAX: 16384,     // bytes: the watch expressions, one a line
    BYTES: 65536,
    KEY: 1, CLICK: 2, TYPED: 3,
  };
  // How long a stopped run has to end by itself before its worker is ended (a single statement
  // that takes long: a huge array, a long string operation).
  const STOP_GRACE_MS = 120;
  // The live run's output kept in its result (the page shows it as it comes).
  const LIVE_OUTPUT_KEEP = 1 << 20;

  const liveMode = () => (!isNode && typeof SharedArrayBuffer === 'function' && global.crossOriginIsolated ? 'sab' : 'async');
  let spare = null;  // a live worker loaded and warmed up, for the next run: {worker, mode, ready}
  function liveWorker() {
    const mode = liveMode();
    const w = new Worker(new URL('rblive.js', scriptBase || global.location.href));
    const entry = {worker: w, mode};
    entry.ready = new Promise((resolve, reject) => {
      const ready = (e) => {
        if (e.data.type !== 'ready') return;
        w.removeEventListener('message', ready);
        resolve(entry);
      };
      w.addEventListener('message', ready);
      w.addEventListener('error', (e) => reject(new Error(e.message || 'the live worker failed to load')));
    });
    entry.ready.catch(() => {});
    w.postMessage({type: 'init', mode});
    return entry;
  }
  function takeLiveWorker() {
    const w = spare || liveWorker();
    spare = null;
    return w;
  }

  let liveRun = null;  // the run in progress
  let runCount = 0;
  function startLive(source, options) {
    const runId = ++runCount;  // the worker tags each message with its run: a worker kept for
                               // the next run still sends the last one's SVG and 'idle'
    const entry = takeLiveWorker();
    const {worker: w, mode} = entry;
    const shared = mode === 'sab' ? new SharedArrayBuffer(LIVE.BYTES) : null;
    const ctrl = shared ? new Int32Array(shared) : null;
    const io = Object.assign({}, noInput, options.io || {});
    const got = {output: '', frame: null, svg: null};
    let settled = false, resolveDone, rejectDone, stopTimer = 0, framesGot = 0, ackFrame = 0;
    let typedSent = 0;  // keys sent for an edit box (run.typed)
    const done = new Promise((res, rej) => { resolveDone = res; rejectDone = rej; });

    // In message mode what is sent before the run has begun goes with its start message.
    let begun = false;
    const pending = [];
    const post = (m) => { if (settled) return; if (begun) w.postMessage(m); else pending.push(m); };
    const wake = () => { Atomics.add(ctrl, LIVE.SEQ, 1); Atomics.notify(ctrl, LIVE.SEQ); };
    const set = (i, v, notify) => {
      if (!ctrl) return post({type: 'set', i, v});
      Atomics.store(ctrl, i, v);
      if (notify) wake();
    };
    const add = (i) => {
      if (!ctrl) return post({type: 'add', i});
      Atomics.add(ctrl, i, 1);
      wake();
    };
    // Queues an event for the run; false when dropped (the run takes none).
    const event = (kind, a, b, c) => {
      if (!ctrl) { post({type: 'event', kind, a, b, c}); return !settled; }
      const widx = Atomics.load(ctrl, LIVE.WIDX);
      if (widx - Atomics.load(ctrl, LIVE.RIDX) >= LIVE.RING_N) return false;
      const o = LIVE.RING + (widx % LIVE.RING_N) * 4;
      ctrl[o] = kind; ctrl[o + 1] = a | 0; ctrl[o + 2] = b | 0; ctrl[o + 3] = c | 0;
      Atomics.store(ctrl, LIVE.WIDX, widx + 1);
      wake();
      return true;
    };
    const bytes = (text, at, max) => {
      let b = new TextEncoder().encode(text);
      if (b.length > max) b = b.subarray(0, max);
      new Uint8Array(shared, at, b.length).set(b);
      return b.length;
    };
    const answer = (id, value) => {
      if (!id || settled) return;
      const text = JSON.stringify(value === undefined ? null : value);
      if (!ctrl) return post({type: 'answer', id, text});
      Atomics.store(ctrl, LIVE.ANSWER_LEN, bytes(text, LIVE.ANSWER_AT, LIVE.ANSWER_MAX));
      Atomics.store(ctrl, LIVE.ANSWER_ID, id);
      wake();
    };
    const setWatches = (list) => {
      const text = (list || []).join('\n');
      if (!ctrl) return post({type: 'watches', text});
      Atomics.store(ctrl, LIVE.WATCH_LEN, bytes(text, LIVE.WATCH_AT, LIVE.WATCH_MAX));
    };

    const end = (result) => {
      if (settled) return;
      settled = true;
      clearTimeout(stopTimer);
      if (liveRun === run) liveRun = null;
      resolveDone(result);
    };
    w.onmessage = (e) => {
      const m = e.data;
      if (settled || m.run !== runId) return;
      switch (m.type) {
        case 'output':
          got.output += m.text;
          if (got.output.length > 2 * LIVE_OUTPUT_KEEP) got.output = got.output.slice(-LIVE_OUTPUT_KEEP);
          if (options.onOutput) options.onOutput(m.text);
          break;
        case 'frame':
          got.frame = m.frame;
          if (options.onFrame) options.onFrame(m.frame);
          // Drawn with the page's next frame: the run may send another (WebHost::present).
          framesGot++;
          if (!ackFrame) ackFrame = requestAnimationFrame(() => { ackFrame = 0; set(LIVE.DRAWN, framesGot, false); });
          break;
        // The second argument: how many of the keys sent for an edit box the core had not
        // taken yet when it showed these controls.
        case 'controls': io.controls(m.controls, typedSent - m.typed); break;
        case 'waiting': if (options.onWaiting) options.onWaiting(m.what); break;
        case 'paused': if (options.onPaused) options.onPaused(m.info); break;
        case 'resumed': if (options.onResumed) options.onResumed(); break;
        // The state the page's text alternative of the screen reads (WebHost::stateJson): sent
        // when it changed, at most every 250 ms, and whenever the run waits for the page.
        case 'state': if (options.onState) options.onState(JSON.parse(m.json)); break;
        case 'call':
          Promise.resolve().then(() => io[m.name](...m.args))
            .then((v) => answer(m.id, v instanceof Uint8Array ? Array.from(v) : v), () => answer(m.id, null));
          break;
        case 'failed':
          w.terminate();
          end(finishedBadly(got, 'error', 'the run failed: ' + m.message));
          break;
        case 'done':
          if (got.output.length > LIVE_OUTPUT_KEEP) got.output = got.output.slice(-LIVE_OUTPUT_KEEP);
          settled = true;
          clearTimeout(stopTimer);
          if (liveRun === run) liveRun = null;
          // The worker takes the next run once it has made this one's SVG.
          if (!spare) { spare = entry; kept = true; }
          finish(m.result, got, Object.assign({}, options, {svg: false})).then(resolveDone, rejectDone);
          break;
      }
    };
    // After the run's end: its SVG (options.svg), made after the page heard of the end, and the
    // worker free again (kept for the next run).
    w.addEventListener('message', function after(e) {
      if (e.data.run !== runId) return;
      if (e.data.type === 'svg') {
        if (options.onSvg) svgText(e.data.svg).then((text) => options.onSvg(text));
      } else if (e.data.type === 'idle') {
        w.removeEventListener('message', after);
        if (!kept && !killed) w.terminate();
      }
    });
    w.onerror = (e) => {
      e.preventDefault();
      w.terminate();
      end(finishedBadly(got, 'error', 'the run failed: ' + (e.message || 'the worker stopped')));
    };
    // A run stopped where it does not look at Stop (one long statement): its worker is ended.
    let killed = false, kept = false;
    const kill = () => {
      if (settled) return;
      killed = true;
      w.terminate();
      if (!spare) spare = liveWorker();
      end(finishedBadly(got, 'stopped', null));
    };

    const run = {
      done,
      mode,
      stop() {
        if (settled) return;
        set(LIVE.STOP, 1, true);
        if (!stopTimer) stopTimer = setTimeout(kill, STOP_GRACE_MS);
      },
      // Pause: the run stops before its next statement (or inside a robot motion or a delay);
      // Step: one more statement; Resume: on without stopping.
      pause() { set(LIVE.STEPPING, 1, true); },
      resume() { set(LIVE.STEPPING, 0, true); },
      step() { set(LIVE.STEPPING, 1, false); add(LIVE.STEPGO); },
      refresh() { add(LIVE.REFRESH); },
      setWatches,
      setSpeed(ms) { set(LIVE.STEPUS, Math.round(Math.max(0, ms) * 1000), false); },
      keyDown(code) { set(LIVE.HELD, code, false); event(LIVE.KEY, code, 0, 0); },
      keyUp() { set(LIVE.HELD, 0, false); },
      mouse(x, y, b) { set(LIVE.MX, x, false); set(LIVE.MY, y, false); set(LIVE.MB, b, false); },
      click(x, y, b) { run.mouse(x, y, b); event(LIVE.CLICK, x, y, b); },
      typed(code) { if (event(LIVE.TYPED, code, 0, 0)) typedSent++; },
    };
    liveRun = run;
    run.setSpeed(options.stepMs ? Number(options.stepMs) : 0);
    if (options.stepping) set(LIVE.STEPPING, 1, false);
    setWatches(options.watches || []);
    entry.ready.then(() => {
      if (settled) return;
      w.postMessage({type: 'run', id: runId, source, shared, options: runOptions(options), before: pending.splice(0)});
      begun = true;
    }, (e) => end(finishedBadly(got, 'error', e.message)));
    return run;
  }

  // A live run that ended without the core's result (its worker was ended).
  function finishedBadly(got, status, error) {
    return {status, error, errorLine: null, steps: null, diagnostics: [], output: got.output, frame: got.frame,
            png: null, svg: null};
  }

  let builtinsPromise = null;
  const rb = {
    // The built-in table (api.cpp's rb_builtins: name, kind, group, usage, help, value, tier and
    // evidence), what the page's help shows (web/help.mjs).
    builtins() {
      if (!builtinsPromise) {
        builtinsPromise = core().then((M) => JSON.parse(takeString(M, M.ccall('rb_builtins', 'number', [], []))));
      }
      return builtinsPromise;
    },
    async check(source) {
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
        const raw = isNode ? runHeadless(await core(), source, options) : await workerRun(source, options);
        return finish(raw.result, raw, options);
      });
      queue = job.catch(() => {});
      return job;
    },
    // options: {io: {inputLine, messageBox, controls, serialOpen, serialSend, serialTake,
    // serialClose}, onOutput, onFrame, onPaused, onResumed, onWaiting, onSvg, onState, stepMs, stepping,
    // watches, seed, maxSteps, timeout, maxMemory, svg, png}. The result's svg is null: with
    // options.svg the SVG comes after the end, to onSvg(text).
    start(source, options = {}) {
      if (isNode || isWorker) throw new Error('rb.start runs on a page');
      return startLive(source, options);
    },
    stop() {
      if (stopWorker()) return;
      if (liveRun) liveRun.stop();
    },
    ready() {
      return core().then(() => true);
    },
    // Loads a live worker ahead of the first Run ('sab' or 'async': how it will run).
    prepare() {
      if (!isNode && !isWorker && !spare) spare = liveWorker();
      return spare ? spare.ready.then((e) => e.mode) : Promise.resolve(null);
    },
    get liveMode() { return liveMode(); },
    pngDataUrl,
    // for the workers (rbworker.js, rblive.js)
    runHeadless,
    warmUp,
    internals: {then, runArgs, takeString, noInput, RUN_TYPES, WARM_UP, LIVE},
  };

  if (isNode) module.exports = rb;
  else global.rb = rb;
})(typeof window !== 'undefined' ? window : globalThis);
