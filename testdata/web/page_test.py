#!/usr/bin/env python3
"""The web page (build-web/site, built by scripts/web.sh) in a real browser: headless Chromium
driven over the DevTools protocol on a pipe (the Browser of testdata/render/replay_browser.py),
the site served by Python's http.server on a free port.

Usage: page_test.py --rb PATH/TO/rb --source SOURCE_DIR --site SITE_DIR --work WORK_DIR CASE

Exits 77 (skipped) when the site has not been built or Chromium is not installed;
scripts/test.sh builds the site and scripts/setup.sh --test installs Chromium, so CI runs these.
"""

import argparse
import base64
import functools
import hashlib
import http.server
import json
import os
import re
import select
import shutil
import subprocess
import sys
import threading
import time
import tty

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "render"))
from replay_browser import CANVAS_JS as REPLAY_CANVAS_JS  # noqa: E402
from replay_browser import Browser, Failure, expect, find_chromium, first_difference, read_png  # noqa: E402

# The screen's pixels as RGB (__rgb, __b64: replay_browser.py's, from the page's 800x600 screen,
# which its canvas shows scaled), and a PNG data URL's pixels as RGB.
CANVAS_JS = REPLAY_CANVAS_JS.replace("document.getElementById('screen')", "rbPage.screen") + """
window.__pngRgb = async (url) => {
  const img = new Image();
  img.src = url;
  await img.decode();
  const c = document.createElement('canvas');
  c.width = img.width; c.height = img.height;
  const g = c.getContext('2d');
  g.drawImage(img, 0, 0);
  const d = g.getImageData(0, 0, c.width, c.height).data;
  const rgb = new Uint8Array(c.width * c.height * 3);
  for (let i = 0, j = 0; i < d.length; i += 4) { rgb[j++] = d[i]; rgb[j++] = d[i + 1]; rgb[j++] = d[i + 2]; }
  return rgb;
};
true
"""


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass

    def end_headers(self):
        # A server that makes the page cross-origin isolated itself, as a deployment may; without
        # them the page is isolated only once its service worker is in control (web/sw.js).
        if self.server.isolated:
            self.send_header("Cross-Origin-Opener-Policy", "same-origin")
            self.send_header("Cross-Origin-Embedder-Policy", "require-corp")
        super().end_headers()


class Env:
    def __init__(self, args, chromium, isolated=True):
        self.args = args
        self.chromium = chromium
        handler = functools.partial(Quiet, directory=args.site)
        self.server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.server.isolated = isolated
        threading.Thread(target=self.server.serve_forever, daemon=True).start()
        self.url = f"http://127.0.0.1:{self.server.server_address[1]}/index.html"
        self.browser = Browser(chromium, args.work)

    def close(self):
        self.browser.close()
        self.server.shutdown()

    def open(self, url=None):
        b = self.browser
        b.events = [e for e in b.events if e.get("method") != "Page.loadEventFired"]
        b.call("Page.navigate", {"url": url or self.url}, session=True)
        b.wait_event("Page.loadEventFired")
        b.js("window.rbPage.ready")
        b.js(CANVAS_JS)
        return b

    def render(self, path):
        png = os.path.join(self.args.work, "render.png")
        r = subprocess.run([self.args.rb, "render", path, "-o", png], capture_output=True, text=True,
                           timeout=60, stdin=subprocess.DEVNULL)
        expect(r.returncode == 0, f"rb render {path}: exit {r.returncode}\n{r.stderr}")
        return read_png(open(png, "rb").read())

    def expect_rgb(self, got_b64, want, what):
        width, _, want_rgb = want
        got = base64.b64decode(got_b64)
        if hashlib.sha256(got).digest() != hashlib.sha256(want_rgb).digest():
            raise Failure(f"{what} is not rb render's picture: {first_difference(width, got, want_rgb)}")

    def run_page(self, text):
        """Puts `text` in the editor and runs it to its end; returns the run's result."""
        b = self.browser
        b.js(f"rbPage.setSource({json.dumps(text)}); true")
        return b.js("rbPage.runProgram().then(() => ({status: rbLastRun.status, error: rbLastRun.error, "
                    "output: document.getElementById('output').textContent}))")

    def expect_quiet(self):
        b = self.browser
        expect(not b.errors, "the console shows errors:\n" + "\n".join(b.errors))


def case_loads(env):
    """The page loads, checks the program in its editor and shows no console error."""
    b = env.open()
    expect(b.js("document.getElementById('status').textContent") == "ready", "the page is not ready")
    expect(b.js("RB_EXAMPLES.length") >= 5, "the seed's figures are not among the examples")
    env.expect_quiet()
    # Robot commands highlighted: no warning from the highlighter either.
    b.js("rbPage.setSource('rLocate 100, 100\\nrForward 10\\n'); true")
    b.js("new Promise((r) => setTimeout(() => r(true), 300))")
    warnings = [json.dumps(e["params"].get("args", []))[:200] for e in b.events
                if e.get("method") == "Runtime.consoleAPICalled" and e["params"].get("type") == "warning"]
    expect(not warnings, "the console shows warnings:\n" + "\n".join(warnings))


def case_square(env):
    """The seed's square runs on the page and its canvas is rb render's PNG, pixel for pixel;
    rb.run's png too."""
    b = env.open()
    fig = os.path.join(env.args.source, "examples", "fig_1_7.bas")
    want = env.render(fig)
    text = open(fig).read()
    r = env.run_page(text)
    expect(r["status"] == "finished", f"the square ended {r}")
    env.expect_rgb(b.js("__b64(__rgb())"), want, "the page's canvas")
    png = b.js(f"rb.run({json.dumps(text)}, {{seed: 1}}).then((r) => r.png)")
    env.expect_rgb(b.js(f"__pngRgb({json.dumps(png)}).then(__b64)"), want, "rb.run's png")
    # Text, in several faces: the fonts are rasterized as natively.
    textprog = os.path.join(env.args.work, "text.bas")
    with open(textprog, "w") as f:
        f.write('xyText 10,10,"Hello, World 123","Arial",14,fs_Bold\n'
                'xyText 10,60,"Serif italic","Times New Roman",20,fs_Italic\n'
                'xyString 10,120,"print face"\nrLocate 400,300\nrForward 50\n')
    want = env.render(textprog)
    r = env.run_page(open(textprog).read())
    expect(r["status"] == "finished", f"the text program ended {r}")
    env.expect_rgb(b.js("__b64(__rgb())"), want, "the page's canvas (text)")
    env.expect_quiet()


