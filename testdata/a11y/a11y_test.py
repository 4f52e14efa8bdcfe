#!/usr/bin/env python3
"""Accessibility (WCAG 2.1 AA) of rb's pages in a real browser: the web page (build-web/site), the
class report of `rb test --html` (teacher's and --student views) and the replay player of
`rb render --animate OUT.html`. Headless Chromium at 1366 x 768, driven over the DevTools
protocol on a pipe (the Browser of testdata/render/replay_browser.py), with axe-core from npm
(tools/package.json, installed by scripts/setup.sh --test) injected into each page.

Usage: a11y_test.py --rb RB --source SOURCE_DIR --site SITE_DIR --tools TOOLS_DIR --work WORK_DIR CASE

Each CASE is one CTest test and one browser session:

  page    axe's WCAG 2.1 A and AA rules find nothing on the page idle (its menus open), running,
          paused, stepping, asking for input, with the program's buttons shown, with a message
          box open, with an error shown and at 200% zoom; the keyboard alone reaches every part
          in order with a visible focus ring, leaves the editor and the screen, runs, pauses,
          steps and stops with the page's keys (which the program never gets), presses the
          program's buttons, types into its edit boxes, answers input and message boxes, goes
          to a diagnostic's line; the screen's text alternative follows a run (at most every
          2 s, then its end) and an error is said with its line; at 200% zoom nothing scrolls
          sideways and every control is on the screen, uncovered
  report  the same rules on the class page and a program's page, teacher's and student's;
          the pass and fail marks carry a symbol and a word; the keyboard reaches the filters,
          the cards and a program's page in order with a focus ring; 200% zoom as above
  player  the same rules on the replay player (light and dark); its keys and focus order; its
          text alternative follows the replay and says the run's error with its line

Exits 77 (skipped) when Chromium is not installed, or (page) when the site is not built; fails
when axe-core is not installed (scripts/setup.sh --test installs it).
"""

import argparse
import functools
import http.server
import json
import os
import shutil
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from replay_browser import Browser, Failure, expect, find_chromium  # noqa: E402

TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]
WIDTH, HEIGHT = 1366, 768

# The element that has the focus: a name for it, and whether a focus ring shows (an outline on
# it, or on the editor around it).
FOCUS_JS = """
window.__focus = async () => {
  // After the page's own focus handlers (the editor marks itself focused a moment later).
  await new Promise((r) => setTimeout(() => requestAnimationFrame(() => r()), 20));
  let e = document.activeElement;
  if (!e || e === document.body) return null;
  // An outline of 2 px or more, or the browser's own ring (style auto).
  const ring = (el) => { const s = getComputedStyle(el);
    return s.outlineStyle === 'auto' || s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) >= 2; };
  if (e.tagName === 'IFRAME') return ['iframe', true];  // its page draws its own ring (the player's case)
  const cm = e.closest('.cm-editor');
  let name = e.id;
  if (cm) name = 'editor';
  else if (e.closest('#screenBox > #controls')) name = 'control:' + e.dataset.name;  // the program's, on the page
  else if (e.closest('#diagnostics')) name = 'diagnostic';
  else if (e.tagName === 'SUMMARY') name = 'summary:' + e.parentElement.id;
  else if (e.closest('article.card')) name = 'card';
  else if (!name) name = e.tagName.toLowerCase() + ':' + (e.getAttribute('aria-label') || e.textContent || '').trim().slice(0, 30);
  return [name, ring(e) || (cm ? ring(cm) : false)];
};
true
"""

