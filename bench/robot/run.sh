#!/usr/bin/env bash
# The simulator's benchmarks side by side: 1,000,000 sensed roaming steps, and 100,000 pen-down
# segments against Python's turtle with the screen updates off (under Xvfb when there is no
# display; skipped when tkinter or xvfb-run is missing). Medians of N runs (default 7).
# Usage: bench/robot/run.sh [path/to/rb] [-n N]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
"$here/../../scripts/setup.sh" --bench >/dev/null   # the peer: Python turtle under Xvfb
rb="$here/../../build/cmd/rb"
runs=7
while [ $# -gt 0 ]; do
  case "$1" in
    -n) runs="$2"; shift 2 ;;
    *) rb="$1"; shift ;;
  esac
done
python3 - "$rb" "$here" "$runs" <<'PY'
import os, shutil, statistics, subprocess, sys, time
rb, here, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
def median(cmd):
    ts = []
    for _ in range(runs):
        t = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        ts.append(time.perf_counter() - t)
    return statistics.median(ts)
roam = median([rb, "run", os.path.join(here, "roam.bas")])
print(f"roam    rb {roam*1000:6.0f} ms   {1e6/roam/1e6:.2f} million sensed steps per second")
pen = median([rb, "run", os.path.join(here, "pen.bas")])
line = f"pen     rb {pen*1000:6.0f} ms"
turtle = [sys.executable, os.path.join(here, "pen_turtle.py")]
if not os.environ.get("DISPLAY"):
    turtle = ["xvfb-run", "-a"] + turtle if shutil.which("xvfb-run") else None
try:
    if turtle is None:
        raise RuntimeError("no display and no xvfb-run")
    subprocess.run([sys.executable, "-c", "import tkinter"], check=True, capture_output=True)
    t = median(turtle)
    line += f"   Python turtle {t*1000:6.0f} ms   rb is {t/pen:.0f}x faster"
except Exception as e:
    line += f"   Python turtle n/a ({e})"
print(line)
PY