def case_input_keys(env):
    """`input` is answered inline on the page, and keys pressed on the screen reach waitKey; rb.run
    reads its stdin list as rb run reads a pipe."""
    b = env.open()
    b.js("rbPage.setSource('input \"name?\", n\\nprint \"hello \" + n\\nwaitKey k\\nprint \"key \" + k\\n'); "
         "window.__done = rbPage.runProgram(); true")
    wait_for(b, "!document.getElementById('inputForm').hidden", "no input line appeared")
    b.js("document.getElementById('inputLine').value = 'Ada'; "
         "document.getElementById('inputForm').requestSubmit(); true")
    time.sleep(0.3)
    b.js("document.getElementById('screen').focus(); true")
    b.call("Input.dispatchKeyEvent", {"type": "keyDown", "key": "q", "code": "KeyQ", "text": "q",
                                      "windowsVirtualKeyCode": 81}, session=True)
    b.call("Input.dispatchKeyEvent", {"type": "keyUp", "key": "q", "code": "KeyQ",
                                      "windowsVirtualKeyCode": 81}, session=True)
    b.js("window.__done.then(() => true)", timeout=20)
    out = b.js("document.getElementById('output').textContent")
    expect(out == "name?Ada\nhello Ada\nkey 113\n", f"the output was {out!r}")
    # A message box is a page dialog; a click on the screen reaches waitClick at its pixel.
    prog = 'MsgBox "hello", "Title"\nprint "after"\nwaitClick x, y, b\nprint x; ","; y; ","; b\n'
    b.js(f"rbPage.setSource({json.dumps(prog)}); window.__done = rbPage.runProgram(); true")
    wait_for(b, "document.getElementById('msgbox').open", "no message box appeared")
    expect(b.js("document.getElementById('msgText').textContent") == "hello", "the message box's text")
    b.js("document.getElementById('msgOk').click(); true")
    time.sleep(0.3)
    click(b, 200, 100)
    b.js("window.__done.then(() => true)", timeout=20)
    out = b.js("document.getElementById('output').textContent")
    expect(out == "after\n200\t,\t100\t,\t1\n", f"after the message box and the click the output was {out!r}")
    r = b.js("rb.run('input a\\ninput b\\nprint a + b\\n', {stdin: ['2', '3']}).then((r) => [r.output, r.status])")
    expect(r == ["2\n3\n5\n", "finished"], f"rb.run with stdin gave {r}")
    # Keys typed before waitKey (during a delay) answer it, one press each, in order; a getKey
    # drops the presses it has seen (docs/interaction.md).
    prog = 'delay 1000\nwaitKey a\nwaitKey b\nprint a\nprint b\ngetKey k\nwaitKey c\nprint c\n'
    b.js(f"rbPage.setSource({json.dumps(prog)}); window.__done = rbPage.runProgram(); true")
    time.sleep(0.2)
    b.js("document.getElementById('screen').focus(); true")
    for key in "qrs":
        tap(b, key)
    wait_for(b, "document.getElementById('output').textContent.length > 0", "waitKey did not take the keys typed before it")
    tap(b, "t")
    b.js("window.__done.then(() => true)", timeout=20)
    out = b.js("document.getElementById('output').textContent")
    expect(out == "113\n114\n116\n", f"keys typed ahead of waitKey: the output was {out!r}")
    # A run started the moment the one before has ended (its worker still makes that run's SVG):
    # it runs to its end too.
    first = "for i = 1 to 3000\n  Line i % 800, 0, 0, i % 600\nnext\n"
    second = 'delay 200\nprint "second"\n'
    r = b.js(f"rbPage.setSource({json.dumps(first)}); rbPage.runProgram().then(() => {{ "
             f"rbPage.setSource({json.dumps(second)}); return rbPage.runProgram(); }})"
             ".then(() => [rbLastRun.status, document.getElementById('output').textContent])", timeout=30)
    expect(r == ["finished", "second\n"], f"the run started as the one before ended: {r}")
    env.expect_quiet()


def tap(b, key, code=None):
    """A key pressed and released on the page: a letter, or a named key with its code."""
    down = {"type": "keyDown", "key": key, "windowsVirtualKeyCode": code or ord(key.upper())}
    if len(key) == 1:
        down["text"] = key
    elif key == "Enter":
        down["text"] = "\r"
    b.call("Input.dispatchKeyEvent", down, session=True)
    b.call("Input.dispatchKeyEvent", {"type": "keyUp", "key": key, "windowsVirtualKeyCode": down["windowsVirtualKeyCode"]},
           session=True)


def case_share(env):
    """A share link holds the program: opened, it puts the same text in the editor."""
    b = env.open()
    text = 'print "shared ü"\nrLocate 100,100\n' + "// " + "x" * 300 + "\n"
    link = b.js(f"rbPage.shareLink({json.dumps(text)})")
    expect("#code=" in link and len(link) < 400, f"the link is {link}")
    b.call("Page.navigate", {"url": "about:blank"}, session=True)
    b.wait_event("Page.loadEventFired")
    env.open(link)
    got = b.js("rbPage.source")
    expect(got == text, f"the editor holds {got!r}")
    env.expect_quiet()


def case_programs(env):
    """Work is never lost: a share link opens as a copy beside the student's own program (Keep or
    Drop), not in its place; the page keeps several programs (new, rename, delete and its undo)
    across reloads; loading an example can be undone, and the editor's undo never empties it."""
    b = env.open()
    names = "[...document.getElementById('programs').options].map((o) => o.textContent)"
    notice = "document.getElementById('notice').hidden ? '' : document.getElementById('noticeText').textContent"

    def reopen(url=None):
        b.call("Page.navigate", {"url": "about:blank"}, session=True)
        b.wait_event("Page.loadEventFired")
        env.open(url)

    def press(label):
        b.js(f"[...document.querySelectorAll('#noticeActions button')].find((x) => x.textContent === {json.dumps(label)}).click(); true")

    # The editor's undo at once: the text the page opened with stays.
    first = b.js("rbPage.source")
    b.js("document.querySelector('.cm-content').focus(); true")
    b.call("Input.dispatchKeyEvent", {"type": "keyDown", "key": "z", "code": "KeyZ", "modifiers": 2,
                                      "windowsVirtualKeyCode": 90}, session=True)
    b.call("Input.dispatchKeyEvent", {"type": "keyUp", "key": "z", "code": "KeyZ", "modifiers": 2,
                                      "windowsVirtualKeyCode": 90}, session=True)
    expect(b.js("rbPage.source") == first and first, f"undo right after loading gave {b.js('rbPage.source')!r}")
    mine = 'print "mine"\n'
    b.js(f"rbPage.setSource({json.dumps(mine)}); true")
    link = b.js("rbPage.shareLink('print \"shared\"\\n')")
    reopen(link)
    expect(b.js("rbPage.source") == 'print "shared"\n', f"the shared program is not open: {b.js('rbPage.source')!r}")
    expect(b.js(names) == ["my program", "shared program"], f"the programs: {b.js(names)}")
    expect("beside your own" in b.js(notice), f"the notice: {b.js(notice)!r}")
    expect("#" not in b.js("location.href"), "the link stays in the address bar")
    press("Drop")
    expect(b.js(names) == ["my program"] and b.js("rbPage.source") == mine,
           f"after Drop: {b.js(names)}, {b.js('rbPage.source')!r}")
    reopen(link)
    press("Keep")
    reopen()  # a reload: the programs kept, no second copy
    expect(b.js(names) == ["my program", "shared program"] and b.js("rbPage.source") == 'print "shared"\n',
           f"after a reload: {b.js(names)}, {b.js('rbPage.source')!r}")
    # New, rename, delete and undo it.
    b.js("document.getElementById('newProgram').click(); true")
    expect(b.js(names) == ["my program", "shared program", "program"] and b.js("rbPage.source") == "",
           f"after New: {b.js(names)}")
    b.js("rbPage.setSource('print 3\\n'); document.getElementById('renameProgram').click(); "
         "document.getElementById('nameInput').value = 'third'; "
         "document.querySelector('#nameDialog button[value=ok]').click(); true")
    wait_for(b, f"{names}[2] === 'third'", f"after Rename: {b.js(names)}")
    b.js("document.getElementById('programs').value = document.getElementById('programs').options[0].value; "
         "document.getElementById('programs').dispatchEvent(new Event('change')); true")
    expect(b.js("rbPage.source") == mine, f"my program holds {b.js('rbPage.source')!r}")
    b.js("document.getElementById('deleteProgram').click(); true")
    expect(b.js(names) == ["shared program", "third"], f"after Delete: {b.js(names)}")
    press("Undo")
    expect(b.js(names) == ["my program", "shared program", "third"] and b.js("rbPage.source") == mine,
           f"after undoing the delete: {b.js(names)}, {b.js('rbPage.source')!r}")
    # An example replaces the open program's text; Undo brings it back.
    b.js("const e = document.getElementById('examples'); e.value = '0'; e.dispatchEvent(new Event('change')); true")
    expect(b.js("rbPage.source") == b.js("RB_EXAMPLES[0].source"), "the example was not loaded")
    press("Undo")
    expect(b.js("rbPage.source") == mine, f"undoing the example gave {b.js('rbPage.source')!r}")
    reopen()
    kept = b.js("JSON.parse(localStorage.getItem('rb.programs')).programs.map((p) => [p.name, p.source])")
    expect(kept == [["my program", mine], ["shared program", 'print "shared"\n'], ["third", "print 3\n"]],
           f"the programs kept: {kept}")
    env.expect_quiet()


