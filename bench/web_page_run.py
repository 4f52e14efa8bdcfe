#!/usr/bin/env python3
"""The page's own Run (the Run button: rb.start in the page's live worker) against native
`rb run`, as a student meets it: headless Chromium at 1366x768 (as testdata/web/page_test.py
drives it), the site served by Python's http.server, the speed slider at its right end (no
animation). For each program: native `rb run`'s wall time, the page's (from the Run to the
status of its end, measured in the page), the longest delay of a 50 ms timer set one after
another on the page during the run, and Stop's latency (the program started again, stopped
after a fifth of its run, until the page shows it stopped). Also the time from opening the page
to the end of a first run of the seed's square, and the site's size gzipped (gzip -9 a file).
Medians of N runs (default 5). --async: the page not cross-origin isolated (the first visit:
the Asyncify core, with messages).

Usage: bench/web_page_run.py [-n N] [--async] [--site DIR] [path/to/rb]
"""
import argparse
import gzip
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from web_page import HERE, RB, SITE

sys.path.insert(0, os.path.join(HERE, "..", "testdata", "web"))
sys.path.insert(0, os.path.join(HERE, "..", "testdata", "render"))
from page_test import TICKER_JS, Env  # noqa: E402
from replay_browser import find_chromium  # noqa: E402

PROGRAMS = {
    "20 M-step loop": "x = 0\nfor i = 1 to 10000000\n  x = x + 1\nnext\nprint x\n",
    "200x200 SetPixel": "for y = 0 to 199\n  for x = 0 to 199\n    SetPixel x, y, RGB(x, y, 100)\n  next\nnext\n",
    "30,000 prints": "for i = 1 to 30000\n  print i\nnext\n",
}

def run(b, source, stop_after=0):
    """The page's Run of `source` with TICKER_JS (stopped after `stop_after` seconds when > 0)."""
    b.js(f"rbPage.setSource({json.dumps(source)}); true")
    return b.js(TICKER_JS % {"seconds": stop_after}, timeout=600)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=5)
    ap.add_argument("--async", dest="isolated", action="store_false")
    ap.add_argument("--site", default=os.environ.get("RB_WEB_SITE", SITE))
    ap.add_argument("rb", nargs="?", default=RB)
    a = ap.parse_args()
    chromium = find_chromium()
    if not os.path.exists(os.path.join(a.site, "index.html")) or not chromium:
        print("needs the site (scripts/web.sh) and Chromium", file=sys.stderr)
        return 66
    size = sum(os.path.getsize(os.path.join(a.site, f)) for f in os.listdir(a.site))
    packed = sum(len(gzip.compress(open(os.path.join(a.site, f), "rb").read(), 9)) for f in os.listdir(a.site))
    print(f"site: {len(os.listdir(a.site))} files, {size / 1e6:.2f} MB, {packed / 1e6:.2f} MB gzipped")
    work = tempfile.mkdtemp()
    env = Env(argparse.Namespace(site=a.site, work=work, rb=a.rb, source=os.path.join(HERE, "..")), chromium,
              isolated=a.isolated)
    try:
        b = env.browser
        b.call("Emulation.setDeviceMetricsOverride", {"width": 1366, "height": 768, "deviceScaleFactor": 1,
                                                      "mobile": False}, session=True)
        square = open(os.path.join(HERE, "..", "examples", "fig_1_7.bas"), encoding="utf-8").read()
        firsts = []
        for _ in range(a.n):
            b.call("Page.navigate", {"url": "about:blank"}, session=True)
            b.wait_event("Page.loadEventFired")
            t = time.monotonic()
            env.open()
            b.js("document.getElementById('speed').value = '10'; "
                 "document.getElementById('speed').dispatchEvent(new Event('input')); true")
            run(b, square)
            firsts.append(time.monotonic() - t)
        print(f"Chromium: {b.js('navigator.userAgent')}")
        print(f"live mode: {b.js('rb.liveMode')}; open the page to the end of a first run of the square: "
              f"median {statistics.median(firsts):.2f} s (the first of {a.n}: {firsts[0]:.2f} s)")
        print("program            native s   page s   page/native   timer late ms   stop ms")
        for name, source in PROGRAMS.items():
            path = os.path.join(work, "prog.bas")
            with open(path, "w") as f:
                f.write(source)
            native, page, late, stops = [], [], [], []
            for _ in range(a.n):
                t = time.monotonic()
                subprocess.run([a.rb, "run", "--seed", "1", path], stdout=subprocess.DEVNULL, check=True)
                native.append(time.monotonic() - t)
                r = run(b, source)
                if r["status"] != "finished":
                    raise SystemExit(f"{name}: the page's run ended {r['status']}")
                page.append(r["seconds"])
                late.append(r["worst"])
            for _ in range(a.n):
                stop_after = max(0.02, statistics.median(page) / 5)
                r = run(b, source, stop_after)
                stops.append(r["stop"])
                late.append(r["worst"])
            n, p = statistics.median(native), statistics.median(page)
            print(f"{name:18} {n:8.3f} {p:8.3f}   {p / n:8.2f}      {max(late):8.0f}      {statistics.median(stops):5.0f}"
                  f" (max {max(stops):.0f})")
    finally:
        env.close()
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