# Every control that is shown: inside the window sideways, and the topmost element at its middle
# once scrolled into view (nothing covers it). Returns what is wrong.
REACH_JS = """
(() => {
  const bad = [];
  const width = document.documentElement.clientWidth;
  if (document.documentElement.scrollWidth > width + 1)
    bad.push('the page scrolls sideways: ' + document.documentElement.scrollWidth + ' > ' + width);
  const controls = document.querySelectorAll('a[href], button, select, input:not([type=hidden]), summary, textarea, [tabindex="0"]');
  for (const e of controls) {
    if (e.closest('[hidden], details:not([open]) > :not(summary), dialog:not([open])') || e.getClientRects().length === 0) continue;
    if (e.closest('#controls') || e.classList.contains('skip')) continue;
    e.scrollIntoView({block: 'center', inline: 'center'});
    const r = e.getBoundingClientRect();
    const name = e.id || e.tagName.toLowerCase() + ':' + (e.textContent || '').trim().slice(0, 20);
    if (r.left < -1 || r.right > width + 1) { bad.push(name + ' is cut off: ' + r.left + '..' + r.right); continue; }
    const x = Math.min(Math.max(r.left + r.width / 2, 0), width - 1);
    const y = Math.min(Math.max(r.top + Math.min(r.height / 2, 10), 0), innerHeight - 1);
    const top = document.elementFromPoint(x, y);
    if (!top || !(e === top || e.contains(top) || top.contains(e) && top.closest('label')))
      bad.push(name + ' is covered by ' + (top ? top.tagName + '#' + top.id + '.' + top.className : 'nothing'));
  }
  window.scrollTo(0, 0);
  return bad;
})()
"""

MENUS_JS = "['limits', 'keys'].forEach((id) => { const d = document.getElementById(id); if (d) d.open = %s; }); true"

KEYS = {
    "Tab": ("Tab", 9), "Enter": ("Enter", 13), "Escape": ("Escape", 27), " ": ("Space", 32),
    ",": ("Comma", 188), ";": ("Semicolon", 186), ".": ("Period", 190), "ArrowRight": ("ArrowRight", 39),
    "ArrowLeft": ("ArrowLeft", 37), "End": ("End", 35), "Home": ("Home", 36),
}
CTRL, SHIFT = 2, 8


