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
    saveCurrent();
    if (notice.kind === 'example') hideNotice();  // an edit makes the example the student's
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
  // Another program's text: no undo back into the one before.
  function resetSource(text) {
    if (editor.reset) editor.reset(text); else editor.value = text;
    if (editor === textAreaEditor) renderEditor();
    listDiagnosticsSoon();
  }
  function listDiagnosticsSoon() {
    clearTimeout(checkTimer);
    checkTimer = setTimeout(async () => listDiagnostics(await rb.check(editor.value)), 0);
  }

  // ---------------------------------------------------------------- notices
  // A line under the header that says what just happened to the student's work, with what can
  // be done about it: keep or drop a shared program's copy, undo loading an example or a delete.
  const notice = {kind: ''};
  function showNotice(kind, text, actions) {
    notice.kind = kind;
    $('noticeText').textContent = text;
    const box = $('noticeActions');
    box.textContent = '';
    for (const [label, act] of actions) {
      const b = document.createElement('button');
      b.textContent = label;
      b.onclick = () => { hideNotice(); act(); };
      box.appendChild(b);
    }
    $('notice').hidden = false;
  }
  function hideNotice() {
    notice.kind = '';
    $('notice').hidden = true;
  }
  $('noticeClose').onclick = hideNotice;

  // ---------------------------------------------------------------- the programs kept
  // The page keeps several programs in the browser's local storage (rb.programs: their names and
  // texts, and the one open), each saved on every change. A share link, a file opened and New
  // add one; nothing replaces a program but the student's own edits and loading an example,
  // which the notice can undo.
  const PROGRAMS = 'rb.programs';
  function readBook() {
    try {
      const b = JSON.parse(localStorage.getItem(PROGRAMS));
      if (b && Array.isArray(b.programs)) return b;
    } catch (e) { /* not ours: start again */ }
    return null;
  }
  function writeBook() {
    try {
      localStorage.setItem(PROGRAMS, JSON.stringify(book));
    } catch (e) {
      status.textContent = 'not saved: the browser\'s storage for this page is full';
    }
  }
  let book = readBook() || {programs: [], current: ''};
  const current = () => book.programs.find((p) => p.id === book.current);
  function newId() { return Date.now().toString(36) + Math.random().toString(36).slice(2, 8); }
  function freeName(name) {
    const taken = new Set(book.programs.map((p) => p.name));
    if (!taken.has(name)) return name;
    for (let i = 2; ; i++) if (!taken.has(`${name} ${i}`)) return `${name} ${i}`;
  }
  // Writes the open program's text; the other programs as the storage has them (another tab
  // may have changed them).
  function saveCurrent() {
    const mine = current();
    if (!mine) return;
    mine.source = editor.value;
    const fresh = readBook();
    if (fresh) {
      const theirs = fresh.programs.find((p) => p.id === mine.id);
      if (theirs) Object.assign(theirs, mine); else fresh.programs.push(mine);
      fresh.current = mine.id;
      book = fresh;
    }
    writeBook();
  }
  function listPrograms() {
    const sel = $('programs');
    sel.textContent = '';
    for (const p of book.programs) {
      const o = document.createElement('option');
      o.value = p.id;
      o.textContent = p.name;
      sel.appendChild(o);
    }
    sel.value = book.current;
  }
  function openProgram(id) {
    if (run) stopProgram();
    saveCurrent();
    if (!book.programs.some((p) => p.id === id)) return;
    book.current = id;
    writeBook();
    listPrograms();
    resetSource(current().source);
  }
  function addProgram(name, source) {
    saveCurrent();
    const p = {id: newId(), name: freeName(name), source};
    book.programs.push(p);
    writeBook();
    openProgram(p.id);
    return p;
  }
  function deleteProgram(id) {
    saveCurrent();
    const i = book.programs.findIndex((p) => p.id === id);
    if (i < 0) return null;
    const [gone] = book.programs.splice(i, 1);
    if (!book.programs.length) book.programs.push({id: newId(), name: 'program 1', source: ''});
    if (book.current === id) {
      book.current = book.programs[Math.min(i, book.programs.length - 1)].id;
      writeBook();
      listPrograms();
      resetSource(current().source);
    } else {
      writeBook();
      listPrograms();
    }
    return gone;
  }
  $('programs').onchange = () => openProgram($('programs').value);
  $('newProgram').onclick = () => { $('programMenu').open = false; addProgram('program', ''); editor.focus(); };
  $('renameProgram').onclick = () => {
    $('programMenu').open = false;
    const d = $('nameDialog');
    $('nameInput').value = current().name;
    d.onclose = () => {
      const name = $('nameInput').value.trim();
      if (d.returnValue === 'ok' && name && name !== current().name) {
        current().name = freeName(name);
        writeBook();
        listPrograms();
      }
    };
    d.showModal();
    $('nameInput').select();
  };
  $('deleteProgram').onclick = () => {
    $('programMenu').open = false;
    const at = book.programs.findIndex((p) => p.id === book.current);
    const gone = deleteProgram(book.current);
    if (gone) {
      showNotice('delete', `Deleted “${gone.name}”.`, [['Undo', () => {
        saveCurrent();
        book.programs.splice(Math.min(at, book.programs.length), 0, gone);
        writeBook();
        openProgram(gone.id);
      }]]);
    }
  };
  // A shared program opens as a copy beside the student's own (the same text opens the copy
  // made before); the link leaves the address bar, so a reload does not make another.
  async function openShared() {
    const text = await programFromHash().catch(() => null);
    if (text === null) return false;
    history.replaceState(null, '', location.href.split('#')[0]);
    const before = book.current;
    const same = book.programs.find((p) => p.source === text);
    if (same) {
      if (same.id !== book.current) openProgram(same.id);
      return true;
    }
    const copy = addProgram('shared program', text);
    showNotice('shared', `Opened a shared program as “${copy.name}”, beside your own programs.`, [
      ['Keep', () => {}],
      ['Drop', () => {
        deleteProgram(copy.id);
        if (book.programs.some((p) => p.id === before)) openProgram(before);
      }],
    ]);
    return true;
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
  window.addEventListener('hashchange', () => { openShared(); });
  $('open').onclick = () => $('file').click();
  $('file').onchange = async () => {
    const f = $('file').files[0];
    if (f) addProgram(f.name.replace(/\.(bas|txt)$/i, ''), await f.text());
    $('file').value = '';
  };
  function download(name, href) {
    const a = document.createElement('a');
    a.href = href;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
  }
  $('save').onclick = () => download(`${(current() || {name: 'program'}).name.replace(/[\\/:*?"<>|]+/g, '_')}.bas`,
    URL.createObjectURL(new Blob([editor.value], {type: 'text/plain'})));
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
  // An example replaces the open program's text (the editor's undo brings it back too).
  $('examples').onchange = () => {
    const ex = examples[Number($('examples').value)];
    $('examples').value = '';
    if (!ex) return;
    const before = editor.value, into = current();
    setSource(ex.source);
    if (before.trim() && before !== ex.source) {
      showNotice('example', `Loaded the example ${ex.name} into “${into.name}”.`, [['Undo', () => {
        if (book.current === into.id) setSource(before);
      }]]);
    }
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
  // Keys, the mouse and clicks go to the run (rb.start's run: its worker takes them).
  let mouseButtons = 0;
  // The program's buttons and edit boxes as the run last showed them (WebHost::presentControls):
  // drawn over the screen; while one of its edit boxes has the keyboard, keys go into it.
  let controls = {buttons: [], edits: [], focus: ''};
  function placeControls() {
    const box = $('screenBox').getBoundingClientRect();
    const p = pictureBox();
    $('controls').style.transform = `translate(${p.left - box.left}px, ${p.top - box.top}px) scale(${p.scale})`;
  }
  // The controls are buttons of the page too, for the keyboard: Tab reaches them after the
  // screen, and Enter or Space presses one where it is (its middle), as a click there does; an
  // edit box so pressed takes the keys typed next on the screen, which gets the focus. The mouse
  // goes through them to the screen (pointer-events: none). `inFlight`: keys the page sent for an
  // edit box that the run had not taken when it showed these controls; until it has, the page's
  // own account of which box has the keys stands (see the screen's keydown).
  function showControls(c, inFlight) {
    if (inFlight > 0) c = Object.assign({}, c, {focus: controls.focus});
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
  new ResizeObserver(() => { fitScreen(); placeControls(); }).observe(canvas);
  // The 800x600 screen fitted in its box. Shown smaller it is smoothed (the browser averages
  // neighbouring pixels as it scales the canvas), so that a 1-pixel line or small text never
  // falls between the pixels shown, as it does when each shown pixel is the nearest one; shown
  // larger each pixel stays sharp. (The browser's compositor scales it: no work for the page.)
  function fitScreen() {
    canvas.classList.toggle('sharp', pictureBox().scale >= 1);
  }
  // Where the picture is on the page (CSS pixels): its top left corner and a screen pixel's size.
  function pictureBox() {
    const r = canvas.getBoundingClientRect();
    const w = canvas.clientWidth, h = canvas.clientHeight, scale = Math.min(w / 800, h / 600);
    return {left: r.left + canvas.clientLeft + (w - 800 * scale) / 2, top: r.top + canvas.clientTop + (h - 600 * scale) / 2, scale};
  }
  $('larger').onclick = () => {
    document.body.classList.toggle('larger');
    $('larger').setAttribute('aria-pressed', String(document.body.classList.contains('larger')));
  };
  $('fullscreen').onclick = () => {
    if (document.fullscreenElement) document.exitFullscreen();
    else $('screenBox').requestFullscreen().then(() => canvas.focus(), () => {});
  };
  canvas.addEventListener('keydown', (e) => {
    const code = keyCode(e);
    if (!code || e.ctrlKey || e.metaKey) return;
    // Tab and Shift+Tab move the focus on, as anywhere on the page (the screen is no trap); only
    // while one of the program's edit boxes has the keyboard does Tab go into it (and give the
    // keyboard back, by core/input's rules).
    if (e.key === 'Tab' && !(run && controls.focus)) return;
    e.preventDefault();
    if (!run) return;
    if (controls.focus) {  // into the program's edit box
      run.typed(code);
      // Enter, Tab and Esc give the keyboard back (core/input's rules): the page knows it at
      // once, so that a Tab typed next moves the focus on even before the run has taken them.
      if (code === NAMED.Enter || code === NAMED.Tab || code === NAMED.Escape) showControls(Object.assign({}, controls, {focus: ''}));
    } else {
      run.keyDown(code);
    }
  });
  canvas.addEventListener('keyup', () => { if (run) run.keyUp(); });
  canvas.addEventListener('blur', () => { if (run) run.keyUp(); });
  function screenPoint(e) {
    const p = pictureBox();
    return [Math.floor((e.clientX - p.left) / p.scale), Math.floor((e.clientY - p.top) / p.scale)];
  }
  // Pointer events: their positions keep fractions of a pixel (the screen's pixels are smaller
  // than the page's when it is shown smaller), and a touch screen's touches are clicks too.
  canvas.addEventListener('pointermove', (e) => {
    const [x, y] = screenPoint(e);
    mouseButtons = e.buttons & 7;
    if (run) run.mouse(x, y, mouseButtons);
  });
  canvas.addEventListener('pointerdown', (e) => {
    const [x, y] = screenPoint(e);
    const bits = e.button === 0 ? 1 : e.button === 2 ? 2 : 4;
    mouseButtons = (e.buttons & 7) | bits;
    if (run) run.click(x, y, mouseButtons);
  });
  canvas.addEventListener('pointerup', (e) => {
    const [x, y] = screenPoint(e);
    mouseButtons = e.buttons & 7;
    if (run) run.mouse(x, y, mouseButtons);
  });
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  // A press of the left button at screen pixel (x, y) and its release, as the mouse gives them.
  function pressAt(x, y) {
    if (!run) return;
    const r = run;
    r.click(x, y, mouseButtons | 1);
    setTimeout(() => r.mouse(x, y, mouseButtons), 100);
  }

  // ---------------------------------------------------------------- the run
  let run = null;          // rb.start's run: {done, stop, pause, resume, step, ...}
  // Paused: the run waits in a pause (Pause, or a Step done) and the debugger shows where;
  // pausing: Pause was pressed and the run has not stopped yet.
  let paused = false, pausing = false;
  let cancelInput = null, cancelDialog = null;
  let waitingFor = '';

  function setRunning(on) {
    $('run').disabled = on;
    $('svg').disabled = on || !lastSvg;
    $('stop').disabled = !on;
    $('pause').disabled = !on;
    $('step').disabled = !on;
    $('pause').textContent = paused || pausing ? 'Resume' : 'Pause';
  }
  function showStatus() {
    if (!run) return;
    if (paused) return;  // showPaused says where
    status.textContent = pausing ? 'pausing…' : waitingFor ? `waiting for ${waitingFor}` : 'running';
  }

  // The output pane: what the run prints is gathered and shown once a frame, in blocks of whole
  // lines (a block is laid out once) and the line being printed; the pane keeps the last
  // `output kept` KiB (the oldest blocks go).
  const shown = {blocks: [], size: 0, pending: '', tail: null, frame: 0};
  function outputKeep() { return Math.max(1, Number($('keepOutput').value) || 256) * 1024; }
  function clearOutput() {
    output.textContent = '';
    shown.blocks = [];
    shown.size = 0;
    shown.pending = '';
    shown.tail = document.createElement('span');
    output.appendChild(shown.tail);
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
    if (cls) {
      flushOutput();
      const span = document.createElement('span');
      span.className = cls;
      span.textContent = text;
      output.appendChild(span);
      $('outputPane').scrollTop = $('outputPane').scrollHeight;
      return;
    }
    shown.pending += text;
    if (shown.pending.length > 4 * outputKeep()) shown.pending = shown.pending.slice(-outputKeep());
    if (!shown.frame) shown.frame = requestAnimationFrame(flushOutput);
  }
  function flushOutput() {
    if (shown.frame) cancelAnimationFrame(shown.frame);
    shown.frame = 0;
    if (!shown.pending) return;
    const keep = outputKeep();
    let text = shown.tail.textContent + shown.pending;
    shown.pending = '';
    if (text.length > keep) {  // all that is kept is new
      text = text.slice(-keep);
      shown.blocks.forEach((b) => b.remove());
      shown.blocks = [];
      shown.size = 0;
    }
    const cut = text.lastIndexOf('\n') + 1;
    if (cut > 0) {
      const block = document.createElement('div');
      block.textContent = text.slice(0, cut);
      output.insertBefore(block, shown.tail);
      shown.blocks.push(block);
      shown.size += cut;
    }
    shown.tail.textContent = text.slice(cut);
    while (shown.size > keep && shown.blocks.length) {
      const first = shown.blocks[0], n = first.textContent.length;
      if (shown.size - n >= keep) {
        first.remove();
        shown.blocks.shift();
        shown.size -= n;
      } else {
        first.textContent = first.textContent.slice(shown.size - keep);
        shown.size = keep;
      }
    }
    $('outputPane').scrollTop = $('outputPane').scrollHeight;
  }
  // The run's frames: the newest is drawn once a frame.
  let nextFrame = null, frameRequest = 0;
  function showFrame(f) {
    nextFrame = f;
    if (!frameRequest) frameRequest = requestAnimationFrame(() => { frameRequest = 0; drawPending(); });
  }
  function drawPending() {
    if (nextFrame) drawFrame(nextFrame);
    nextFrame = null;
  }
  function drawFrame(f) {
    ctx.putImageData(new ImageData(f.rgba, f.width, f.height), 0, 0);
  }
  function clearScreen() {
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, 800, 600);
  }
  const io = {
    controls: showControls,
    inputLine: (prompt) => new Promise((resolve) => {
      flushOutput();
      const form = $('inputForm'), line = $('inputLine');
      form.hidden = false;
      line.value = '';
      line.focus();
      waitingFor = 'input';
      showStatus();
      $('outputPane').scrollTop = $('outputPane').scrollHeight;
      const finish = (value) => {
        form.hidden = true; form.onsubmit = null; cancelInput = null;
        waitingFor = '';
        showStatus();
        resolve(value);
      };
      form.onsubmit = (e) => { e.preventDefault(); finish(line.value); };
      cancelInput = () => finish(null);
    }),
    messageBox: (text, title) => new Promise((resolve) => {
      flushOutput();
      drawPending();
      const d = $('msgbox');
      $('msgTitle').textContent = title || 'Message';
      $('msgText').textContent = text;
      waitingFor = 'an answer to the message box';
      showStatus();
      const finish = () => {
        d.onclose = null; cancelDialog = null; if (d.open) d.close(); canvas.focus();
        waitingFor = '';
        showStatus();
        resolve();
      };
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

  // ---------------------------------------------------------------- the speed
  // The slider from slow (left) to fast (right): the milliseconds each pixel or degree of robot
  // motion takes (as the live terminal view paces it); the right end is instantaneous. The
  // default, 2 ms, is the speed docs/web.md's figures are for.
  const SPEED_MS = [40, 20, 10, 6, 4, 3, 2, 1, 0.5, 0.2, 0];
  function speedMs() {
    const i = Math.min(SPEED_MS.length - 1, Math.max(0, Math.round(Number($('speed').value))));
    return SPEED_MS[i];
  }
  function showSpeed() {
    const ms = speedMs();
    const text = ms ? `${ms} ms per pixel or degree of robot motion` : 'as fast as it goes (no animation)';
    $('speed').title = text;
    $('speed').setAttribute('aria-valuetext', text);
    if (run) run.setSpeed(ms);
  }
  $('speed').addEventListener('input', showSpeed);
  showSpeed();

  // ---------------------------------------------------------------- the debugger
  // Paused or stepping, the run shows where it stands, the variables (the core's look at the
  // running program, as the live terminal view shows them) and the watch expressions, which the
  // core computes with the program's variables (core/machine/watch.h). Watches are kept with the
  // page.
  const WATCHES = 'rb.watches';
  let watchList = [];
  try { watchList = JSON.parse(localStorage.getItem(WATCHES) || '[]').filter((w) => typeof w === 'string'); } catch (e) { watchList = []; }
  function cell(row, text, cls) {
    const td = document.createElement('td');
    td.textContent = text;
    if (cls) td.className = cls;
    row.appendChild(td);
  }
  function showPaused(info) {
    paused = true;
    pausing = false;
    flushOutput();
    drawPending();
    setRunning(true);
    editor.setStepLine(info.line);
    status.textContent = info.where === 'before' ? `paused before line ${info.line}` : `paused in line ${info.line}`;
    const panel = $('debugger');
    panel.hidden = false;
    $('debugWhere').textContent = info.where === 'before' ? `Paused before line ${info.line}`
      : `Paused in line ${info.line} (inside the statement: Step finishes it)`;
    const vars = $('variables');
    vars.textContent = '';
    let inSub = false;
    for (const v of info.vars) {
      if (v.local && !inSub) {
        inSub = true;
        const row = vars.insertRow();
        cell(row, `in sub ${info.sub}`, 'sub');
        row.firstChild.colSpan = 2;
      }
      const row = vars.insertRow();
      cell(row, v.name, 'name');
      cell(row, v.value, 'value');
    }
    if (!info.vars.length) cell(vars.insertRow(), 'no variables yet', 'none');
    const list = $('watches');
    list.textContent = '';
    info.watches.forEach((w, i) => {
      const li = document.createElement('li');
      const x = document.createElement('button');
      x.textContent = '×';
      x.title = 'Stop watching ' + w.expr;
      x.onclick = () => setWatches(watchList.filter((_, k) => k !== i));
      li.appendChild(x);
      li.appendChild(document.createTextNode(w.error !== undefined ? ` ${w.expr}: ` : ` ${w.expr} = `));
      const v = document.createElement('span');
      v.className = w.error !== undefined ? 'error' : 'value';
      v.textContent = w.error !== undefined ? w.error : w.value;
      li.appendChild(v);
      list.appendChild(li);
    });
  }
  function hidePaused() {
    paused = false;
    editor.setStepLine(0);
    $('debugger').hidden = true;
  }
  function setWatches(list) {
    watchList = list;
    localStorage.setItem(WATCHES, JSON.stringify(list));
    if (run) {
      run.setWatches(list);
      if (paused) run.refresh();
    }
  }
  $('watchForm').onsubmit = (e) => {
    e.preventDefault();
    const text = $('watchInput').value.trim();
    if (text && !watchList.includes(text)) setWatches([...watchList, text]);
    $('watchInput').value = '';
  };

  function limits() {
    return {
      maxSteps: Number($('maxSteps').value) || 0,
      timeout: Number($('timeout').value) || 0,
      maxMemory: Number($('maxMemory').value) || 0,
    };
  }
  let latest = null;  // the last run started (its SVG comes after its end)
  async function runProgram() {
    if (run) return;
    clearTimeout(checkTimer);  // the end of the run checks the text
    lastSvg = null;
    clearOutput();
    nextFrame = null;
    editor.setErrorLine(0);
    clearScreen();
    showControls({buttons: [], edits: [], focus: ''});
    paused = pausing = false;
    waitingFor = '';
    $('debugger').hidden = true;
    status.textContent = 'running';
    alertError('');
    const started = performance.now();
    canvas.focus();
    const r = rb.start(editor.value, Object.assign(limits(), {
      io,
      png: false,
      svg: true,
      stepMs: speedMs(),
      watches: watchList,
      onOutput: (t) => appendOutput(t),
      onFrame: showFrame,
      onPaused: showPaused,
      onSvg: (text) => {
        if (latest !== r) return;
        lastSvg = text;
        if (!run) setRunning(false);
      },
      onResumed: () => { if (paused) { hidePaused(); showStatus(); setRunning(true); } },
      onWaiting: (what) => {
        waitingFor = what === 'key' ? 'a key' : what === 'click' ? 'a click' : what;
        if (what) { flushOutput(); drawPending(); }
        showStatus();
      },
      onState: (st) => say(describeState(st)),
    }));
    run = latest = r;
    setRunning(true);
    let result;
    try {
      result = await r.done;
    } catch (e) {
      result = {status: 'error', error: String(e), output: ''};
    }
    run = null;
    hidePaused();
    pausing = false;
    waitingFor = '';
    if (cancelInput) cancelInput();
    if (cancelDialog) cancelDialog();
    setRunning(false);
    flushOutput();
    nextFrame = null;
    if (result.frame) drawFrame(result.frame);
    const secs = ((performance.now() - started) / 1000).toFixed(2);
    // The diagnostics again (the text may have changed during the run), and a runtime error
    // marked at its place among them.
    const ran = editor.value;
    if (result.status !== 'rejected') {
      rb.check(ran).then((list) => {
        if (editor.value !== ran) return listDiagnostics(list);
        listDiagnostics(result.errorDiagnostic ? [result.errorDiagnostic, ...list] : list);
      });
    }
    const printed = output.textContent;
    if (result.status === 'rejected') {
      listDiagnostics(result.diagnostics);
      const first = result.diagnostics.find((d) => d.severity === 'error');
      editor.setErrorLine(first ? first.line : 0);
      appendOutput(result.error, 'error');
    } else if (result.error) {
      editor.setErrorLine(result.errorLine || 0);
      appendOutput((printed && !printed.endsWith('\n') ? '\n' : '') + result.error, 'error');
    }
    const steps = typeof result.steps === 'number' ? `, ${result.steps} steps` : '';
    status.textContent = `${result.status} (${secs} s${steps})`;
    const ended = {finished: 'The program finished', stopped: 'The program was stopped', error: 'The program stopped with an error',
                   'step-limit': 'The program stopped at the step limit', timeout: 'The program stopped at the time limit',
                   rejected: 'The program did not compile'}[result.status] || `The program ended: ${result.status}`;
    const after = typeof result.steps === 'number' ? ` after ${result.steps} steps` : '';
    say(`${ended}${after}. ${describeState(result.state)}`.trim(), true);
    if (result.errorMessage) alertError(result.errorLine ? `Error at line ${result.errorLine}: ${result.errorMessage}` : `Error: ${result.errorMessage}`);
    window.rbLastRun = result;
  }
  function stopProgram() {
    if (!run) return;
    run.stop();
    if (cancelInput) cancelInput();
    if (cancelDialog) cancelDialog();
    serial.woken();
  }
  $('run').onclick = runProgram;
  $('stop').onclick = stopProgram;
  $('pause').onclick = () => {
    if (!run) return;
    if (paused || pausing) {
      pausing = false;
      hidePaused();
      run.resume();
    } else {
      pausing = true;
      run.pause();
    }
    setRunning(true);
    showStatus();
  };
  // Step: while paused, one statement; while running, the run stops before its next statement.
  $('step').onclick = () => {
    if (!run) return;
    if (paused) hidePaused();
    pausing = true;  // until the run stops again
    status.textContent = 'stepping';
    setRunning(true);
    run.step();
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

  // ---------------------------------------------------------------- start
  window.rbPage = {runProgram, stopProgram, setSource, shareLink, programFromHash, screen: canvas,
    get source() { return editor.value; },
    get running() { return run !== null; }, ready: null};
  // Offline once loaded: the service worker keeps the site's files (web/sw.js). Browsers run
  // service workers on https:// and on localhost only.
  if ('serviceWorker' in navigator && window.isSecureContext) navigator.serviceWorker.register('sw.js').catch(() => {});
  window.rbPage.ready = (async () => {
    clearScreen();
    // The programs kept, the single one of earlier pages (rb.source) among them, or the first
    // example as the first program.
    if (!book.programs.length) {
      const saved = localStorage.getItem(STORE);
      book.programs.push({id: newId(), name: 'my program',
                          source: saved !== null ? saved : (examples[0] ? examples[0].source : '')});
    }
    if (!current()) book.current = book.programs[0].id;
    writeBook();
    listPrograms();
    resetSource(current().source);
    await openShared();
    await rb.ready();
    listDiagnostics(await rb.check(editor.value));
    rb.prepare();  // the live run's worker, loaded and warmed up before the first Run
    status.textContent = 'ready';
    return true;
  })();
})();
