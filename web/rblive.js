// The page's live runs (rb.start in web/rb.js) in a Web Worker of their own, so that a run never
// holds up the page: it draws, takes keys and clicks, and ends a run on Stop whatever the
// program does. Two ways, chosen by the page when it makes the worker (docs/web.md):
//   'sab'    the page is cross-origin isolated: rbcore_fast runs the program in one call; the
//            hooks read what the page sets in a SharedArrayBuffer and wait with Atomics.wait.
//   'async'  otherwise: rbcore (Asyncify) yields to this worker's event loop every few
//            milliseconds, and the page's messages update a plain copy of the same fields.
// The hooks (Module.rbHooks, called by web/host/web_host.cpp) are the same code for both: a
// waiting hook's answer is a value in 'sab' mode and a promise of it in 'async' mode.
'use strict';
importScripts('rb.js');
const {then, runArgs, takeString, noInput, RUN_TYPES, WARM_UP, LIVE} = self.rb.internals;

let M = null;
let mode = 'async';
let ctrl = new Int32Array(LIVE.BYTES / 4);  // shared in 'sab' mode
let shared = null;
let answerText = '';  // 'async' mode: the last answer
let watchText = '';   // 'async' mode: the watch expressions
const waiters = new Set();  // 'async' mode: blocked hooks, checked after each message

// ---- what the page sends
let readIdx = 0;
let keyCount = 0, lastKey = 0;
let clicks = [], typed = [];
function drain() {
  const widx = Atomics.load(ctrl, LIVE.WIDX);
  while (readIdx < widx) {
    const o = LIVE.RING + (readIdx % LIVE.RING_N) * 4;
    const kind = ctrl[o], a = ctrl[o + 1], b = ctrl[o + 2], c = ctrl[o + 3];
    readIdx++;
    if (kind === LIVE.KEY) { keyCount++; lastKey = a; }
    else if (kind === LIVE.CLICK) { if (clicks.length < 64) clicks.push([a, b, c]); }
    else if (kind === LIVE.TYPED) { if (typed.length < 256) typed.push(a); }
  }
  Atomics.store(ctrl, LIVE.RIDX, readIdx);
}
const stopped = () => Atomics.load(ctrl, LIVE.STOP) !== 0;
const stepping = () => Atomics.load(ctrl, LIVE.STEPPING) !== 0;

// Waits until ready() (or `ms` have passed; ms < 0: no limit), then gives then().
function block(ready, ms, after) {
  const end = ms >= 0 ? performance.now() + ms : Infinity;
  if (mode === 'sab') {
    for (;;) {
      const seq = Atomics.load(ctrl, LIVE.SEQ);
      if (ready()) return after();
      const left = end - performance.now();
      if (left <= 0) return after();
      Atomics.wait(ctrl, LIVE.SEQ, seq, Math.min(left, 250));
    }
  }
  if (ready() || end <= performance.now()) return after();
  return new Promise((resolve) => {
    let timer = 0;
    const check = (timedOut) => {
      if (!ready() && !timedOut) return;
      waiters.delete(check);
      clearTimeout(timer);
      resolve(after());
    };
    waiters.add(check);
    if (ms >= 0) timer = setTimeout(() => check(true), ms);
  });
}

// A turn of the event loop without a timer's clamp ('async' mode).
const fastYield = (() => {
  const channel = new MessageChannel();
  const waiting = [];
  channel.port1.onmessage = () => { const r = waiting.shift(); if (r) r(); };
  return () => new Promise((r) => { waiting.push(r); channel.port2.postMessage(0); });
})();

// A call the page answers (an input line, a dialog, the serial port): null when the run is
// stopped first.
let callId = 0;
function call(name, args) {
  const id = ++callId;
  postMessage({type: 'call', id, name, args});
  return block(() => stopped() || Atomics.load(ctrl, LIVE.ANSWER_ID) === id, -1, () => {
    if (Atomics.load(ctrl, LIVE.ANSWER_ID) !== id) return null;
    if (mode !== 'sab') return JSON.parse(answerText);
    const n = Atomics.load(ctrl, LIVE.ANSWER_LEN);
    return JSON.parse(new TextDecoder().decode(new Uint8Array(shared, LIVE.ANSWER_AT, n).slice()));
  });
}
function watches() {
  if (mode !== 'sab') return watchText;
  const n = Atomics.load(ctrl, LIVE.WATCH_LEN);
  return new TextDecoder().decode(new Uint8Array(shared, LIVE.WATCH_AT, n).slice());
}
function waiting(what) {
  postMessage({type: 'waiting', what});
}