def case_stop(env):
    """Stop ends an endless loop within 100 ms, and the page stays responsive while it runs."""
    b = env.open()
    b.js("rbPage.setSource('x = 0\\nwhile 1\\n  x = x + 1\\nwend\\n'); window.__done = rbPage.runProgram(); true")
    time.sleep(1.0)
    # The page answers while the loop runs: a timer fires on time.
    late = b.js("new Promise((r) => { const t = performance.now(); setTimeout(() => r(performance.now() - t - 50), 50); })")
    expect(late < 100, f"a 50 ms timer fired {late:.0f} ms late while the program ran")
    expect(b.js("rbPage.running"), "the endless loop is not running")
    took = b.js("(async () => { const t = performance.now(); rbPage.stopProgram(); await window.__done; "
                "return performance.now() - t; })()")
    expect(took < 100, f"Stop took {took:.0f} ms")
    expect(b.js("rbLastRun.status") == "stopped", "the run did not end as stopped")
    # rb.run runs in a Web Worker: the page answers while it loops, and rb.stop() ends it.
    b.js("window.__api = rb.run('x = 0\\nwhile 1\\n  x = x + 1\\nwend\\n'); true")
    time.sleep(1.0)
    late = b.js("new Promise((r) => { const t = performance.now(); setTimeout(() => r(performance.now() - t - 50), 50); })")
    expect(late < 100, f"a 50 ms timer fired {late:.0f} ms late while rb.run looped")
    took = b.js("(async () => { const t = performance.now(); rb.stop(); const r = await window.__api; "
                "return [performance.now() - t, r.status]; })()")
    expect(took[0] < 100 and took[1] == "stopped", f"rb.stop() of rb.run: {took}")
    r = b.js("rb.run('print 6 * 7\\n').then((r) => r.output)")
    expect(r == "42\n", f"rb.run after a stopped one printed {r!r}")
    # A delay and a waitKey end at Stop too.
    for prog in ["delay 100000\\n", "waitKey k\\n", "input a\\n"]:
        b.js(f"rbPage.setSource('{prog}'); window.__done = rbPage.runProgram(); true")
        time.sleep(0.3)
        took = b.js("(async () => { const t = performance.now(); rbPage.stopProgram(); await window.__done; "
                    "return performance.now() - t; })()")
        expect(took < 100, f"Stop of {prog!r} took {took:.0f} ms")
        expect(b.js("rbLastRun.status") == "stopped", f"{prog!r} ended {b.js('rbLastRun.status')}")
    env.expect_quiet()


# While a run goes on: a 50 ms timer after another on the page, each one's delay past its 50 ms
# noted, until the run ends (or `seconds` have passed, then Stop, timed); the run's own time
# (from Run to its end shown) in `seconds` (bench/web_page_run.py measures with it too). `late`
# is the second longest delay, `worst` the longest: one hiccup of a busy test machine (CI builds beside the
# tests) is allowed once, a page held up by its run delays every timer.
TICKER_JS = """
(async () => {
  const lates = [];
  let on = true;
  const ticker = (async () => {
    while (on) {
      const t = performance.now();
      await new Promise((r) => setTimeout(r, 50));
      lates.push(performance.now() - t - 50);
    }
  })();
  const started = performance.now();
  const done = rbPage.runProgram();
  let stop = null;
  if (%(seconds)s > 0) {
    await Promise.race([done, new Promise((r) => setTimeout(r, %(seconds)s * 1000))]);
    const t = performance.now();
    rbPage.stopProgram();
    await done;
    stop = performance.now() - t;
  }
  await done;
  const seconds = (performance.now() - started) / 1000;
  on = false;
  await ticker;
  const out = document.getElementById('output').textContent;
  lates.sort((a, b) => b - a);
  return {late: lates[Math.min(1, lates.length - 1)] || 0, worst: lates[0] || 0, timers: lates.length, seconds, stop,
          status: rbLastRun.status,
          shown: out.length, end: out.slice(-12), output: rbLastRun.output.length};
})()
"""


def case_never_frozen(env):
    """A live run never holds up the page, in both ways the page runs programs (a worker on the
    fast core with shared memory when the page is cross-origin isolated, else the Asyncify core
    in a worker): a timer set during an endless printing loop, an endless computing loop and
    30,000 prints fires within 100 ms, Stop ends the endless ones within 200 ms, and the output
    pane keeps the last `output kept` KiB of a long output."""
    for isolated, mode in ((False, "async"), (True, "sab")):
        # The first visit is not isolated (the service worker is not in control yet); then the
        # server sends the headers.
        env.server.isolated = isolated
        b = env.open()
        got = b.js("rb.prepare()")
        expect(got == mode, f"the page runs programs in {got!r} mode, not {mode!r}")
        b.js("document.getElementById('keepOutput').value = '16'; true")
        for prog in ("i = 0\nwhile 1\n  print i\n  i = i + 1\nwend\n", "x = 0\nwhile 1\n  x = x + 1\nwend\n"):
            b.js(f"rbPage.setSource({json.dumps(prog)}); true")
            r = b.js(TICKER_JS % {"seconds": 1.5}, timeout=60)
            expect(r["timers"] >= 10 and r["late"] < 100 and r["worst"] < 1000,
                   f"{mode}: {prog!r}: timers fired {r['late']:.0f} and {r['worst']:.0f} ms late ({r})")
            expect(r["status"] == "stopped" and r["stop"] < 200, f"{mode}: {prog!r}: Stop took {r['stop']:.0f} ms ({r})")
            expect(r["shown"] <= 16 * 1024, f"{mode}: {prog!r}: the pane shows {r['shown']} characters")
        # (Fewer on the Asyncify core, three times as slow: the suite stays quick.)
        n = 30000 if mode == "sab" else 8000
        b.js(f"rbPage.setSource('for i = 1 to {n}\\n  print i\\nnext\\n'); true")
        r = b.js(TICKER_JS % {"seconds": 0}, timeout=120)
        expect(r["status"] == "finished" and r["late"] < 100 and r["worst"] < 1000,
               f"{mode}: {n} prints: timers fired {r['late']:.0f} and {r['worst']:.0f} ms late ({r})")
        expect(r["end"].endswith(f"{n - 1}\n{n}\n") and 16 * 1024 - 8 <= r["shown"] <= 16 * 1024,
               f"{mode}: the pane does not show the last 16 KiB of the output: {r}")
        expect(r["output"] == sum(len(str(i)) + 1 for i in range(1, n + 1)), f"{mode}: the run's output is cut: {r}")
    env.expect_quiet()


