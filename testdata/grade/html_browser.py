#!/usr/bin/env python3
"""The class report page of `rb test --html DIR` in a real browser: headless Chromium driven over
the DevTools protocol on a pipe (the Browser of testdata/render/replay_browser.py).

Usage: html_browser.py --rb PATH/TO/rb --source SOURCE_DIR --work WORK_DIR CASE

The class is testdata/grade/square's (a correct program, one off by one side, one crashing, one
looping forever, one not compiling, one with the wrong output) and a hostile student's program:
its file name, its student's name (in the roster), its source and its output all carry markup
that would run a script or load an image if the page let it through. Each CASE is one CTest test;
WORK_DIR is emptied first. Exits 77 (skipped) when Chromium is not installed.

  loads        the report's folder zipped and unzipped elsewhere: index.html loads from file://
               with no console error, a card per program with its final screen shown, and the
               hostile markup shown as text, never run
  opens        a card's link opens its program's page: source with the failing line marked,
               checks, pictures loaded, the replay's player in its frame; the page goes back
  sort_filter  the filters (name, points, result, failed check) hide the right cards and the
               sorts order them; the numbers shown follow
  inject       no page (the class page, every program page, the hostile program's replay)
               runs the student's script or loads its image
"""

import argparse
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from replay_browser import Browser, Failure, expect, find_chromium  # noqa: E402

SQUARE = os.path.join(HERE, "square")

# Markup a student could hand in: each would set window.__pwned if it ran.
SCRIPT = "<script>window.__pwned='script'</script>"
IMAGE = "<img src=x onerror=\"window.__pwned='img'\">"
HOSTILE_NAME = "Eve " + SCRIPT + "\" onmouseover=\"window.__pwned='attr'"
HOSTILE_FILE = "eve<script>x<img src=x onerror=alert(1)>.bas"
HOSTILE_SOURCE = """// """ + SCRIPT + """
rLocate 400,300
rPen DOWN
rForward 120
print \"""" + SCRIPT.replace('"', "'") + IMAGE.replace('"', "'") + """\"
x = 1/0
"""


def grade(args):
    work = args.work
    cls = os.path.join(work, "class")
    shutil.copytree(os.path.join(SQUARE, "class"), cls)
    shutil.copy(os.path.join(SQUARE, "solution.bas"), work)
    shutil.copy(os.path.join(SQUARE, "assignment.toml"), work)
    with open(os.path.join(cls, HOSTILE_FILE), "w") as f:
        f.write(HOSTILE_SOURCE)
    with open(os.path.join(work, "roster.csv"), "w") as f:
        f.write("student,file\n")
        f.write('"' + HOSTILE_NAME.replace('"', '""') + '",class/' + HOSTILE_FILE + "\n")
        f.write("Ana,class/correct.bas\n")
        f.write("Bo,class/off_by_one.bas\n")
        f.write("Nobody,class/absent.bas\n")
    out = os.path.join(work, "report")
    p = subprocess.run([args.rb, "test", "-q", "-j", "2", "-a", "assignment.toml", "--roster", "roster.csv",
                        "--html", out, "class"], cwd=work, capture_output=True, text=True, timeout=300)
    expect(p.returncode == 1, f"rb test exit {p.returncode}: {p.stderr}")
    expect(os.path.exists(os.path.join(out, "index.html")), "no index.html")
    return out


class Page:
    def __init__(self, args):
        chromium = find_chromium()
        if not chromium:
            print("SKIP: Chromium is not installed (scripts/setup.sh --test installs it)")
            sys.exit(77)
        self.work = args.work
        self.report = grade(args)
        self.browser = Browser(chromium, args.work)

    def open(self, path):
        self.browser.open(path)
        # Lazy images in view and the frame: give them their moment.
        self.browser.js("new Promise(r => setTimeout(r, 300))")

    def quiet(self):
        expect(not self.browser.errors, "console errors:\n" + "\n".join(self.browser.errors))
        expect(self.browser.js("window.__pwned === undefined"),
               f"the student's markup ran: {self.browser.js('String(window.__pwned)')}")

    def cards(self):
        """The visible cards, in order: (name, points, verdict)."""
        return self.browser.js("""Array.from(document.querySelectorAll('#cards .card'))
            .filter(c => !c.hidden && c.offsetParent !== null)
            .map(c => [c.querySelector('h2').textContent, Number(c.dataset.points), c.dataset.verdict])""")

    def set(self, element_id, value):
        self.browser.js(f"""(() => {{ const e = document.getElementById({element_id!r});
            e.value = {value!r}; e.dispatchEvent(new Event('input')); }})()""")