class Session:
    def __init__(self, args):
        chromium = find_chromium()
        if not chromium:
            print("skipped: Chromium is not installed (scripts/setup.sh --test installs it)")
            sys.exit(77)
        axe = os.path.join(args.tools, "node_modules", "axe-core", "axe.min.js")
        if not os.path.exists(axe):
            print(f"FAIL: axe-core is not installed ({axe}; scripts/setup.sh --test installs it)")
            sys.exit(1)
        self.axe_source = open(axe, encoding="utf-8").read()
        self.args = args
        self.browser = Browser(chromium, args.work)
        self.browser.viewport(WIDTH, HEIGHT)
        # The report's pages allow only their own script (a nonce): let axe in.
        self.browser.call("Page.setBypassCSP", {"enabled": True}, session=True)
        self.problems = []

    def close(self):
        self.browser.close()

    def js(self, expression, timeout=60):
        return self.browser.js(expression, timeout=timeout)

    def axe(self, state):
        """axe-core's WCAG 2.1 A and AA rules on the page as it is now; what they find is noted
        under `state`. Text whose contrast axe measured below the ratio asked, but left undecided
        (one or two characters), counts too. Contrast is measured only on what is in the window:
        a page longer than the window is checked again in a window as tall as the page."""
        if not self.js("typeof window.axe === 'object'"):
            self.js(self.axe_source + "\n;true")
        found = {}
        for rule, target, summary in self.axe_once():
            found.setdefault(rule, {})[target] = summary
        height = self.js("document.documentElement.scrollHeight")
        if height > HEIGHT + 8:
            self.browser.viewport(WIDTH, min(height, 8000))
            for rule, target, summary in self.axe_once():
                found.setdefault(rule, {})[target] = summary
            self.browser.viewport(WIDTH, HEIGHT)
        for rule, nodes in found.items():
            self.problems.append(f"{state}: {rule} ({len(nodes)} elements): " +
                                 " | ".join(f"{t}: {v}" for t, v in list(nodes.items())[:3]))

    def axe_once(self):
        """[rule, element, what is wrong] for each element axe finds at fault."""
        return self.js(f"""axe.run(document, {{runOnly: {{type: 'tag', values: {json.dumps(TAGS)}}},
              resultTypes: ['violations', 'incomplete'], iframes: false}}).then((r) => {{
            const out = [];
            for (const v of r.violations)
              for (const n of v.nodes) out.push([v.id, n.target.join(' '), n.failureSummary.replace(/\\s+/g, ' ').slice(0, 240)]);
            for (const v of r.incomplete.filter((v) => v.id === 'color-contrast'))
              for (const n of v.nodes)
                for (const c of n.any)
                  if (c.data && c.data.contrastRatio && c.data.contrastRatio < parseFloat(c.data.expectedContrastRatio))
                    out.push(['color-contrast (short text)', n.target.join(' '), JSON.stringify(c.data)]);
            return out;
        }})""", timeout=120)

    def key(self, key, modifiers=0, text=None):
        code, vk = KEYS.get(key, (None, None))
        if code is None:  # a letter
            code, vk = "Key" + key.upper(), ord(key.upper())
        down = {"type": "keyDown", "key": key, "code": code, "windowsVirtualKeyCode": vk, "modifiers": modifiers}
        if text is None and not modifiers & CTRL:
            text = {"Enter": "\r", " ": " "}.get(key, key if len(key) == 1 else None)
        if text:
            down["text"] = text
        self.browser.call("Input.dispatchKeyEvent", down, session=True)
        self.browser.call("Input.dispatchKeyEvent", {"type": "keyUp", "key": key, "code": code,
                                                     "windowsVirtualKeyCode": vk, "modifiers": modifiers}, session=True)

    def focus(self):
        if not self.js("typeof window.__focus === 'function'"):
            self.js(FOCUS_JS)
        return self.js("__focus()")

    def tab(self, shift=False):
        self.key("Tab", SHIFT if shift else 0)
        return self.focus()

    def tab_order(self, count, what, shift=False):
        """The next `count` elements Tab (or Shift+Tab) reaches; each must show a focus ring."""
        stops = []
        for _ in range(count):
            if stops and stops[-1] == "editor":
                self.key("Escape")  # Tab indents in the editor: Esc, then Tab leaves it
            f = self.tab(shift)
            expect(f is not None, f"{what}: Tab left the page after {stops}")
            if not f[1]:
                self.problems.append(f"{what}: no visible focus ring on {f[0]}")
            stops.append(f[0])
        return stops

    def zoom(self, what):
        """200% zoom of a 1366 x 768 window: nothing scrolls sideways, every control is in the
        window and uncovered."""
        self.browser.viewport(WIDTH // 2, HEIGHT // 2, 2)
        self.js("new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(true))))")
        for p in self.js(REACH_JS):
            self.problems.append(f"{what} at 200% zoom: {p}")

    def unzoom(self):
        self.browser.viewport(WIDTH, HEIGHT)

    def wait_for(self, expression, what, timeout=20):
        deadline = time.monotonic() + timeout
        while True:
            value = self.js(expression)
            if value:
                return value
            expect(time.monotonic() < deadline, what)
            time.sleep(0.05)

    def finish(self):
        expect(not self.browser.errors, "the console shows errors:\n" + "\n".join(self.browser.errors))
        problems, self.problems = self.problems, []
        expect(not problems, f"{len(problems)} problems:\n" + "\n".join(problems))


def in_order(stops, wanted, what):
    """`wanted` appear in `stops` in this order (other stops may come between)."""
    at = 0
    for w in wanted:
        expect(w in stops[at:], f"{what}: Tab does not reach {w} after {stops[:at]} (the order: {stops})")
        at = stops.index(w, at) + 1


# ---------------------------------------------------------------- the web page

ROAM = """rLocate 400, 300
rInvisible BLACK
rPen DOWN
print "start"
for i = 1 to 1000000
  rForward 2
  rTurn 3
  f = rFeel()
  if i % 40 = 0 then print "lap " + i
next
"""


def case_page(s):
    site = s.args.site
    if not os.path.exists(os.path.join(site, "index.html")):
        print(f"skipped: the site is not built ({site}; scripts/web.sh builds it)")
        sys.exit(77)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=site))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        page(s, f"http://127.0.0.1:{server.server_address[1]}/index.html")
    finally:
        server.shutdown()


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def page(s, url):
    b = s.browser
    b.call("Page.navigate", {"url": url}, session=True)
    b.wait_event("Page.loadEventFired")
    s.js("window.rbPage.ready")
    s.js("rbPage.setSource('print \"hello\"\\n'); true")

    # Idle, with its menus open.
    s.js(MENUS_JS % "true")
    s.axe("idle, menus open")
    s.js(MENUS_JS % "false")

    # The order Tab follows, from the top: every control, the editor, the screen, the output.
    s.js("document.activeElement.blur(); window.scrollTo(0, 0); true")
    stops = s.tab_order(18, "the page")
    in_order(stops, ["skip", "programs", "summary:programMenu", "examples", "open", "save", "share", "run", "speed",
                     "png", "summary:limits", "summary:keys", "help", "editor", "screen", "larger", "fullscreen",
                     "outputPane"],
             "the page")
    # The command reference: a dialog, its search box takes the focus; Esc closes it.
    s.js("document.getElementById('help').click(); true")
    s.wait_for("document.querySelectorAll('#referenceList li').length > 0", "the command reference shows nothing")
    expect(s.focus()[0] == "referenceSearch", f"the command reference's search box does not have the focus: {s.focus()}")
    s.axe("the command reference open")
    s.key("Escape")
    expect(not s.js("document.getElementById('reference').open"), "Esc does not close the command reference")
    # The keys menu names the page's keys.
    keys = s.js("document.getElementById('keys').textContent")
    for k in ["Ctrl+Enter", "Ctrl+,", "Ctrl+;", "Ctrl+."]:
        expect(k.replace("+", "") in keys.replace("+", "").replace(" ", ""), f"the keys menu does not list {k}: {keys!r}")
    # The editor: Tab indents; Esc then Tab leaves it for the screen; Shift+Tab comes back.
    s.js("document.querySelector('.cm-content').focus(); true")
    s.key("Home")  # any key but Esc: the Esc of the walk above no longer counts
    s.key("Tab")
    src = s.js("rbPage.source")
    expect(s.focus()[0] == "editor" and src != 'print "hello"\n', f"Tab in the editor does not indent: {src!r}")
    s.key("Escape")
    expect(s.tab()[0] == "screen", f"Esc, Tab does not leave the editor for the screen: {s.focus()}")
    expect(s.tab(shift=True)[0] == "editor", f"Shift+Tab from the screen goes to {s.focus()}")

    # Run with Ctrl+Enter from the editor; the screen's text follows the run, at most every 2 s.
    s.js(f"rbPage.setSource({json.dumps(ROAM)}); true")
    s.js("""window.__said = []; new MutationObserver(() => __said.push([performance.now(),
        document.getElementById('screenText').textContent])).observe(document.getElementById('screenText'),
        {childList: true, characterData: true, subtree: true}); true""")
    s.js("document.querySelector('.cm-content').focus(); true")
    s.key("Enter", CTRL)
    s.wait_for("rbPage.running", "Ctrl+Enter did not run the program")
    s.js("document.getElementById('screen').focus(); true")
    time.sleep(1.0)
    s.axe("running")
    # Tab leaves the screen while a program runs (the screen is no trap).
    expect(s.tab()[0] != "screen", "Tab does not leave the screen during a run")
    s.js("document.getElementById('screen').focus(); true")
    time.sleep(4.5)
    s.key(",", CTRL)
    s.wait_for("document.getElementById('status').textContent.startsWith('paused')", "Ctrl+, did not pause the run")
    s.axe("paused")
    s.key(";", CTRL)
    line = s.wait_for("(/^paused before line (\\d+)$/.exec(document.getElementById('status').textContent) || [])[1]",
                      "Ctrl+; did not step")
    s.key(";", CTRL)
    s.wait_for(f"/^paused before line (?!{line}$)/.test(document.getElementById('status').textContent)",
               "a second Ctrl+; did not step on")
    s.axe("stepping")
    s.key(",", CTRL)
    s.wait_for("document.getElementById('status').textContent === 'running'", "Ctrl+, did not resume the run")
    said = s.js("__said")
    expect(len(said) >= 2, f"the screen's text did not follow the run: {said}")
    gaps = [b[0] - a[0] for a, b in zip(said, said[1:])]
    expect(min(gaps) > 1900, f"the screen's text changed more often than every 2 s: {gaps}")
    text = said[-1][1]
    expect("Robot at x " in text and "pen down" in text and "rFeel" in text and "Printed: lap" in text,
           f"the screen's text during the run: {text!r}")
    s.key(".", CTRL)
    s.wait_for("!rbPage.running", "Ctrl+. did not stop the run")
    st = s.js("rbLastRun.state")
    text = s.js("document.getElementById('screenText').textContent")
    expect(text.startswith("The program was stopped after") and
           f"Robot at x {st['x']}, y {st['y']}, heading {st['heading']} degrees, pen down." in text and
           f"Printed: {st['printed']}" in text and st["printed"].startswith("lap"),
           f"at the end the screen's text is {text!r}, the core's state {st}")

    # The page's keys never reach the program: Ctrl+, while it waits for a key, then x.
    s.js("rbPage.setSource('waitKey k\\nprint \"key \" + k\\n'); window.__done = rbPage.runProgram(); true")
    s.wait_for("rbPage.running", "the waitKey program did not start")
    s.key(",", CTRL)
    s.key(",", CTRL)
    s.key("x")
    s.js("window.__done.then(() => true)")
    out = s.js("document.getElementById('output').textContent")
    expect(out == "key 120\n", f"the program read {out!r}, not only the x")

    # input, answered from the keyboard.
    s.js("rbPage.setSource('input \"name? \", n\\nprint \"hi \" + n\\n'); window.__done = rbPage.runProgram(); true")
    s.wait_for("document.activeElement && document.activeElement.id === 'inputLine'", "input did not take the focus")
    s.axe("asking for input")
    for c in "Ada":
        s.key(c, SHIFT if c.isupper() else 0)
    s.key("Enter")
    s.js("window.__done.then(() => true)")
    out = s.js("document.getElementById('output').textContent")
    expect(out == "name? Ada\nhi Ada\n", f"input from the keyboard: {out!r}")

    # The program's buttons and edit boxes from the keyboard: Tab from the screen reaches them.
    prog = ('AddButton "Go", 100, 100\nAddEdit "Name", 100, 200, 120, "Bob"\n'
            'repeat\n  GetButton b\nuntil b = "Go"\nprint "name=" + GetEdit("Name")\n')
    s.js(f"rbPage.setSource({json.dumps(prog)}); window.__done = rbPage.runProgram(); true")
    s.wait_for("document.querySelectorAll('#controls > button').length === 2", "the program's controls did not show")
    s.axe("the program's buttons shown")
    s.js("document.getElementById('screen').focus(); true")
    expect(s.tab()[0] == "control:Go", f"Tab from the screen goes to {s.focus()}, not the program's button")
    expect(s.tab()[0] == "control:Name", f"the next Tab goes to {s.focus()}, not the program's edit box")
    s.key("Enter")
    s.wait_for("document.querySelector('#controls .rb-edit.focus') !== null", "Enter did not give the edit box the keys")
    expect(s.focus()[0] == "screen", "the screen does not have the focus to type into the edit box")
    s.key("x")
    s.key("Enter")
    s.wait_for("document.querySelector('#controls .rb-edit').textContent === 'Bobx'", "typing into the edit box")
    s.tab()
    s.key(" ")
    s.js("window.__done.then(() => true)")
    out = s.js("document.getElementById('output').textContent")
    expect(out == "name=Bobx\n", f"the program's controls from the keyboard: {out!r}")

    # A message box, answered with Enter.
    s.js("rbPage.setSource('MsgBox \"hello\", \"Title\"\\nprint \"after\"\\n'); window.__done = rbPage.runProgram(); true")
    s.wait_for("document.getElementById('msgbox').open", "no message box")
    s.axe("a message box open")
    s.key("Enter")
    s.js("window.__done.then(() => true)")
    expect(s.js("document.getElementById('output').textContent") == "after\n", "Enter did not answer the message box")

    # Errors: said at once with their line; a compile error's diagnostic takes Enter to its line.
    s.js("rbPage.setSource('print \"a\"\\nx = 0\\nprint 1 / x\\n'); rbPage.runProgram()")
    alert = s.js("document.getElementById('alert').textContent")
    expect(alert.startswith("Error at line 3: ") and "division by zero" in alert, f"the error said: {alert!r}")
    expect(s.js("document.getElementById('alert').getAttribute('role')") == "alert", "the error is not an alert")
    s.axe("a runtime error shown")
    s.js("rbPage.setSource('print \"a\"\\n\\ngosub Nowhere\\n'); rbPage.runProgram()")
    alert = s.js("document.getElementById('alert').textContent")
    expect(alert.startswith("Error at line 3: "), f"the compile error said: {alert!r}")
    s.axe("a compile error shown")
    s.js("document.querySelector('#diagnostics button').focus(); true")
    s.key("Enter")
    expect(s.focus()[0] == "editor" and s.js("(() => { const v = document.querySelector('.cm-content'); "
                                             "return getSelection().toString(); })()") == "gosub Nowhere",
           "Enter on the diagnostic does not select its line in the editor")

    # 200% zoom, idle and with the menus open.
    s.zoom("the page")
    s.js(MENUS_JS % "true")
    s.zoom("the page, menus open")
    s.axe("200% zoom")
    s.unzoom()
    s.finish()