def case_step(env):
    """Pause, then Step runs one statement at a time: the run stops before each line, marks it in
    the editor, and has printed only what the statements before it print; Resume runs on."""
    b = env.open()
    prog = 'delay 400\nprint "a"\nprint "b"\nprint "c"\n'
    b.js(f"rbPage.setSource({json.dumps(prog)}); window.__done = rbPage.runProgram(); true")
    b.js("document.getElementById('pause').click(); true")
    out = lambda: b.js("document.getElementById('output').textContent")
    state = lambda: b.js("document.getElementById('status').textContent")
    # The run pauses where it is when it next looks (before line 1, or inside the delay).
    wait_for(b, "/^paused (before|in) line 1$/.test(document.getElementById('status').textContent)",
             "Pause did not pause the run in line 1")

    def step_to(line):
        b.js("document.getElementById('step').click(); true")
        deadline = time.monotonic() + 10
        while state() != f"paused before line {line}":
            expect(time.monotonic() < deadline, f"the run did not stop before line {line}: {state()!r}")
            time.sleep(0.05)

    step_to(2)
    expect(out() == "", f"before line 2 the output is {out()!r}")
    step_to(3)
    expect(out() == "a\n", f"before line 3 the output is {out()!r}")
    marked = b.js("(() => { const l = document.querySelector('.rb-stepline'); return l ? l.textContent : ''; })()")
    expect(marked == 'print "b"', f"the editor marks {marked!r}, not line 3")
    step_to(4)
    expect(out() == "a\nb\n", f"before line 4 the output is {out()!r}")
    b.js("document.getElementById('pause').click(); true")  # Resume
    b.js("window.__done.then(() => true)", timeout=20)
    expect(b.js("rbLastRun.status") == "finished", f"the run ended {b.js('rbLastRun.status')}")
    expect(out() == "a\nb\nc\n", f"the output is {out()!r}")
    expect(not b.js("document.querySelector('.rb-stepline')"), "the stepped line stays marked after the run")
    env.expect_quiet()


def case_error_line(env):
    """A runtime error is shown with rb run's message and its line is marked in the editor; a
    program that does not compile shows its error at its line too."""
    b = env.open()
    r = env.run_page('print "a"\nx = 0\nprint 1 / x\nprint "b"\n')
    expect(r["status"] == "error", f"the run ended {r['status']}")
    expect("program.bas:3:" in r["error"] and "division by zero" in r["error"], f"the error is {r['error']!r}")
    marked = b.js("[...document.querySelectorAll('.cm-line.rb-errline')].map((e) => e.textContent)")
    expect(marked == ["print 1 / x"], f"the marked lines are {marked}")
    r = env.run_page('print "a"\ngosub Nowhere\n')
    expect(r["status"] == "rejected" and "program.bas:2:" in r["error"], f"the load error is {r}")
    listed = b.js("[...document.querySelectorAll('#diagnostics li.error')].map((e) => e.dataset.line)")
    expect(listed == ["2"], f"the errors listed are at lines {listed}")
    marked = b.js("document.querySelectorAll('.cm-lint-marker-error').length")
    expect(marked == 1, f"the gutter marks {marked} errors")
    # A variable with no value: the runtime error is marked where rb check's warning is, on the
    # name (not the operator), and both where the name is on a line with accents before it (rb's
    # columns count UTF-8 bytes, the editor's UTF-16 code units).
    r = env.run_page('s = "héllo wörld" + zz\nprint s\n')
    expect(r["status"] == "error" and "program.bas:1:23:" in r["error"], f"the error is {r['error']!r}")
    listed = "[...document.querySelectorAll('#diagnostics li')].map((e) => e.textContent.split(': ').slice(0, 2).join(' '))"
    wait_for(b, f"{listed}.length === 2", "the error and the warning are not both listed")
    expect(b.js(listed) == ["1:23 error", "1:23 warning"], f"the error and the warning are listed at {b.js(listed)}")
    marks = "[...document.querySelectorAll('.cm-lintRange')].map((e) => e.textContent)"
    expect(b.js(marks) == ["z"], f"the editor marks {b.js(marks)}, not the name")
    # The same limits as rb run: --max-steps.
    r = b.js("rb.run('while 1\\nwend\\n', {maxSteps: 1000}).then((r) => r.error)")
    expect("stopped after 1000 steps (the --max-steps limit)" in r, f"the step limit said {r!r}")
    env.expect_quiet()