def case_loads(page):
    # The folder zipped, unzipped elsewhere and opened there: every link is relative.
    archive = shutil.make_archive(os.path.join(page.work, "report"), "zip", page.report)
    shutil.rmtree(page.report)
    moved = os.path.join(page.work, "elsewhere", "report")
    shutil.unpack_archive(archive, moved)
    page.report = moved
    page.open(os.path.join(page.report, "index.html"))
    page.quiet()
    cards = page.cards()
    expect(len(cards) == 8, f"8 cards (6 programs, Eve's, Nobody missing), not {len(cards)}: {cards}")
    names = [c[0] for c in cards]
    expect(HOSTILE_NAME in names, f"the hostile name is shown as text: {names}")
    expect("Nobody" in names and "Ana" in names, f"roster names: {names}")
    # The first cards' final screens are loaded (the rest load as they scroll into view).
    loaded = page.browser.js("""Array.from(document.querySelectorAll('#cards .card img')).slice(0, 3)
        .map(i => i.complete && i.naturalWidth)""")
    expect(loaded == [400, 400, 400], f"final screens loaded: {loaded}")
    expect(page.browser.js("document.getElementById('shown').textContent") == "8 of 8 shown", "count shown")
    scripts = page.browser.js("document.scripts.length")
    expect(scripts == 1, f"one script, the page's own: {scripts}")
    expect(page.browser.js("document.querySelectorAll('#cards img[src=\"x\"], #cards [onmouseover]').length") == 0,
           "no element from the student's markup")


def case_opens(page):
    page.open(os.path.join(page.report, "index.html"))
    href = page.browser.js("""(() => { const a = Array.from(document.querySelectorAll('.card'))
        .find(c => c.querySelector('h2').textContent.endsWith('crashing.bas')).querySelector('a.open');
        return a.getAttribute('href'); })()""")
    page.browser.events = [e for e in page.browser.events if e.get("method") != "Page.loadEventFired"]
    page.browser.js("""Array.from(document.querySelectorAll('.card'))
        .find(c => c.querySelector('h2').textContent.endsWith('crashing.bas')).querySelector('a.open').click()""")
    page.browser.wait_event("Page.loadEventFired")
    page.browser.js("new Promise(r => setTimeout(r, 1000))")
    url = page.browser.js("location.href")
    expect(url.endswith(href.split("/")[-1]), f"the card opened {url}, its link is {href}")
    expect(page.browser.js("document.querySelector('h1').textContent").endswith("crashing.bas"), "the program's page")
    bad = page.browser.js("Array.from(document.querySelectorAll('.source .l.bad')).map(l => l.id)")
    expect(len(bad) == 1, f"one failing line marked: {bad}")
    msg = page.browser.js("document.querySelector('.source .l.bad + .msg').textContent")
    expect("crash" in msg, f"the mark says why: {msg}")
    fails = page.browser.js("document.querySelectorAll('table.checks tr.fail').length")
    expect(fails >= 1, f"failed checks in the table: {fails}")
    images = page.browser.js("Array.from(document.querySelectorAll('#pictures img')).map(i => i.complete && i.naturalWidth)")
    expect(images == [800, 400], f"the picture and the final screen load: {images}")
    frame = page.browser.js("document.querySelector('iframe.replay') && document.querySelector('iframe.replay').src")
    expect(frame and frame.endswith(".html"), f"the replay's frame: {frame}")
    # The player in the frame runs: its canvas is there and drawn (the frame is same-origin on file://
    # only for Chromium's test flags, so ask the frame's own document through the DevTools tree).
    tree = page.browser.call("Page.getFrameTree", session=True)["frameTree"]
    children = tree.get("childFrames", [])
    expect(len(children) == 1 and children[0]["frame"]["url"].endswith(".html"),
           f"the replay frame loaded: {children}")
    page.quiet()
    page.browser.events = [e for e in page.browser.events if e.get("method") != "Page.loadEventFired"]
    page.browser.js("document.getElementById('back').click()")
    page.browser.wait_event("Page.loadEventFired")
    expect(page.browser.js("location.pathname.endsWith('/index.html')"), "back to the class")
    page.quiet()


