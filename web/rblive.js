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
// The run under way (the page's number for it): every message about a run carries it, so that a
// run's last messages (its SVG, 'idle') are never taken for the next run's, which the page may
// start on this worker as soon as it has heard of the end.
let runId = 0;
const send = (m, transfer) => postMessage(Object.assign(m, {run: runId}), transfer || []);

// ---- what the page sends
let readIdx = 0;
// Key presses not yet taken: each answers one waitKey, in the order typed (up to 8 typed ahead);
// a look at the held key (getKey, keyDown) drops them, as in the live terminal view
// (docs/interaction.md). A press that came before the waitKey counts: the program may be busy,
// or paused, when the key is typed.
const PRESSES_AHEAD = 8;
let presses = [], clicks = [], typed = [];
let typedDone = 0;  // keys for an edit box taken (or dropped): the page learns which it sent are in
function drain() {
  const widx = Atomics.load(ctrl, LIVE.WIDX);
  while (readIdx < widx) {
    const o = LIVE.RING + (readIdx % LIVE.RING_N) * 4;
    const kind = ctrl[o], a = ctrl[o + 1], b = ctrl[o + 2], c = ctrl[o + 3];
    readIdx++;
    if (kind === LIVE.KEY) { if (presses.length < PRESSES_AHEAD) presses.push(a); }
    else if (kind === LIVE.CLICK) { if (clicks.length < 64) clicks.push([a, b, c]); }
    else if (kind === LIVE.TYPED) { if (typed.length < 256) typed.push(a); else typedDone++; }
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
  send({type: 'call', id, name, args});
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
  send({type: 'waiting', what});
}

let pauseGo = null;  // STEPGO when the current pause began
let framesSent = 0;
let svg = null;
const hooks = {
  output: (text) => send({type: 'output', text}),
  frame: (p, w, h) => {
    const rgba = new Uint8ClampedArray(M.HEAPU8.subarray(p, p + w * h * 4));
    framesSent++;
    send({type: 'frame', frame: {rgba, width: w, height: h}}, [rgba.buffer]);
  },
  // The page draws one frame in each of its own: one more may wait there, not a heap of them.
  frameWanted: () => framesSent - Atomics.load(ctrl, LIVE.DRAWN) < 2,
  svg: (text, rgba, width, height) => {
    svg = {text, rgba, width, height};
    send({type: 'svg', svg}, rgba ? [rgba.buffer] : []);
  },
  // The run has ended (the SVG comes after).
  finished: (json) => send({type: 'done', result: JSON.parse(json)}),
  // The controls as the core has them now, with the count of the page's keys for an edit box the
  // core has taken so far (the page's own guess of which box has the keys stands until then).
  controls: (c) => send({type: 'controls', controls: c, typed: typedDone}),
  state: (json) => send({type: 'state', json}),
  stopped,
  stepMs: () => Atomics.load(ctrl, LIVE.STEPUS) / 1000,
  stepping,
  // ms > 0: a delay (ended early by Stop); 0: a turn of the event loop ('async' mode only).
  yield: (ms) => (ms > 0 ? block(stopped, ms, () => undefined) : mode === 'sab' ? undefined : fastYield()),
  heldKey: () => {
    drain();
    presses = [];
    return Atomics.load(ctrl, LIVE.HELD);
  },
  mouse: () => [Atomics.load(ctrl, LIVE.MX), Atomics.load(ctrl, LIVE.MY), Atomics.load(ctrl, LIVE.MB)],
  takeClick: () => { drain(); return clicks.shift() || null; },
  takeTyped: () => {
    drain();
    if (!typed.length) return 0;
    typedDone++;
    return typed.shift();
  },
  // The first press not yet taken; else the key held now; else the next press.
  waitKey: () => {
    drain();
    if (presses.length) return presses.shift();
    const held = Atomics.load(ctrl, LIVE.HELD);
    if (held) return held;
    waiting('key');
    return block(() => { drain(); return stopped() || presses.length > 0; }, -1, () => {
      waiting('');
      return stopped() ? 0 : presses.shift();
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
  serialClose: () => send({type: 'call', id: 0, name: 'serialClose', args: []}),
  // Paused: the page shows `info`; 1 when it asks for a fresh look (the watches changed).
  pause: (info) => {
    if (pauseGo === null) pauseGo = Atomics.load(ctrl, LIVE.STEPGO);
    const refresh = Atomics.load(ctrl, LIVE.REFRESH);
    send({type: 'paused', info: JSON.parse(info)});
    return block(() => stopped() || !stepping() || Atomics.load(ctrl, LIVE.STEPGO) !== pauseGo ||
                        Atomics.load(ctrl, LIVE.REFRESH) !== refresh, -1, () => {
      const again = !stopped() && stepping() && Atomics.load(ctrl, LIVE.STEPGO) === pauseGo ? 1 : 0;
      if (!again) {
        pauseGo = null;
        send({type: 'resumed'});
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
      runId = m.id;
      shared = m.shared;
      ctrl = shared ? new Int32Array(shared) : new Int32Array(LIVE.BYTES / 4);
      readIdx = framesSent = typedDone = 0;
      presses = [];
      clicks = [];
      typed = [];
      answerText = watchText = '';
      pauseGo = null;
      for (const before of m.before || []) take(before);  // 'async' mode: the fields set so far
      let r;
      try {
        r = await run(m.source, m.options, true);
      } catch (err) {
        send({type: 'failed', message: String(err && err.stack || err)});
        return;
      } finally {
        waiters.clear();
      }
      if (r.result.status === 'rejected' || r.result.status === 'usage') send({type: 'done', result: r.result});
      send({type: 'idle'});
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
      if (widx - readIdx >= LIVE.RING_N) {  // the run takes none: dropped
        if (m.kind === LIVE.TYPED) typedDone++;
        return true;
      }
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