def case_debugger(env):
    """Paused, the page shows where the run stands, its variables (current inside a robot motion,
    as the core has them) and watch expressions; Step finishes the statement and stops before
    the next; the status says what a run waits for; the speed slider runs slow (left) to fast
    (right); a crash reports the statements it ran."""
    b = env.open()
    state = lambda: b.js("document.getElementById('status').textContent")  # noqa: E731
    expect("one statement" in b.js("document.getElementById('step').title"), "Step's tooltip")
    expect("Pause" in b.js("document.getElementById('pause').title") or
           "pause" in b.js("document.getElementById('pause').title"), "Pause's tooltip")
    # The slowest speed: the first side takes seconds; paused inside it.
    b.js("document.getElementById('speed').value = '0'; document.getElementById('speed').dispatchEvent(new Event('input')); true")
    prog = ("rLocate 400, 300\nn = 0\nfor side = 1 to 4\n  rForward 100\n  rTurn 90\n  n = n + 1\nnext\n"
            "print \"done\"\n")
    b.js(f"rbPage.setSource({json.dumps(prog)}); window.__done = rbPage.runProgram(); true")
    time.sleep(0.5)
    b.js("document.getElementById('pause').click(); true")
    wait_for(b, "document.getElementById('status').textContent.startsWith('paused')", "Pause did not pause")
    expect(state() == "paused in line 4", f"paused inside the first side, the status is {state()!r}")
    variables = "[...document.querySelectorAll('#variables tr')].map((r) => r.textContent)"
    expect(b.js(variables) == ["n0", "side1"], f"the variables shown: {b.js(variables)}")
    expect(b.js("document.getElementById('debugger').hidden") is False, "the debugger is hidden")
    # A watch, computed by the core with the program's variables.
    b.js("document.getElementById('watchInput').value = 'side * 10 + n'; "
         "document.getElementById('watchForm').requestSubmit(); true")
    watches = "[...document.querySelectorAll('#watches li')].map((l) => l.textContent)"
    wait_for(b, f"{watches}.length === 1 && {watches}[0].includes('= 10')", f"the watch shows {b.js(watches)}")
    b.js("document.getElementById('watchInput').value = 'nothing + 1'; "
         "document.getElementById('watchForm').requestSubmit(); true")
    wait_for(b, f"{watches}.length === 2 && {watches}[1].endsWith(\": the program has no variable 'nothing'\")",
             f"the watches show {b.js(watches)}")
    b.js("document.querySelectorAll('#watches li button')[1].click(); true")
    wait_for(b, f"{watches}.length === 1", "the watch was not removed")
    # Step: the side is finished, then one statement at a time, the variables current.
    b.js("document.getElementById('speed').value = '10'; document.getElementById('speed').dispatchEvent(new Event('input')); true")
    b.js("document.getElementById('step').click(); true")
    wait_for(b, "document.getElementById('status').textContent === 'paused before line 5'",
             f"Step did not stop before line 5: {state()!r}")
    for line in (6, 7, 4):
        b.js("document.getElementById('step').click(); true")
        wait_for(b, f"document.getElementById('status').textContent === 'paused before line {line}'",
                 f"Step did not stop before line {line}: {state()!r}")
    expect(b.js(variables) == ["n1", "side2"], f"before the second side the variables are {b.js(variables)}")
    expect(b.js(f"{watches}[0]").endswith("= 21"), f"the watch shows {b.js(watches)}")
    b.js("document.getElementById('pause').click(); true")  # Resume
    b.js("window.__done.then(() => true)", timeout=30)
    expect(b.js("rbLastRun.status") == "finished", f"the run ended {b.js('rbLastRun.status')}")
    expect(b.js("document.getElementById('debugger').hidden"), "the debugger stays after the run")
    # What a run waits for.
    for prog, what, act in (("waitKey k\n", "waiting for a key", "key"), ("waitClick x, y, b\n", "waiting for a click", "click"),
                            ("input a\n", "waiting for input", "input")):
        b.js(f"rbPage.setSource({json.dumps(prog)}); window.__done = rbPage.runProgram(); true")
        wait_for(b, f"document.getElementById('status').textContent === {json.dumps(what)}", f"{prog!r}: the status is {state()!r}")
        if act == "key":
            b.js("document.getElementById('screen').focus(); true")
            b.call("Input.dispatchKeyEvent", {"type": "keyDown", "key": "a", "code": "KeyA", "text": "a",
                                              "windowsVirtualKeyCode": 65}, session=True)
            b.call("Input.dispatchKeyEvent", {"type": "keyUp", "key": "a", "code": "KeyA", "windowsVirtualKeyCode": 65},
                   session=True)
        elif act == "click":
            click(b, 10, 10)
        else:
            b.js("document.getElementById('inputLine').value = '1'; document.getElementById('inputForm').requestSubmit(); true")
        b.js("window.__done.then(() => true)", timeout=20)
        expect(b.js("rbLastRun.status") == "finished", f"{prog!r} ended {b.js('rbLastRun.status')}")
    # Right is faster: a side at the middle of the slider takes longer than at its right end.
    timed = "rbPage.runProgram().then(() => rbLastRun.status)"
    b.js("rbPage.setSource('rLocate 400, 300\\nrForward 60\\n'); true")
    took = {}
    for value in ("5", "10"):
        b.js(f"document.getElementById('speed').value = '{value}'; document.getElementById('speed').dispatchEvent(new Event('input')); true")
        t = time.monotonic()
        expect(b.js(timed) == "finished", "the side did not finish")
        took[value] = time.monotonic() - t
    expect(took["5"] > took["10"] + 0.1, f"the slider's middle is not slower than its right end: {took}")
    # A crash into the wall: the statements it ran, not "0 steps".
    r = env.run_page("rLocate 400, 300\nx = 1\nrForward 1000\n")
    expect(r["status"] == "error", f"the crash ended {r}")
    expect(re.fullmatch(r"error \([0-9.]+ s, 3 steps\)", state()), f"after the crash the status is {state()!r}")
    env.expect_quiet()


def case_screen(env):
    """The screen stays readable at 1366x768 (the screen shown smaller than its 800x600): every
    1-pixel line is still seen, each row of it, as it is not when the shown pixels are the
    nearest of the screen's; Larger gives the screen more room and Full screen the whole
    display."""
    b = env.browser
    b.call("Emulation.setDeviceMetricsOverride", {"width": 1366, "height": 768, "deviceScaleFactor": 1, "mobile": False},
           session=True)
    env.open()
    xs, ys = list(range(100, 256, 6)), list(range(420, 576, 6))
    prog = "".join(f"line {x}, 100, {x}, 400\n" for x in xs) + "".join(f"line 300, {y}, 700, {y}\n" for y in ys)
    r = env.run_page(prog)
    expect(r["status"] == "finished", f"the lines ended {r}")
    box = b.js("(() => { const c = document.getElementById('screen'), r = c.getBoundingClientRect(); "
               "return {left: r.left + c.clientLeft, top: r.top + c.clientTop, w: c.clientWidth, h: c.clientHeight}; })()")
    scale = min(box["w"] / 800, box["h"] / 600)
    expect(scale < 0.95, f"the screen is shown at {scale:.2f}: nothing to test at this size")
    ox = box["left"] + (box["w"] - 800 * scale) / 2
    oy = box["top"] + (box["h"] - 600 * scale) / 2
    width, height, rgb = b.screenshot(1366, 768)

    def grey(px, py):
        i = (py * width + px) * 3
        return (rgb[i] + rgb[i + 1] + rgb[i + 2]) // 3

    lost = []
    for x in xs:  # each row of each vertical line has a dark pixel where the line is
        cols = range(int(ox + x * scale) - 1, int(ox + (x + 1) * scale) + 2)
        rows = range(int(oy + 100 * scale) + 2, int(oy + 400 * scale) - 2)
        faint = [py for py in rows if min(grey(px, py) for px in cols) > 200]
        if faint:
            lost.append(f"x={x}: {len(faint)} of {len(rows)} rows")
    for y in ys:
        rows = range(int(oy + y * scale) - 1, int(oy + (y + 1) * scale) + 2)
        cols = range(int(ox + 300 * scale) + 2, int(ox + 700 * scale) - 2)
        faint = [px for px in cols if min(grey(px, py) for py in rows) > 200]
        if faint:
            lost.append(f"y={y}: {len(faint)} of {len(cols)} columns")
    expect(not lost, f"at scale {scale:.3f} lines fade out: {'; '.join(lost)}")
    # Larger: more room; Full screen: the whole display.
    before = b.js("document.getElementById('screen').clientWidth")
    b.js("document.getElementById('larger').click(); true")
    wait_for(b, f"document.getElementById('screen').clientWidth > {before} + 100", "Larger left the screen as it was")
    b.js("document.getElementById('larger').click(); true")
    cx, cy = b.js("(() => { const r = document.getElementById('fullscreen').getBoundingClientRect(); "
                  "return [r.left + r.width / 2, r.top + r.height / 2]; })()")
    for kind in ("mousePressed", "mouseReleased"):
        b.call("Input.dispatchMouseEvent", {"type": kind, "x": cx, "y": cy, "button": "left", "clickCount": 1}, session=True)
    wait_for(b, "document.fullscreenElement && document.fullscreenElement.id === 'screenBox' && "
                "document.getElementById('screen').clientHeight >= innerHeight - 2", "Full screen did not fill the display")
    b.js("document.exitFullscreen().then(() => true)")
    env.expect_quiet()