let pauseGo = null;  // STEPGO when the current pause began
let framesSent = 0;
let svg = null;
const hooks = {
  output: (text) => postMessage({type: 'output', text}),
  frame: (p, w, h) => {
    const rgba = new Uint8ClampedArray(M.HEAPU8.subarray(p, p + w * h * 4));
    framesSent++;
    postMessage({type: 'frame', frame: {rgba, width: w, height: h}}, [rgba.buffer]);
  },
  // The page draws one frame in each of its own: one more may wait there, not a heap of them.
  frameWanted: () => framesSent - Atomics.load(ctrl, LIVE.DRAWN) < 2,
  svg: (text, rgba, width, height) => {
    svg = {text, rgba, width, height};
    postMessage({type: 'svg', svg}, rgba ? [rgba.buffer] : []);
  },
  // The run has ended (the SVG comes after).
  finished: (json) => postMessage({type: 'done', result: JSON.parse(json)}),
  controls: (c) => postMessage({type: 'controls', controls: c}),
  stopped,
  stepMs: () => Atomics.load(ctrl, LIVE.STEPUS) / 1000,
  stepping,
  // ms > 0: a delay (ended early by Stop); 0: a turn of the event loop ('async' mode only).
  yield: (ms) => (ms > 0 ? block(stopped, ms, () => undefined) : mode === 'sab' ? undefined : fastYield()),
  heldKey: () => Atomics.load(ctrl, LIVE.HELD),
  mouse: () => [Atomics.load(ctrl, LIVE.MX), Atomics.load(ctrl, LIVE.MY), Atomics.load(ctrl, LIVE.MB)],
  takeClick: () => { drain(); return clicks.shift() || null; },
  takeTyped: () => { drain(); return typed.shift() || 0; },
  waitKey: () => {
    drain();
    const held = Atomics.load(ctrl, LIVE.HELD);
    if (held) return held;
    const n = keyCount;
    waiting('key');
    return block(() => { drain(); return stopped() || keyCount !== n; }, -1, () => {
      waiting('');
      return stopped() ? 0 : lastKey;
    });
  },
  waitClick: () => {
    drain();
    if (clicks.length) return clicks.shift();
    waiting('click');
    return block(() => { drain(); return stopped() || clicks.length > 0; }, -1, () => {
      waiting('');
      return clicks.shift() || [0, 0, 0];
    });
  },
  inputLine: (prompt) => call('inputLine', [prompt]),
  messageBox: (text, title) => call('messageBox', [text, title]),
  serialOpen: (n) => call('serialOpen', [n]),
  serialSend: (code, param) => call('serialSend', [code, param]),
  serialTake: (want, ms, room) => then(call('serialTake', [want, ms, room]), (a) => (a ? new Uint8Array(a) : null)),
  serialClose: () => postMessage({type: 'call', id: 0, name: 'serialClose', args: []}),
  // Paused: the page shows `info`; 1 when it asks for a fresh look (the watches changed).
  pause: (info) => {
    if (pauseGo === null) pauseGo = Atomics.load(ctrl, LIVE.STEPGO);
    const refresh = Atomics.load(ctrl, LIVE.REFRESH);
    postMessage({type: 'paused', info: JSON.parse(info)});
    return block(() => stopped() || !stepping() || Atomics.load(ctrl, LIVE.STEPGO) !== pauseGo ||
                        Atomics.load(ctrl, LIVE.REFRESH) !== refresh, -1, () => {
      const again = !stopped() && stepping() && Atomics.load(ctrl, LIVE.STEPGO) === pauseGo ? 1 : 0;
      if (!again) {
        pauseGo = null;
        postMessage({type: 'resumed'});
      }
      return again;
    });
  },
  watches,
};

// Runs `source` live (or headless, for the warm-up); resolves to {result, svg}.
function run(source, options, live) {
  svg = null;
  M.rbThen = then;
  M.rbHooks = live ? Object.assign({}, noInput, hooks)
                   : Object.assign({}, noInput, {output: () => {}, frame: () => {}, svg: () => {}, stopped: () => false,
                                                 stepMs: () => 0, stepping: () => false});
  const args = runArgs(M, source, options, live);
  const done = (p) => {
    args.free();
    return {result: JSON.parse(takeString(M, p)), svg};
  };
  if (mode === 'sab') {
    try {
      return done(M.ccall('rb_run', 'number', RUN_TYPES, args.values));
    } catch (e) {
      args.free();
      throw e;
    }
  }
  return M.ccall('rb_run', 'number', RUN_TYPES, args.values, {async: true}).then(done, (e) => { args.free(); throw e; });
}

onmessage = async (e) => {
  const m = e.data;
  switch (m.type) {
    case 'init':
      mode = m.mode;
      importScripts(mode === 'sab' ? 'rbcore_fast.js' : 'rbcore.js');
      M = await (mode === 'sab' ? createRbCoreFast({}) : createRbCore({}));
      await run(WARM_UP, {seed: 1}, false);
      postMessage({type: 'ready'});
      return;
    case 'run': {
      shared = m.shared;
      ctrl = shared ? new Int32Array(shared) : new Int32Array(LIVE.BYTES / 4);
      readIdx = keyCount = lastKey = framesSent = 0;
      clicks = [];
      typed = [];
      answerText = watchText = '';
      pauseGo = null;
      for (const before of m.before || []) take(before);  // 'async' mode: the fields set so far
      let r;
      try {
        r = await run(m.source, m.options, true);
      } catch (err) {
        postMessage({type: 'failed', message: String(err && err.stack || err)});
        return;
      } finally {
        waiters.clear();
      }
      if (r.result.status === 'rejected' || r.result.status === 'usage') postMessage({type: 'done', result: r.result});
      postMessage({type: 'idle'});
      return;
    }
    default:
      if (!take(m)) return;
  }
  for (const check of [...waiters]) check(false);
};

// 'async' mode: the page's fields, events, answers and watches.
function take(m) {
  switch (m.type) {
    case 'set': ctrl[m.i] = m.v; return true;
    case 'add': ctrl[m.i]++; return true;
    case 'event': {
      const widx = ctrl[LIVE.WIDX];
      if (widx - readIdx >= LIVE.RING_N) return true;
      const o = LIVE.RING + (widx % LIVE.RING_N) * 4;
      ctrl[o] = m.kind; ctrl[o + 1] = m.a; ctrl[o + 2] = m.b; ctrl[o + 3] = m.c;
      ctrl[LIVE.WIDX] = widx + 1;
      return true;
    }
    case 'answer': answerText = m.text; ctrl[LIVE.ANSWER_ID] = m.id; return true;
    case 'watches': watchText = m.text; return true;
    default: return false;
  }
}