# ---------------------------------------------------------------- the class report


def grade(s, student):
    work = os.path.join(s.args.work, "student" if student else "teacher")
    square = os.path.join(s.args.source, "testdata", "grade", "square")
    shutil.copytree(os.path.join(square, "class"), os.path.join(work, "class"))
    for f in ("solution.bas", "assignment.toml"):
        shutil.copy(os.path.join(square, f), work)
    # A roster with a student who handed nothing in: a card with no picture.
    with open(os.path.join(work, "roster.csv"), "w") as f:
        f.write("student,file\nAna,class/correct.bas\nNobody,class/absent.bas\n")
    r = subprocess.run([s.args.rb, "test", "-q", "-j", "2", "-a", "assignment.toml", "--roster", "roster.csv",
                        "--html", "report", "class"]
                       + (["--student"] if student else []), cwd=work, capture_output=True, text=True, timeout=300)
    expect(r.returncode == 1, f"rb test exit {r.returncode}: {r.stderr}")
    return os.path.join(work, "report")


def marks(s, what):
    """Each pass or fail mark has a symbol and a word; the cards' results too."""
    bad = s.js("""[...document.querySelectorAll('ul.checks li, table.checks tr.pass, table.checks tr.fail, ' +
        'table.checks tr.unchecked, .verdict')].map((e) => e.textContent.trim()).filter((t) =>
        !(/[\\u2713\\u2717\\u2013]/.test(t) && /\\b(passed|failed|not checked|not graded|skipped|no submission)\\b/.test(t)))""")
    if bad:
        s.problems.append(f"{what}: marks without a symbol and a word: {bad[:5]}")