def client_point(b, x, y):
    """The page coordinates of screen pixel (x, y)'s centre on the scaled canvas (the picture
    fitted in the canvas's content box)."""
    return b.js(f"(() => {{ const c = document.getElementById('screen'), r = c.getBoundingClientRect(); "
                f"const w = c.clientWidth, h = c.clientHeight, s = Math.min(w / 800, h / 600); "
                f"return [r.left + c.clientLeft + (w - 800 * s) / 2 + {x + 0.5} * s, "
                f"r.top + c.clientTop + (h - 600 * s) / 2 + {y + 0.5} * s]; }})()")


def click(b, x, y):
    cx, cy = client_point(b, x, y)
    for kind in ("mousePressed", "mouseReleased"):
        b.call("Input.dispatchMouseEvent", {"type": kind, "x": cx, "y": cy, "button": "left", "clickCount": 1},
               session=True)


def wait_for(b, expression, what, timeout=20):
    deadline = time.monotonic() + timeout
    while True:
        value = b.js(expression)
        if value:
            return value
        expect(time.monotonic() < deadline, what)
        time.sleep(0.05)


def case_controls(env):
    """The program's buttons and edit boxes show over the screen where the program put them; a
    click on an edit box gives it the keys typed next (Backspace deletes, Enter gives the keyboard
    back), a click on a button presses it: core/input's rules, as in the live terminal view. A Tab
    right after the Enter moves the focus on, though the run (in a delay) has not taken the keys yet."""
    b = env.open()
    prog = ('AddButton "Go", 100, 100\nAddEdit "Name", 100, 200, 120, "Bob"\n'
            'repeat\n  GetButton b\n  delay 300\nuntil b = "Go"\nprint "name=" + GetEdit("Name")\n')
    b.js(f"rbPage.setSource({json.dumps(prog)}); window.__done = rbPage.runProgram(); true")
    shown = ("[...document.querySelectorAll('#controls > *')].map((d) => [d.className, d.textContent, "
             "(() => { const r = d.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; })()])")
    wait_for(b, f"{shown}.length === 2", "the button and the edit box did not appear")
    controls = b.js(shown)
    expect([c[:2] for c in controls] == [["rb-button", "Go"], ["rb-edit", "Bob"]], f"the controls shown: {controls}")
    # Where the program put them: the edit box from (100, 200), 120 wide, 24 high.
    left, top = client_point(b, 100 - 0.5, 200 - 0.5)
    right, bottom = client_point(b, 220 - 0.5, 224 - 0.5)
    got = controls[1][2]
    expect(all(abs(a - w) < 1.01 for a, w in zip(got, (left, top, right, bottom))),
           f"the edit box is at {got}, not at {(left, top, right, bottom)}")
    click(b, 150, 210)
    wait_for(b, "document.querySelector('#controls .rb-edit.focus') !== null", "the edit box did not take the keyboard")
    for key, code in (("Backspace", 8), ("x", 88), ("y", 89), ("Enter", 13), ("Tab", 9)):
        tap(b, key, code)
    focus = b.js("document.activeElement.id || document.activeElement.dataset.name")
    expect(focus == "Go", f"Tab right after Enter in the edit box went to {focus!r}, not the program's button")
    wait_for(b, "(() => { const e = document.querySelector('#controls .rb-edit'); "
                "return e.textContent === 'Boxy' && !e.classList.contains('focus'); })()",
             f"the edit box shows {b.js(shown)}")
    click(b, 110, 110)
    b.js("window.__done.then(() => true)", timeout=20)
    out = b.js("document.getElementById('output').textContent")
    expect(out == "name=Boxy\n", f"the output was {out!r}")
    env.expect_quiet()


FAKE_SERIAL_JS = """
(() => {
  let feed;
  window.__robotOut = [];
  window.__robotFeed = (a) => feed.enqueue(new Uint8Array(a));
  const port = {
    readable: new ReadableStream({start(c) { feed = c; }}),
    writable: new WritableStream({write(chunk) { window.__robotOut.push(...chunk); }}),
    open: async (o) => { window.__robotBaud = o.baudRate; },
    close: async () => {},
    getInfo: () => ({usbVendorId: 0x2341, usbProductId: 0x43}),
  };
  Object.defineProperty(navigator, 'serial', {configurable: true, value: {requestPort: async () => port}});
  return true;
})()
"""


class RobotEmulator:
    """`rb robot --pty`, with this end of its pseudo-terminal open raw: a robot on a serial line."""

    def __init__(self, rb, *options):
        self.proc = subprocess.Popen([rb, "robot", "--pty", *options], stdout=subprocess.PIPE,
                                     stderr=subprocess.DEVNULL)
        ready, _, _ = select.select([self.proc.stdout], [], [], 10)
        expect(ready, "rb robot printed no device")
        self.device = self.proc.stdout.readline().decode().strip()
        self.fd = None

    def open(self):
        self.fd = os.open(self.device, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.fd)

    def close(self):
        if self.fd is not None:
            os.close(self.fd)
        self.proc.terminate()
        self.proc.wait(5)


def serial_run(env, text, *options, cancel=False, stop_after=None):
    """Runs `text` on the page with a Web Serial port whose bytes go to and from `rb robot`: what
    the page writes goes down the emulator's line, what it answers comes back, as on a cable."""
    b = env.browser
    robot = RobotEmulator(env.args.rb, *options)
    try:
        robot.open()
        b.js(FAKE_SERIAL_JS)
        b.js(f"rbPage.setSource({json.dumps(text)}); window.__done = rbPage.runProgram(); true")
        wait_for(b, "document.getElementById('serialDialog').open", "the page did not ask for a serial port")
        b.js(f"document.getElementById('{'serialDialog' if cancel else 'serialChoose'}')"
             f".{'close' if cancel else 'click'}(); true")
        start = time.monotonic()
        deadline, stopped = start + 30, None
        while not b.js("window.rbLastRun !== undefined && !rbPage.running"):
            expect(time.monotonic() < deadline, "the run with a robot did not end")
            if stop_after is not None and stopped is None and time.monotonic() - start > stop_after:
                b.js("rbPage.stopProgram(); true")
                stopped = time.monotonic()
            out = b.js("window.__robotOut.splice(0)")
            if out:
                os.write(robot.fd, bytes(out))
            ready, _, _ = select.select([robot.fd], [], [], 0.02)
            if ready:
                b.js(f"window.__robotFeed({list(os.read(robot.fd, 4096))}); true")
        ended = time.monotonic()
        r = b.js("({status: rbLastRun.status, error: rbLastRun.error, baud: window.__robotBaud, "
                 "output: document.getElementById('output').textContent})")
        r["stop_seconds"] = ended - stopped if stopped else None
        return r
    finally:
        robot.close()


