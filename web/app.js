// The page: editor, run controls, the screen and the output, on window.rb (web/rb.js).
(function () {
  'use strict';
  const $ = (id) => document.getElementById(id);
  const source = $('source'), highlight = $('highlight'), gutter = $('gutter');
  const canvas = $('screen'), ctx = canvas.getContext('2d');
  const output = $('output'), status = $('status');
  const STORE = 'rb.source';

  // ---------------------------------------------------------------- editor
  const KEYWORDS = new Set(('if then else elseif endif for to step next while wend repeat until do loop ' +
    'gosub goto return sub call end print input and or not mod xor break continue case select ' +
    'endsub onerror data dim byref declare include true false').split(' '));
  let errorLine = 0;
  let marks = new Map();  // line -> 'err' | 'warn'

  function escapeHtml(s) {
    return s.replace(/[&<>]/g, (c) => ({'&': '&amp;', '<': '&lt;', '>': '&gt;'}[c]));
  }
  function highlightLine(line) {
    let html = '';
    const re = /(\/\/.*$|'.*$)|("[^"]*"?)|(\b\d+(?:\.\d*)?(?:e[+-]?\d+)?\b)|([A-Za-z_][A-Za-z_0-9]*:?)|(\s+|.)/gi;
    let m;
    let first = true;
    while ((m = re.exec(line)) !== null) {
      if (m[0] === '') break;
      const t = escapeHtml(m[0]);
      if (m[1]) html += `<span class="com">${t}</span>`;
      else if (m[2]) html += `<span class="str">${t}</span>`;
      else if (m[3]) html += `<span class="num">${t}</span>`;
      else if (m[4]) {
        const w = m[4].toLowerCase();
        if (first && w.endsWith(':')) html += `<span class="lbl">${t}</span>`;
        else if (w === 'rem' && first) { html += `<span class="com">${escapeHtml(line.slice(m.index))}</span>`; break; }
        else if (KEYWORDS.has(w)) html += `<span class="kw">${t}</span>`;
        else if (/^r[A-Z]/.test(m[4])) html += `<span class="rb">${t}</span>`;
        else html += t;
      } else html += t;
      if (!/^\s+$/.test(m[0])) first = false;
    }
    return html;
  }
  function renderEditor() {
    const lines = source.value.split('\n');
    highlight.innerHTML = lines.map((l, i) => {
      const h = highlightLine(l) || ' ';
      return i + 1 === errorLine ? `<span class="errline">${h}</span>` : h;
    }).join('\n') + '\n';
    gutter.innerHTML = lines.map((_, i) => {
      const m = marks.get(i + 1);
      return m ? `<span class="${m}">${i + 1}</span>` : String(i + 1);
    }).join('\n');
    source.style.height = 'auto';
    source.style.height = source.scrollHeight + 'px';
    source.style.width = 'auto';
    source.style.width = Math.max(source.scrollWidth, $('code').clientWidth) + 'px';
  }
  function goToLine(line) {
    const lines = source.value.split('\n');
    let pos = 0;
    for (let i = 0; i < line - 1 && i < lines.length; i++) pos += lines[i].length + 1;
    source.focus();
    source.setSelectionRange(pos, pos + (lines[line - 1] || '').length);
    $('editor').scrollTop = Math.max(0, (line - 5) * 20);
  }
  function listDiagnostics(list) {
    const ul = $('diagnostics');
    ul.textContent = '';
    marks = new Map();
    for (const d of list) {
      if (d.severity === 'note') continue;
      if (d.line) marks.set(d.line, d.severity === 'error' ? 'err' : marks.get(d.line) || 'warn');
      const li = document.createElement('li');
      li.className = d.severity;
      li.dataset.line = d.line;
      // A button: the keyboard reaches it (Tab) and Enter goes to the line, as a click does.
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = `${d.line}:${d.col}: ${d.severity}: ${d.message}${d.code ? ' [' + d.code + ']' : ''}`;
      b.title = `Go to line ${d.line}`;
      b.onclick = () => editor.goToLine(d.line);
      li.appendChild(b);
      ul.appendChild(li);
    }
    editor.setDiagnostics(list);
  }
  // The plain editor: the text area with its highlighting overlay and gutter, when the
  // CodeMirror bundle (editor.js) is not there.
  const textAreaEditor = {
    get value() { return source.value; },
    set value(text) { source.value = text; renderEditor(); },
    setDiagnostics() { renderEditor(); },
    setErrorLine(line) { errorLine = line || 0; renderEditor(); },
    setStepLine(line) { errorLine = line || 0; renderEditor(); },
    goToLine,
    focus() { source.focus(); },
  };
  let editor = textAreaEditor;
  if (window.RbEditor) {
    $('gutter').remove();
    $('code').remove();
    editor = window.RbEditor.create($('editor'), {doc: '', onChange: () => changed(), onRun: () => runProgram()});
    editor.view.dom.id = 'cm';
  }
  let checkTimer = 0;
  function changed() {
    localStorage.setItem(STORE, editor.value);
    if (editor === textAreaEditor) { errorLine = 0; renderEditor(); }
    clearTimeout(checkTimer);
    // During a run the check waits for its end (runProgram checks then).
    checkTimer = setTimeout(async () => { if (!run) listDiagnostics(await rb.check(editor.value)); }, 250);
  }
  source.addEventListener('input', changed);
  // Tab indents; Esc, then Tab within 2 s, leaves the text (as in the CodeMirror editor).
  let escapedAt = -Infinity;
  source.addEventListener('keydown', (e) => {
    if (e.key === 'Escape') escapedAt = performance.now();
    if (e.key === 'Tab' && performance.now() - escapedAt > 2000) {
      e.preventDefault();
      source.setRangeText('    ', source.selectionStart, source.selectionEnd, 'end');
      changed();
    }
  });
  function setSource(text) {
    editor.value = text;
    if (editor === textAreaEditor) changed();
  }

  // ---------------------------------------------------------------- share links, files, examples
  function toBase64Url(bytes) {
    let s = '';
    for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(s).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  }
  function fromBase64Url(s) {
    const b = atob(s.replace(/-/g, '+').replace(/_/g, '/'));
    return Uint8Array.from(b, (c) => c.charCodeAt(0));
  }
  async function pipe(bytes, stream) {
    return new Uint8Array(await new Response(new Blob([bytes]).stream().pipeThrough(stream)).arrayBuffer());
  }
  async function shareLink(text) {
    const packed = await pipe(new TextEncoder().encode(text), new CompressionStream('deflate-raw'));
    return location.href.split('#')[0] + '#code=' + toBase64Url(packed);
  }
  async function programFromHash() {
    const m = /^#code=([A-Za-z0-9_-]+)/.exec(location.hash);
    if (!m) return null;
    return new TextDecoder().decode(await pipe(fromBase64Url(m[1]), new DecompressionStream('deflate-raw')));
  }
  $('share').onclick = async () => {
    const link = await shareLink(editor.value);
    history.replaceState(null, '', link);
    try { await navigator.clipboard.writeText(link); status.textContent = 'link copied'; } catch (e) { status.textContent = 'link in the address bar'; }
  };
  window.addEventListener('hashchange', async () => { const p = await programFromHash(); if (p !== null) setSource(p); });
  $('open').onclick = () => $('file').click();
  $('file').onchange = async () => { const f = $('file').files[0]; if (f) setSource(await f.text()); $('file').value = ''; };
  function download(name, href) {
    const a = document.createElement('a');
    a.href = href;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
  }
  $('save').onclick = () => download('program.bas', URL.createObjectURL(new Blob([editor.value], {type: 'text/plain'})));
  $('png').onclick = () => download('screen.png', canvas.toDataURL('image/png'));
  // The SVG is the screen as the last run left it, made by the core as `rb render -o OUT.svg`
  // makes it (lines, shapes and text as vectors).
  let lastSvg = null;
  $('svg').onclick = () => {
    if (lastSvg) download('screen.svg', URL.createObjectURL(new Blob([lastSvg], {type: 'image/svg+xml'})));
  };
  const examples = window.RB_EXAMPLES || [];
  for (const [i, ex] of examples.entries()) {
    const o = document.createElement('option');
    o.value = String(i);
    o.textContent = `${ex.name}: ${ex.title}`;
    $('examples').appendChild(o);
  }
  $('examples').onchange = () => {
    const ex = examples[Number($('examples').value)];
    if (ex) setSource(ex.source);
    $('examples').value = '';
  };

  // ---------------------------------------------------------------- keys and the mouse
  const NAMED = {Enter: 13, Escape: 27, Backspace: 8, Tab: 9, ' ': 32, PageUp: 256 + 33, PageDown: 256 + 34,
    End: 256 + 35, Home: 256 + 36, ArrowLeft: 256 + 37, ArrowUp: 256 + 38, ArrowRight: 256 + 39,
    ArrowDown: 256 + 40, Insert: 256 + 45, Delete: 256 + 46};
  function keyCode(e) {
    if (NAMED[e.key] !== undefined) return NAMED[e.key];
    const f = /^F(\d+)$/.exec(e.key);
    if (f && Number(f[1]) >= 1 && Number(f[1]) <= 12) return 256 + 111 + Number(f[1]);
    if (e.key.length === 1) {
      let c = e.key;
      if (/[a-zA-Z]/.test(c)) c = e.shiftKey ? c.toUpperCase() : c.toLowerCase();
      const code = c.charCodeAt(0);
      return code <= 255 ? code : 0;
    }
    return 0;
  }
  const input = {held: 0, keyWaiters: [], mouse: [0, 0, 0], clicks: [], clickWaiters: [], typed: []};
  // The program's buttons and edit boxes as the run last showed them (WebHost::presentControls):
  // drawn over the screen; while one of its edit boxes has the keyboard, keys go into it.
  let controls = {buttons: [], edits: [], focus: ''};
  function placeControls() {
    const layer = $('controls');
    const box = $('screenBox').getBoundingClientRect();
    const r = canvas.getBoundingClientRect();
    const scale = Math.min(r.width / 800, r.height / 600);
    const x = r.left - box.left + (r.width - 800 * scale) / 2, y = r.top - box.top + (r.height - 600 * scale) / 2;
    layer.style.transform = `translate(${x}px, ${y}px) scale(${scale})`;
  }
  // The controls are buttons of the page too, for the keyboard: Tab reaches them after the
  // screen, and Enter or Space presses one where it is (its middle), as a click there does; an
  // edit box so pressed takes the keys typed next on the screen, which gets the focus. The mouse
  // goes through them to the screen (pointer-events: none).
  function showControls(c) {
    controls = c;
    const layer = $('controls');
    const had = layer.contains(document.activeElement) ? document.activeElement.dataset.key : null;
    layer.textContent = '';
    const add = (cls, item, text, label, edit) => {
      const d = document.createElement('button');
      d.type = 'button';
      d.className = cls;
      d.dataset.name = item.name;
      d.dataset.key = (edit ? 'edit:' : 'button:') + item.name;
      Object.assign(d.style, {left: `${item.x}px`, top: `${item.y}px`, width: `${item.w}px`, height: `${item.h}px`});
      d.textContent = text;
      d.setAttribute('aria-label', label);
      d.addEventListener('click', (e) => {
        if (e.detail !== 0 || !run) return;  // only the keyboard's clicks (a mouse's went to the screen)
        pressAt(item.x + Math.floor(item.w / 2), item.y + Math.floor(item.h / 2));
        if (edit) canvas.focus();
      });
      layer.appendChild(d);
      if (d.dataset.key === had) d.focus();
    };
    // In the order added: the last added is on top, as a press finds it (core/input).
    c.buttons.forEach((b) => add('rb-button', b, b.name, `the program's button ${b.name}`, false));
    c.edits.forEach((e) => add('rb-edit' + (e.name === c.focus ? ' focus' : ''), e, e.text,
                               `the program's edit box ${e.name}: ${e.text || 'empty'}`, true));
    placeControls();
  }
  new ResizeObserver(placeControls).observe(canvas);
  function keyDown(code) {
    if (!code) return;
    input.held = code;
    const w = input.keyWaiters.splice(0);
    w.forEach((r) => r(code));
  }
  canvas.addEventListener('keydown', (e) => {
    const code = keyCode(e);
    if (!code || e.ctrlKey || e.metaKey) return;
    // Tab and Shift+Tab move the focus on, as anywhere on the page (the screen is no trap); only
    // while one of the program's edit boxes has the keyboard does Tab go into it (and give the
    // keyboard back, by core/input's rules).
    if (e.key === 'Tab' && !(run && controls.focus)) return;
    e.preventDefault();
    if (run && controls.focus) input.typed.push(code);  // into the program's edit box
    else keyDown(code);
  });
  canvas.addEventListener('keyup', () => { input.held = 0; });
  canvas.addEventListener('blur', () => { input.held = 0; });
  function screenPoint(e) {
    const r = canvas.getBoundingClientRect();
    // object-fit: contain: the picture's box inside the element
    const scale = Math.min(r.width / 800, r.height / 600);
    const ox = (r.width - 800 * scale) / 2, oy = (r.height - 600 * scale) / 2;
    return [Math.floor((e.clientX - r.left - ox) / scale), Math.floor((e.clientY - r.top - oy) / scale)];
  }
  canvas.addEventListener('mousemove', (e) => { const [x, y] = screenPoint(e); input.mouse = [x, y, e.buttons & 7]; });
  canvas.addEventListener('mousedown', (e) => {
    const [x, y] = screenPoint(e);
    const bits = e.button === 0 ? 1 : e.button === 2 ? 2 : 4;
    input.mouse = [x, y, (e.buttons & 7) | bits];
    const c = [x, y, input.mouse[2]];
    const w = input.clickWaiters.shift();
    if (w) w(c); else input.clicks.push(c);
  });
  canvas.addEventListener('mouseup', (e) => { input.mouse = [input.mouse[0], input.mouse[1], e.buttons & 7]; });
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  // A press of the left button at screen pixel (x, y) and its release, as the mouse gives them.
  function pressAt(x, y) {
    input.mouse = [x, y, 1];
    const c = [x, y, 1];
    const w = input.clickWaiters.shift();
    if (w) w(c); else input.clicks.push(c);
    setTimeout(() => { input.mouse = [x, y, input.mouse[2] & ~1]; }, 100);
  }

  // ---------------------------------------------------------------- the run
  let run = null;          // {stop, done}
  let paused = false, resumeWaiters = [];
  // Step: the run stops before each statement (the host asks stepping() at each yield and
  // after each stop, and waits in atLine() until Step, Resume or Stop).
  let stepMode = false;
  let cancelInput = null, cancelDialog = null;
  let outputText = '';

  function setRunning(on) {
    $('run').disabled = on;
    $('svg').disabled = on || !lastSvg;
    $('stop').disabled = !on;
    $('pause').disabled = !on;
    $('step').disabled = !on;
    $('pause').textContent = paused ? 'Resume' : 'Pause';
  }

  // ---------------------------------------------------------------- the screen as text
  // What a screen reader says of the screen (#screenText, aria-live polite): the robot's pose
  // and pen, the sensors the program read last and the last line it printed, from the core's
  // state (WebHost::stateJson, sent as the run goes). Said at most every SAY_EVERY_MS while a
  // run goes, at once when it ends; errors are said at once (#alert, role alert) with their line.
  const SAY_EVERY_MS = 2000;
  const said = {text: '', at: -Infinity, pending: null, timer: 0};
  function describeState(s) {
    if (!s) return '';
    const parts = [];
    if (!s.placed) parts.push('The robot is not placed.');
    else parts.push(`Robot at x ${s.x}, y ${s.y}, heading ${s.heading} degrees, pen ${s.pen ? 'down' : 'up'}.`);
    if (s.sensors && s.sensors.length)
      parts.push('Last read: ' + s.sensors.slice(0, 5).map((r) => `${r.name} ${r.value} (line ${r.line})`).join(', ') + '.');
    if (s.printed) parts.push(`Printed: ${s.printed}`);
    return parts.join(' ');
  }
  function sayNow() {
    clearTimeout(said.timer);
    said.timer = 0;
    const text = said.pending;
    said.pending = null;
    if (text === null || text === said.text) return;
    $('screenText').textContent = text;
    said.text = text;
    said.at = performance.now();
  }
  function say(text, now) {
    said.pending = text;
    const wait = said.at + SAY_EVERY_MS - performance.now();
    if (now || wait <= 0) sayNow();
    else if (!said.timer) said.timer = setTimeout(sayNow, wait);
  }
  function alertError(text) {
    $('alert').textContent = '';
    if (text) $('alert').textContent = text;
  }
  function appendOutput(text, cls) {
    const keep = Math.max(1, Number($('keepOutput').value) || 256) * 1024;
    outputText += text;
    if (cls) {
      const span = document.createElement('span');
      span.className = cls;
      span.textContent = text;
      output.appendChild(span);
      return;
    }
    if (outputText.length > keep) {
      outputText = outputText.slice(outputText.length - keep);
      output.textContent = outputText;
    } else {
      output.appendChild(document.createTextNode(text));
    }
    $('outputPane').scrollTop = $('outputPane').scrollHeight;
  }
  function drawFrame(f) {
    ctx.putImageData(new ImageData(f.rgba, f.width, f.height), 0, 0);
  }
  function clearScreen() {
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, 800, 600);
  }
  const io = {
    heldKey: () => input.held,
    takeTyped: () => input.typed.shift() || 0,
    controls: showControls,
    waitKey: () => (input.held ? Promise.resolve(input.held) : new Promise((r) => input.keyWaiters.push(r))),
    mouse: () => input.mouse,
    takeClick: () => input.clicks.shift() || null,
    waitClick: () => (input.clicks.length ? Promise.resolve(input.clicks.shift()) : new Promise((r) => input.clickWaiters.push(r))),
    inputLine: (prompt) => new Promise((resolve) => {
      const form = $('inputForm'), line = $('inputLine');
      form.hidden = false;
      line.value = '';
      line.focus();
      $('outputPane').scrollTop = $('outputPane').scrollHeight;
      const finish = (value) => { form.hidden = true; form.onsubmit = null; cancelInput = null; resolve(value); };
      form.onsubmit = (e) => { e.preventDefault(); finish(line.value); };
      cancelInput = () => finish(null);
    }),
    messageBox: (text, title) => new Promise((resolve) => {
      const d = $('msgbox');
      $('msgTitle').textContent = title || 'Message';
      $('msgText').textContent = text;
      const finish = () => { d.onclose = null; cancelDialog = null; if (d.open) d.close(); canvas.focus(); resolve(); };
      d.onclose = finish;
      cancelDialog = finish;
      d.showModal();
    }),
    serialOpen: (n) => serial.open(n),
    serialSend: (code, param) => serial.send(code, param),
    serialTake: (want, ms, room) => serial.take(want, ms, room),
    serialClose: () => serial.close(),
  };
  // ---------------------------------------------------------------- a real robot: Web Serial
  // `rCommPort n` (n > 0) asks the user for the robot's port in a dialog (a browser lets a page
  // ask for a port only in answer to a click) and opens it at the baud rate of the limits menu;
  // the core then sends each command's two bytes and reads the reply (WebSerialLink).
  const serial = {
    port: null, reader: null, bytes: [], gone: false, wake: null,
    woken() { if (this.wake) { const w = this.wake; this.wake = null; w(); } },
    choose(n) {
      return new Promise((resolve) => {
        const d = $('serialDialog');
        $('serialPort').textContent = String(n);
        const finish = (port) => { d.onclose = null; cancelDialog = null; if (d.open) d.close(); canvas.focus(); resolve(port); };
        $('serialChoose').onclick = (e) => {
          e.preventDefault();
          navigator.serial.requestPort().then(finish, () => finish(null));
        };
        d.onclose = () => finish(null);
        cancelDialog = () => finish(null);
        d.showModal();
      });
    },
    async open(n) {
      if (!navigator.serial)
        return {error: 'this browser has no Web Serial (Chrome and Edge have it); use the simulator (rCommPort 0)'};
      this.close();
      const port = await this.choose(n);
      if (!port) return {error: 'no serial port was chosen'};
      const baud = Number($('baud').value) || 9600;
      try {
        await port.open({baudRate: baud});
      } catch (e) {
        return {error: `cannot open the serial port: ${e.message}`};
      }
      Object.assign(this, {port, bytes: [], gone: false});
      const reader = port.readable.getReader();
      this.reader = reader;
      (async () => {
        try {
          for (;;) {
            const {value, done} = await reader.read();
            if (done) break;
            if (this.reader === reader) { for (const b of value) this.bytes.push(b); this.woken(); }
          }
        } catch (e) { /* the device went away */ }
        if (this.reader === reader) { this.gone = true; this.woken(); }
      })();
      const info = port.getInfo ? port.getInfo() : {};
      const hex = (v) => v.toString(16).padStart(4, '0');
      const what = info.usbVendorId !== undefined ? ` (USB ${hex(info.usbVendorId)}:${hex(info.usbProductId || 0)})` : '';
      return {name: `Web Serial port ${n}${what} at ${baud} baud`};
    },
    async send(code, param) {
      if (!this.port || this.gone) return false;
      this.bytes = [];  // stale bytes belong to no command
      try {
        const w = this.port.writable.getWriter();
        try { await w.write(new Uint8Array([code, param])); } finally { w.releaseLock(); }
        return true;
      } catch (e) {
        return false;
      }
    },
    async take(want, ms, room) {
      if (this.bytes.length < want && !this.gone && ms > 0 && run) {
        await new Promise((r) => {
          const t = setTimeout(() => { this.wake = null; r(); }, ms);
          this.wake = () => { clearTimeout(t); r(); };
        });
      }
      if (this.gone && !this.bytes.length) return null;
      return new Uint8Array(this.bytes.splice(0, room));
    },
    close() {
      const {port, reader} = this;
      Object.assign(this, {port: null, reader: null, bytes: [], gone: false});
      this.woken();
      if (reader) reader.cancel().catch(() => {}).then(() => { reader.releaseLock(); return port.close(); }).catch(() => {});
    },
  };

  // The run's yields wait here while paused.
  function pauseGate(inner) {
    return async (ms) => {
      await inner(ms);
      while (paused && run) await new Promise((r) => resumeWaiters.push(r));
    };
  }

  // A stepped run stops here before the statement on `line`.
  function stepAt(line) {
    if (!run) return Promise.resolve();
    paused = true;
    setRunning(true);
    editor.setStepLine(line);
    status.textContent = `paused before line ${line}`;
    return new Promise((r) => resumeWaiters.push(r));
  }
  function limits() {
    return {
      maxSteps: Number($('maxSteps').value) || 0,
      timeout: Number($('timeout').value) || 0,
      maxMemory: Number($('maxMemory').value) || 0,
    };
  }
  async function runProgram() {
    if (run) return;
    output.textContent = '';
    outputText = '';
    editor.setErrorLine(0);
    clearScreen();
    input.clicks = [];
    input.typed = [];
    input.held = 0;
    showControls({buttons: [], edits: [], focus: ''});
    paused = false;
    stepMode = false;
    status.textContent = 'running';
    alertError('');
    const started = performance.now();
    canvas.focus();
    const r = rb.start(editor.value, Object.assign(limits(), {
      io,
      png: false,
      svg: true,
      stepMs: () => Number($('speed').value),
      onOutput: (t) => appendOutput(t),
      onFrame: drawFrame,
      wrapYield: pauseGate,
      stepping: () => stepMode,
      atLine: stepAt,
      onState: (st) => say(describeState(st)),
    }));
    run = r;
    setRunning(true);
    let result;
    try {
      result = await r.done;
    } catch (e) {
      result = {status: 'error', error: String(e), output: ''};
    }
    run = null;
    lastSvg = result.svg || null;
    paused = false;
    stepMode = false;
    editor.setErrorLine(0);  // the stepped line
    resumeWaiters.splice(0).forEach((w) => w());
    setRunning(false);
    if (result.frame) drawFrame(result.frame);
    const secs = ((performance.now() - started) / 1000).toFixed(2);
    // The diagnostics again (a check waits while a run is on); the run has ended already.
    if (result.status !== 'rejected') rb.check(editor.value).then(listDiagnostics);
    if (result.status === 'rejected') {
      listDiagnostics(result.diagnostics);
      const first = result.diagnostics.find((d) => d.severity === 'error');
      editor.setErrorLine(first ? first.line : 0);
      appendOutput(result.error, 'error');
    } else if (result.error) {
      editor.setErrorLine(result.errorLine || 0);
      appendOutput((outputText && !outputText.endsWith('\n') ? '\n' : '') + result.error, 'error');
    }
    status.textContent = `${result.status} (${secs} s, ${result.steps || 0} steps)`;
    const ended = {finished: 'The program finished', stopped: 'The program was stopped', error: 'The program stopped with an error',
                   'step-limit': 'The program stopped at the step limit', timeout: 'The program stopped at the time limit',
                   rejected: 'The program did not compile'}[result.status] || `The program ended: ${result.status}`;
    say(`${ended} after ${result.steps || 0} steps. ${describeState(result.state)}`.trim(), true);
    if (result.errorMessage) alertError(result.errorLine ? `Error at line ${result.errorLine}: ${result.errorMessage}` : `Error: ${result.errorMessage}`);
    window.rbLastRun = result;
  }
  function stopProgram() {
    if (!run) return;
    run.stop();
    paused = false;
    resumeWaiters.splice(0).forEach((w) => w());
    input.keyWaiters.splice(0).forEach((w) => w(0));
    input.clickWaiters.splice(0).forEach((w) => w([0, 0, 0]));
    if (cancelInput) cancelInput();
    if (cancelDialog) cancelDialog();
    serial.woken();
  }
  $('run').onclick = runProgram;
  $('stop').onclick = stopProgram;
  $('pause').onclick = () => {
    if (!run) return;
    paused = !paused;
    if (!paused) {
      stepMode = false;
      editor.setErrorLine(0);
      resumeWaiters.splice(0).forEach((w) => w());
    }
    setRunning(true);
    status.textContent = paused ? 'paused' : 'running';
  };
  // Step: while paused, one statement; while running, the run stops before its next statement.
  $('step').onclick = () => {
    if (!run) return;
    stepMode = true;
    paused = false;
    status.textContent = 'stepping';
    resumeWaiters.splice(0).forEach((w) => w());
  };
  // The page's keys (the keys menu lists them): Ctrl with Enter, comma, semicolon or period,
  // wherever the focus is. A running program never gets a key with Ctrl (keyCode above), so
  // none of these is a key it could read.
  const SHORTCUTS = {'Enter': 'run', ',': 'pause', ';': 'step', '.': 'stop'};
  window.addEventListener('keydown', (e) => {
    if (!(e.ctrlKey || (e.metaKey && e.key === 'Enter')) || e.altKey) return;
    const action = SHORTCUTS[e.key];
    if (!action) return;
    e.preventDefault();
    e.stopPropagation();
    if (!$(action).disabled) $(action).click();
  }, true);
  $('skip').addEventListener('click', (e) => { e.preventDefault(); editor.focus(); });
  const speedText = () => $('speed').setAttribute('aria-valuetext', `${$('speed').value} ms per pixel or degree`);
  $('speed').addEventListener('input', speedText);
  speedText();

  // ---------------------------------------------------------------- start
  window.rbPage = {runProgram, stopProgram, setSource, shareLink, programFromHash,
    get source() { return editor.value; },
    get running() { return run !== null; }, ready: null};
  // Offline once loaded: the service worker keeps the site's files (web/sw.js). Browsers run
  // service workers on https:// and on localhost only.
  if ('serviceWorker' in navigator && window.isSecureContext) navigator.serviceWorker.register('sw.js').catch(() => {});
  window.rbPage.ready = (async () => {
    clearScreen();
    const fromLink = await programFromHash().catch(() => null);
    const saved = localStorage.getItem(STORE);
    editor.value = fromLink !== null ? fromLink : saved !== null ? saved : (examples[0] ? examples[0].source : '');
    await rb.ready();
    listDiagnostics(await rb.check(editor.value));
    status.textContent = 'ready';
    return true;
  })();
})();