def case_report(s):
    for student in (False, True):
        view = "student's" if student else "teacher's"
        report = grade(s, student)
        s.browser.open(os.path.join(report, "index.html"))
        s.axe(f"the class page ({view})")
        marks(s, f"the class page ({view})")
        s.js("document.activeElement.blur(); window.scrollTo(0, 0); true")
        stops = s.tab_order(8, f"the class page ({view})")
        in_order(stops, ["f-name", "f-min", "f-max", "f-verdict", "f-check", "sort", "card"], f"the class page ({view})")
        # The filters from the keyboard: the count shown is said (a status).
        if s.js("document.getElementById('shown').getAttribute('role')") != "status":
            s.problems.append(f"the class page ({view}): the count of cards shown is not a status (not said)")
        if not student:
            s.zoom("the class page")
            s.unzoom()
        # A card opens its program's page with Enter.
        s.js("""[...document.querySelectorAll('.card')].find((c) => c.querySelector('h2').textContent.endsWith(
            'crashing.bas')).querySelector('a').focus(); true""")
        s.browser.events = [e for e in s.browser.events if e.get("method") != "Page.loadEventFired"]
        s.key("Enter")
        s.browser.wait_event("Page.loadEventFired")
        expect(s.js("location.pathname").endswith("/programs/crashing.html"), "Enter on the card did not open its page")
        s.js("new Promise((r) => setTimeout(r, 300))")
        s.axe(f"a program's page ({view})")
        marks(s, f"a program's page ({view})")
        s.js("document.activeElement.blur(); window.scrollTo(0, 0); true")
        stops = s.tab_order(5, f"a program's page ({view})")
        in_order(stops, ["back"], f"a program's page ({view})")
        if not student:
            s.zoom("a program's page")
            s.unzoom()
        # A page with the source long enough to scroll and a feedback to read.
        s.browser.open(os.path.join(report, "programs", "looping.html"))
        s.axe(f"another program's page ({view})")
    s.finish()