def case_serial(env):
    """rCommPort drives a real robot over Web Serial with rb run --real's protocol: the page asks
    for the port, and a program driving `rb robot` prints what it prints under rb run --port;
    a robot that stops answering is rb run's fault at the program's line; no port, a clear error."""
    b = env.open()
    b.js("window.rbLastRun = undefined; true")
    prog = ('rCommPort 5\nrForward 20\nrTurn 90\nprint "compass "; rCompass()\n'
            'print "feel "; rFeel(); " bumper "; rBumper()\nrCommPort 0\nprint "done"\n')
    path = os.path.join(env.args.work, "serial.bas")
    with open(path, "w") as f:
        f.write(prog)
    native = RobotEmulator(env.args.rb)
    try:
        r = subprocess.run([env.args.rb, "run", "--port", native.device, path], capture_output=True, text=True,
                           timeout=60)
    finally:
        native.close()
    expect(r.returncode == 0 and "\t90\n" in r.stdout, f"rb run --port: {r.returncode} {r.stdout} {r.stderr}")
    got = serial_run(env, prog)
    expect(got["status"] == "finished" and got["output"] == r.stdout,
           f"on the page: {got}, under rb run --port: {r.stdout!r}")
    expect(got["baud"] == 9600, f"the port was opened at {got['baud']} baud")
    # A robot that answers every other command: the second is rb run's fault, at its line.
    b.js("window.rbLastRun = undefined; true")
    got = serial_run(env, "rCommPort 5\nrForward 5\nrForward 5\n", "--drop-every", "2")
    err = got["error"] or ""
    expect(got["status"] == "error" and "program.bas:3:" in err and
           "robot on Web Serial port 5 (USB 2341:0043) at 9600 baud did not answer within 2 s" in err,
           f"a dropped command gave {got}")
    # Stop while the page waits for a robot that never answers: the run ends as stopped, long
    # before the 2 s a reply may take (the stop test times Stop itself; this one's loop polls).
    b.js("window.rbLastRun = undefined; true")
    got = serial_run(env, "rCommPort 5\nrForward 5\n", "--drop-every", "1", stop_after=0.5)
    expect(got["status"] == "stopped" and got["stop_seconds"] < 1.0, f"Stop while waiting for the robot: {got}")
    b.js("window.rbLastRun = undefined; true")
    got = serial_run(env, "rCommPort 5\nrForward 5\n", cancel=True)
    expect(got["status"] == "error" and "program.bas:1:" in (got["error"] or "") and
           "rCommPort 5: no serial port was chosen" in got["error"], f"no port chosen gave {got}")
    env.expect_quiet()


def case_offline(env):
    """Once loaded, the page works offline: with its server gone, the page loads again from the
    browser's cache (its service worker) and runs programs, on the page and in rb.run's worker.
    The service worker makes the page cross-origin isolated (a server that sends no headers,
    as GitHub Pages), so its runs use shared memory."""
    env.server.isolated = False
    b = env.open()
    expect(not b.js("crossOriginIsolated"), "the first visit is isolated without the headers")
    ready = b.js("Promise.race([navigator.serviceWorker.ready.then(() => true), "
                 "new Promise((r) => setTimeout(() => r(false), 10000))])")
    expect(ready, "no service worker took the page within 10 s")
    wait_for(b, "caches.keys().then((k) => k.some((n) => n.startsWith('rb-site-')))", "the site was not cached")
    env.server.shutdown()
    env.server.server_close()
    env.open()
    expect(b.js("navigator.serviceWorker.controller !== null"), "the reloaded page is not the service worker's")
    expect(b.js("crossOriginIsolated && rb.liveMode === 'sab'"), "the service worker's page is not cross-origin isolated")
    r = env.run_page('print "offline "; 6 * 7\n')
    expect(r["status"] == "finished" and r["output"] == "offline \t42\n", f"offline, the run gave {r}")
    got = b.js("rb.run('print 1 + 1\\n').then((r) => r.output)")
    expect(got == "2\n", f"offline, rb.run gave {got!r}")
    env.expect_quiet()


def case_svg(env):
    """After a run the SVG button downloads the screen as `rb render -o OUT.svg` writes it: the same
    bytes for shapes, text and the robot; where the SVG embeds the screen's pixels (a flood fill),
    the same document around a PNG of the same pixels. rb.run gives it too (options.svg)."""
    b = env.open()
    expect(b.js("document.getElementById('svg').disabled"), "the SVG button works before any run")
    # What the page downloads: the Blob given to URL.createObjectURL, read back as text.
    b.js("window.__blobs = []; const make = URL.createObjectURL; "
         "URL.createObjectURL = (blob) => { window.__blobs.push(blob); return make(blob); }; true")
    cases = {
        "shapes": 'rectangle 10,10,200,100\ncircle 300,300,400,400,red\nline 0,599,799,500,3,blue\n'
                  'xyText 50,500,"Hello, SVG","Arial",14,fs_Bold\nrLocate 400,300\nrForward 50\nrTurn 30\n',
        "fill": 'rectangle 10,10,200,100\nfloodfill 100,50,red\nrLocate 400,300\n',
    }
    for name, text in cases.items():
        path = os.path.join(env.args.work, name + ".bas")
        with open(path, "w") as f:
            f.write(text)
        out = os.path.join(env.args.work, name + ".svg")
        r = subprocess.run([env.args.rb, "render", path, "-o", out], capture_output=True, text=True, timeout=60)
        expect(r.returncode == 0, f"rb render {name}: {r.stderr}")
        want = open(out, encoding="utf-8").read()
        r = env.run_page(text)
        expect(r["status"] == "finished", f"{name} ended {r}")
        # The SVG is made after the run's end is shown.
        wait_for(b, "!document.getElementById('svg').disabled", f"{name}: the SVG button stays off after the run")
        b.js("window.__blobs = []; document.getElementById('svg').click(); true")
        got = b.js("window.__blobs.length === 1 && window.__blobs[0].type === 'image/svg+xml' "
                   "? window.__blobs[0].text() : null")
        expect(got is not None, f"{name}: the SVG button gave no SVG file")
        headless = b.js(f"rb.run({json.dumps(text)}, {{seed: 1, svg: true, png: false}}).then((r) => r.svg)")
        for who, svg in (("the page's SVG", got), ("rb.run's svg", headless)):
            if "data:image/png" not in want:
                expect(svg == want, f"{name}: {who} is not rb render's:\n{svg[:600]}\n--- rb render:\n{want[:600]}")
                continue
            strip = lambda t: re.sub(r'data:image/png;base64,[^"]*', "PNG", t)  # noqa: E731
            expect(strip(svg) == strip(want), f"{name}: {who} is not rb render's around its PNG:\n{svg[:600]}")
            png = lambda t: read_png(base64.b64decode(re.search(r'data:image/png;base64,([^"]*)', t).group(1)))  # noqa: E731
            expect(png(svg) == png(want), f"{name}: {who}'s embedded pixels are not rb render's")
    env.expect_quiet()


