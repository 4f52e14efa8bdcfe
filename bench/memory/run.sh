#!/usr/bin/env bash
# Memory that must not grow with what a program draws (issue 9's second cliff): the peak
# resident memory and time of
#   - pen_long.bas: 10,000,000 pen-down moves under rb run (target: peak under 32 MiB),
#   - set_pixel.bas: 1,000,000 and 3,000,000 setPixel calls under rb run (no display list),
#   - the empty program, for scale,
#   - rb render -o x.svg of pen_long.bas: the SVG's size and the peak memory.
# Checks every answer. Usage: bench/memory/run.sh [path/to/rb] [-n RUNS]   (default 3)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=3
source "$here/../args.sh" "$@"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
sed 's/^n = 1000000$/n = 3000000/' "$here/set_pixel.bas" > "$dir/set_pixel3.bas"
: > "$dir/empty.bas"
python3 - "$rb" "$here" "$dir" "$runs" <<'PY'
import os, sys
rb, here, d, runs = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
sys.path.insert(0, here + "/..")
from measure import alternate, machine, ms, mib
pen = "353,280"
jobs = {
    "empty program": ([rb, "run", d + "/empty.bas"], ""),
    "pen: 10M moves": ([rb, "run", here + "/pen_long.bas"], pen),
    "setPixel 1M": ([rb, "run", here + "/set_pixel.bas"], "103800"),
    "setPixel 3M": ([rb, "run", d + "/set_pixel3.bas"], "103800"),
    "pen: 10M moves, SVG": ([rb, "render", "-o", d + "/pen.svg", here + "/pen_long.bas"], ""),
}
print(f"machine: {machine()}")
got = alternate(jobs, runs)
print(f"{'what':24} {'wall':>9} {'cpu':>9} {'peak RSS':>10}")
for name, g in got.items():
    print(f"{name:24} {ms(g['wall']):>9} {ms(g['cpu']):>9} {mib(g['rss']):>10}")
print(f"SVG of the 10M-move pen run: {os.path.getsize(d + '/pen.svg') / 1024:.0f} KiB")
PY