# ---------------------------------------------------------------- the replay player

PLAYER_PROG = """rLocate 400, 500
rPen DOWN
print "start"
for i = 1 to 60
  f = rFeel()
  rForward 10
  if i % 10 = 0 then print "i = " + i
next
"""


def case_player(s):
    prog = os.path.join(s.args.work, "crash.bas")
    with open(prog, "w") as f:
        f.write(PLAYER_PROG)
    html = os.path.join(s.args.work, "crash.html")
    r = subprocess.run([s.args.rb, "render", prog, "--animate", html], capture_output=True, text=True, timeout=120)
    expect(r.returncode == 70 and os.path.exists(html), f"rb render --animate: exit {r.returncode}: {r.stderr}")
    b = s.browser
    b.open(html)
    s.js("rbPlayer.ready.then(() => true)")
    s.axe("the player")
    b.call("Emulation.setEmulatedMedia", {"features": [{"name": "prefers-color-scheme", "value": "dark"}]}, session=True)
    s.axe("the player, dark")
    b.call("Emulation.setEmulatedMedia", {"features": []}, session=True)
    keys = s.js("document.body.textContent")
    for k in ["Space", "Left", "Right", "Home", "End"]:
        expect(k in keys, f"the player does not say what {k} does")
    # Tab reaches the controls, then the panes that scroll.
    s.js("document.activeElement.blur(); window.scrollTo(0, 0); true")
    stops = s.tab_order(8, "the player")
    in_order(stops, ["back", "play", "forward", "timeline", "speed", "autoplay", "source", "output"], "the player")
    # The keys: Right steps; the text alternative says the step, the line and the robot.
    s.js("document.activeElement.blur(); true")
    for _ in range(4):
        s.key("ArrowRight")
    expect(s.js("rbPlayer.step") == 4, f"Right did not step: {s.js('rbPlayer.step')}")
    s.wait_for("document.getElementById('describe').textContent.startsWith('Step 5 of ')",
               "the text alternative does not follow the steps")
    text = s.js("document.getElementById('describe').textContent")
    expect("robot at x 400, y 500, heading 0 degrees, pen down" in text.lower() and "line " in text,
           f"the text alternative at step 5: {text!r}")
    # Playing: said at most every 2 s, and at the end, with the error's line said at once.
    s.js("""window.__said = []; new MutationObserver(() => __said.push([performance.now(),
        document.getElementById('describe').textContent])).observe(document.getElementById('describe'),
        {childList: true, characterData: true, subtree: true}); true""")
    s.key("Home")
    s.key(" ")
    s.wait_for("!rbPlayer.playing", "the player did not play to its end", timeout=30)
    said = s.js("__said")
    gaps = [q[0] - p[0] for p, q in zip(said, said[1:-1])]  # the end is said at once
    expect(len(said) >= 3 and min(gaps) > 1900, f"while playing the text changed {len(said)} times, gaps {gaps}")
    end = said[-1][1]
    expect("the robot crashed" in end.lower() or "runtime error" in end.lower(), f"the end is not said: {end!r}")
    alert = s.js("document.getElementById('alert').textContent")
    expect("line 6" in alert, f"the error is not said with its line: {alert!r}")
    s.zoom("the player")
    s.unzoom()
    s.finish()


CASES = {"page": case_page, "report": case_report, "player": case_player}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--site", required=True)
    ap.add_argument("--tools", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("case", choices=sorted(CASES))
    args = ap.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    args.rb = os.path.abspath(args.rb)
    args.work = os.path.abspath(args.work)
    s = Session(args)
    try:
        CASES[args.case](s)
    except Failure as e:
        print(f"FAIL {args.case}: {e}")
        if s.problems:
            print(f"and before that, {len(s.problems)} problems:\n" + "\n".join(s.problems))
        return 1
    finally:
        s.close()
    print(f"ok {args.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
