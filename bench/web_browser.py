#!/usr/bin/env python3
"""The interpreter benchmarks (bench/programs/*.bas) in rb's WebAssembly core in headless
Chromium beside native rb, side by side in one run: bench/web.sh's table, with the page's
`rb.run` (which runs in a Web Worker, on the rbcore_fast build) instead of node's. The wasm time
is measured in the page (performance.now() around `await rb.run(...)`: compile, run, and the
messages to and from the worker); native rb's is the wall time of `rb run --seed 1 FILE`. The
"live" column is the page's own Run (`rb.start`: the Asyncify build on the page's thread, with
the hook for Step, yielding to the browser every few milliseconds).
Median of N runs each (default 5); the outputs must be equal.

Usage: bench/web_browser.py [-n N] [--site DIR] [path/to/rb]   (scripts/web.sh builds the site)
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

from web_page import HERE, RB, SITE, open_page

RUN_JS = """
(async () => {
  const t = performance.now();
  const r = await rb.run(%s, {seed: 1, png: false});
  return {seconds: (performance.now() - t) / 1000, output: r.output, error: r.error};
})()
"""
# The page's own run (Run on the page): rb.start, live, on the page's thread with the Asyncify
# build, yielding to the browser every few milliseconds.
LIVE_JS = """
(async () => {
  const t = performance.now();
  const r = await rb.start(%s, {seed: 1, png: false}).done;
  return {seconds: (performance.now() - t) / 1000, output: r.output, error: r.error};
})()
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=5, help="runs of each program on each side")
    ap.add_argument("--site", default=os.environ.get("RB_WEB_SITE", SITE))
    ap.add_argument("rb", nargs="?", default=RB)
    a = ap.parse_args()
    with open_page(a.site, a.rb) as b:
        print(f"Chromium: {b.js('navigator.userAgent')}")
        print("program         native s   wasm s   wasm/native   live s   live/native")
        folder = os.path.join(HERE, "programs")
        for name in sorted(f for f in os.listdir(folder) if f.endswith(".bas")):
            path = os.path.join(folder, name)
            source = open(path, encoding="utf-8").read()
            native, wasm, live = [], [], []
            native_out = wasm_out = ""
            for _ in range(a.n):
                t = time.monotonic()
                native_out = subprocess.run([a.rb, "run", "--seed", "1", path], capture_output=True, text=True,
                                            check=True).stdout
                native.append(time.monotonic() - t)
                r = b.js(RUN_JS % json.dumps(source), timeout=600)
                if r["error"]:
                    raise SystemExit(f"{name}: {r['error']}")
                wasm.append(r["seconds"])
                wasm_out = r["output"]
                r = b.js(LIVE_JS % json.dumps(source), timeout=600)
                if r["error"] or r["output"] != wasm_out:
                    raise SystemExit(f"{name}: the live run gave {r['error'] or r['output'][:200]}")
                live.append(r["seconds"])
            if native_out != wasm_out:
                raise SystemExit(f"{name}: the page's output differs from rb run's")
            n, w, v = statistics.median(native), statistics.median(wasm), statistics.median(live)
            print(f"{name:15} {n:8.3f} {w:8.3f}   {w / n:6.2f}     {v:8.3f}   {v / n:6.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