def case_sort_filter(page):
    page.open(os.path.join(page.report, "index.html"))
    total = len(page.cards())
    page.set("f-name", "OFF_BY")
    cards = page.cards()
    expect([c[0] for c in cards] == ["Bo"], f"name filter (case ignored, file names too): {cards}")
    expect(page.browser.js("document.getElementById('shown').textContent") == f"1 of {total} shown", "count")
    page.set("f-name", "")
    page.set("f-verdict", "pass")
    cards = page.cards()
    expect([c[0] for c in cards] == ["Ana"], f"result filter: {cards}")
    page.set("f-verdict", "")
    page.set("f-check", "corners")
    cards = page.cards()
    expect(cards and all(c[2] != "pass" for c in cards) and "Ana" not in [c[0] for c in cards],
           f"failed-check filter: {cards}")
    expect(page.browser.js("""Array.from(document.querySelectorAll('#cards .card:not([hidden])'))
        .every(c => c.dataset.failed.split('\\n').includes('corners'))"""), "each shown card failed corners")
    page.set("f-check", "")
    page.set("f-min", "5")
    cards = page.cards()
    expect(cards and all(c[1] >= 5 for c in cards), f"points from 5: {cards}")
    page.set("f-max", "7")
    cards = page.cards()
    expect(cards and all(5 <= c[1] <= 7 for c in cards), f"points 5 to 7: {cards}")
    page.set("f-min", "")
    page.set("f-max", "")
    page.set("sort", "points-desc")
    points = [c[1] for c in page.cards()]
    expect(points == sorted(points, reverse=True) and len(points) == total, f"points, most first: {points}")
    page.set("sort", "points-asc")
    points = [c[1] for c in page.cards()]
    expect(points == sorted(points), f"points, fewest first: {points}")
    page.set("sort", "name")
    names = [c[0] for c in page.cards()]
    expect(names == sorted(names, key=lambda n: n.lower()), f"by name: {names}")
    page.set("sort", "result")
    verdicts = [c[2] for c in page.cards()]
    expect(verdicts[-1] == "pass" and verdicts[0] == "fail", f"failed first: {verdicts}")
    page.quiet()


def case_inject(page):
    page.open(os.path.join(page.report, "index.html"))
    page.quiet()
    pages = [os.path.join(page.report, "programs", f) for f in sorted(os.listdir(os.path.join(page.report, "programs")))]
    expect(len(pages) == 8, f"a page per program: {pages}")
    hostile = [p for p in pages if p.endswith(".html") and "eve" in os.path.basename(p)]
    expect(len(hostile) == 1, f"the hostile program's page: {pages}")
    for p in pages:
        page.open(p)
        page.quiet()
    page.open(hostile[0])
    text = page.browser.js("document.body.innerText")
    for shown in [HOSTILE_NAME, SCRIPT, "window.__pwned='img'"]:
        expect(shown in text, f"the page shows {shown!r} as text")
    expect(page.browser.js("document.scripts.length") == 0, "no script on a program's page")
    replays = [os.path.join(page.report, "pictures", f) for f in os.listdir(os.path.join(page.report, "pictures"))
               if f.startswith("eve") and f.endswith(".html")]
    expect(len(replays) == 1, f"the hostile program's replay: {replays}")
    page.open(replays[0])
    page.browser.js("new Promise(r => setTimeout(r, 500))")
    page.quiet()


CASES = {"loads": case_loads, "opens": case_opens, "sort_filter": case_sort_filter, "inject": case_inject}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("case", choices=sorted(CASES))
    args = ap.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    args.rb = os.path.abspath(args.rb)
    args.work = os.path.abspath(args.work)
    page = Page(args)
    try:
        CASES[args.case](page)
    except Failure as e:
        print(f"FAIL {args.case}: {e}")
        return 1
    finally:
        page.browser.close()
    print(f"ok {args.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