def word_point(b, word):
    """The page coordinates of the middle of the first `word` shown in the editor."""
    return b.js(f"""(() => {{
      const w = {json.dumps(word)};
      const walk = document.createTreeWalker(document.querySelector('.cm-content'), NodeFilter.SHOW_TEXT);
      for (let n = walk.nextNode(); n; n = walk.nextNode()) {{
        const i = n.textContent.indexOf(w);
        if (i < 0) continue;
        const r = document.createRange();
        r.setStart(n, i); r.setEnd(n, i + w.length);
        const b = r.getBoundingClientRect();
        return [b.left + b.width / 2, b.top + b.height / 2];
      }}
      return null;
    }})()""")


def case_help(env):
    """Help from rb's built-in table (the core's, as the language server reads it): completion as
    you type (a command at a statement's start with its usage and help, functions in an
    expression), hover (usage, help, group and kind), the searchable command reference, and every
    example of the Examples menu runs without an error (the book's figures and the ones beyond)."""
    b = env.open()
    rows = b.js("rb.builtins()")
    fwd = next((r for r in rows if r["name"] == "rForward"), None)
    expect(len(rows) > 100 and fwd and fwd["usage"] == "rForward distance" and fwd["tier"] == "confirmed",
           f"rb.builtins(): {len(rows)} rows, rForward {fwd}")
    # Completion: typing "rFor" at a statement's start offers rForward with its usage.
    b.js("rbPage.setSource(''); document.querySelector('.cm-content').focus(); true")
    for c in "rFor":
        tap(b, c)
    wait_for(b, "document.querySelector('.cm-tooltip-autocomplete') !== null", "typing rFor shows no completion")
    shown = b.js("document.querySelector('.cm-tooltip-autocomplete').textContent")
    expect("rForward" in shown and "rForward distance" in shown, f"the completion shows {shown!r}")
    info = b.js("(document.querySelector('.cm-completionInfo') || {}).textContent || ''")
    expect(info == fwd["help"], f"the completion's help is {info!r}, not {fwd['help']!r}")
    time.sleep(0.2)  # (an Enter within 75 ms of the list showing is not taken: CodeMirror's guard)
    tap(b, "Enter", 13)
    expect(b.js("rbPage.source") == "rForward", f"Enter did not take the completion: {b.js('rbPage.source')!r}")
    # In an expression: functions, not commands.
    b.js("rbPage.setSource('x = '); document.querySelector('.cm-content').focus(); true")
    b.js("(() => { const s = getSelection(); const c = document.querySelector('.cm-line'); "
         "s.collapse(c.firstChild, c.firstChild.length); return true; })()")
    for c in "rF":
        tap(b, c)
    wait_for(b, "document.querySelector('.cm-tooltip-autocomplete') !== null", "typing x = rF shows no completion")
    labels = b.js("[...document.querySelectorAll('.cm-completionLabel')].map((e) => e.textContent)")
    expect("rFeel" in labels and "rForward" not in labels, f"in an expression the completion offers {labels}")
    tap(b, "Escape", 27)
    # Hover over rForward: its usage, help, group and kind.
    b.js("rbPage.setSource('rLocate 400, 300\\nrForward 50\\n'); true")
    time.sleep(0.2)
    x, y = word_point(b, "rForward")
    b.call("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": x, "y": y}, session=True)
    wait_for(b, "document.querySelector('.cm-tooltip-hover .rb-hover') !== null", "no hover over rForward")
    text = b.js("document.querySelector('.cm-tooltip-hover').textContent")
    expect("rForward distance" in text and fwd["help"] in text and "robot command" in text,
           f"the hover over rForward says {text!r}")
    # The command reference: a search narrows it; each row has the usage, the help and the evidence.
    b.js("document.getElementById('help').click(); true")
    wait_for(b, "document.querySelectorAll('#referenceList li').length === " + str(len(rows)), "the reference lists not every built-in")
    b.js("document.getElementById('referenceSearch').focus(); true")
    for c in "bumper":
        tap(b, c)
    wait_for(b, "document.querySelectorAll('#referenceList li').length < 10", "the search does not narrow the reference")
    found = b.js("[...document.querySelectorAll('#referenceList li')].map((e) => e.textContent)")
    bumper = [t for t in found if t.startswith("rBumper()")]
    expect(bumper and "1 rear, 2 right, 4 front, 8 left" in bumper[0] and "robot function" in bumper[0]
           and "a RobotBASIC source shows it" in bumper[0], f"the reference's rows for 'bumper': {found}")
    count = b.js("document.getElementById('referenceCount').textContent")
    expect(count == f"{len(found)} of {len(rows)} built-ins", f"the reference's count says {count!r}")
    tap(b, "Escape", 27)
    # Every example runs without an error, at the fastest speed; those that wait for keys or
    # buttons are stopped after a while. (Figure 1.9 as printed is an error on purpose, and both
    # forms of Figure 1.13 include RB-9.bas, which a page has not: rb run's examples.)
    b.js("document.getElementById('speed').value = '10'; document.getElementById('speed').dispatchEvent(new Event('input')); true")
    names = b.js("RB_EXAMPLES.map((e) => e.name)")
    for want in ("keys", "buttons", "sensors", "bumper_roamer", "line_follower", "maze"):
        expect(want in names, f"the Examples menu has no {want}: {names}")
    for i, name in enumerate(names):
        if name in ("fig_1_9", "fig_1_13", "fig_1_13_sim"):
            continue
        b.js(f"(() => {{ const s = document.getElementById('examples'); s.value = '{i}'; "
             "s.dispatchEvent(new Event('change')); return true; })()")
        r = b.js("""(async () => {
          const done = rbPage.runProgram();
          await Promise.race([done, new Promise((r) => setTimeout(r, 2000))]);
          rbPage.stopProgram();
          await done;
          return [rbLastRun.status, rbLastRun.error];
        })()""", timeout=60)
        expect(r[0] in ("finished", "stopped") and not r[1], f"the example {name} ended {r}")
    env.expect_quiet()


CASES = {"never_frozen": case_never_frozen, "debugger": case_debugger, "screen": case_screen, "loads": case_loads, "square": case_square, "input_keys": case_input_keys, "share": case_share, "programs": case_programs,
         "stop": case_stop, "step": case_step, "error_line": case_error_line, "svg": case_svg, "controls": case_controls, "serial": case_serial, "offline": case_offline,
         "help": case_help}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--rb", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--site", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("case", choices=sorted(CASES))
    args = p.parse_args()
    if not os.path.exists(os.path.join(args.site, "index.html")):
        print(f"skipped: the site is not built ({args.site}; scripts/web.sh builds it)")
        return 77
    chromium = find_chromium()
    if not chromium:
        print("skipped: Chromium is not installed (scripts/setup.sh --test installs it)")
        return 77
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    env = Env(args, chromium, isolated=os.environ.get("RB_PAGE_ISOLATED", "1") != "0")
    try:
        CASES[args.case](env)
    except Failure as e:
        print(f"{args.case}: FAILED: {e}")
        return 1
    finally:
        env.close()
    print(f"{args.case}: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
