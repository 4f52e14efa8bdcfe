#!/usr/bin/env bash
# Roaming with a status line (issue 9's first cliff): roam_status.bas, 100,000 sensed steps
# among obstacles, writes xyText + xyString every N steps, N = 1, 10, 100 and never. Checks the
# answer of every run, prints medians (wall and processor time), the ratio to the run without
# a status line (target: within 2x at N = 1) and the peak resident memory. Then
# planner_status.bas, a stand-in for the published path planner the issue names (not in this
# tree): three maps driven to a goal, the distance to it written at every step, against the same
# program without its status line (target: well under a second).
# Usage: bench/robot/status.sh [path/to/rb] [-n RUNS]   (default 5 runs each)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=5
source "$here/../args.sh" "$@"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
for n in 1 10 100 0; do
  sed "s/^every = 100\$/every = $n/" "$here/roam_status.bas" > "$dir/every$n.bas"
done
# The same every step with opaque backgrounds (xyText's white, setColor's yellow behind
# xyString), the way a status line is usually kept readable: each changed character's cell is
# painted afresh.
sed -e "s/^every = 100\$/every = 1/" -e 's/"", 10$/"", 10, 0, black, white/' \
    -e 's/^turns = 0$/turns = 0\nsetColor black, yellow/' "$here/roam_status.bas" > "$dir/every1bg.bas"
grep -q 'black, white' "$dir/every1bg.bas" && grep -q "setColor black, yellow" "$dir/every1bg.bas"
cp "$here/planner_status.bas" "$dir/planner1.bas"
sed "s/^status = 1\$/status = 0/" "$here/planner_status.bas" > "$dir/planner0.bas"
grep -q "^status = 0$" "$dir/planner0.bas"
python3 - "$rb" "$dir" "$runs" "$here/.." <<'PY'
import sys
rb, d, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
sys.path.insert(0, sys.argv[4])
from measure import alternate, machine, ms, mib
# turns, x, y after 100,000 steps; the status text lies where this robot never drives.
expect = "864 37 242"
names = {"every step": "1", "every step, backgrounds": "1bg", "every 10 steps": "10",
         "every 100 steps": "100", "no status line": "0"}
jobs = {name: ([rb, "run", f"{d}/every{n}.bas"], expect) for name, n in names.items()}
print(f"machine: {machine()}")
got = alternate(jobs, runs)
base = got["no status line"]
print(f"{'100k roaming steps, status line':32} {'wall':>9} {'cpu':>9} {'vs none':>8} {'peak RSS':>10}")
for name in names:
    g = got[name]
    print(f"{name:32} {ms(g['wall']):>9} {ms(g['cpu']):>9} {g['cpu'] / base['cpu']:7.2f}x {mib(g['rss']):>10}")
# Every map reached, in the same steps with or without the status line.
expect = ("map 1: reached 1 in 2133 steps\nmap 2: reached 1 in 1073 steps\n"
          "map 3: reached 1 in 9572 steps")
names = {"status line every step": "1", "no status line": "0"}
got = alternate({name: ([rb, "run", f"{d}/planner{n}.bas"], expect) for name, n in names.items()}, runs)
base = got["no status line"]
print(f"{'planner stand-in, 3 maps':32} {'wall':>9} {'cpu':>9} {'vs none':>8} {'peak RSS':>10}")
for name in names:
    g = got[name]
    print(f"{name:32} {ms(g['wall']):>9} {ms(g['cpu']):>9} {g['cpu'] / base['cpu']:7.2f}x {mib(g['rss']):>10}")
PY
