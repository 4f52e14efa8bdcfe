#!/usr/bin/env bash
# Replays (rb render --animate, issue 25): the processor time, peak memory and size of the GIF,
# the animated SVG and the HTML player of
#   - the seed's square (examples/fig_1_7.bas; target: the GIF under 200 KB),
#   - roam100k.bas: a roam of 100,000 statements (targets: the GIF in under 3 s of processor
#     time and under 5 MB, the HTML page under 2 MB),
#   - roam10m.bas: a roam of 10,000,000 statements, a pixel per move (memory stays bounded),
#   - rb render -o x.png of each, for scale.
# Checks the statement counts with rb trace first. Usage: bench/replay/run.sh [path/to/rb] [-n RUNS]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=3
source "$here/../args.sh" "$@"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 - "$rb" "$here" "$dir" "$runs" <<'PY'
import os, subprocess, sys
rb, here, d, runs = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
sys.path.insert(0, here + "/..")
from measure import alternate, machine, ms, mib
programs = {
    "square": (here + "/../../examples/fig_1_7.bas", 17),
    "roam 100k": (here + "/roam100k.bas", 100000),
    "roam 10M": (here + "/roam10m.bas", 10000000),
}
for name, (path, steps) in programs.items():
    last = subprocess.run([rb, "trace", path], capture_output=True, text=True).stdout.strip().splitlines()[-1]
    if f"finished after {steps} steps" not in last:
        sys.exit(f"{name}: rb trace ends {last!r}, expected {steps} statements")
jobs = {}
for name, (path, _) in programs.items():
    tag = name.replace(" ", "_")
    jobs[f"{name}: PNG"] = ([rb, "render", path, "-o", f"{d}/{tag}.png"], "")
    for ext in ["gif", "svg", "html"]:
        jobs[f"{name}: {ext.upper()}"] = ([rb, "render", path, "--animate", f"{d}/{tag}.{ext}"], "")
print(f"machine: {machine()}")
got = alternate(jobs, runs)
print(f"{'what':20} {'wall':>9} {'cpu':>9} {'peak RSS':>10} {'size':>10}")
for name, g in got.items():
    program, kind = name.split(": ")
    out = f"{d}/{program.replace(' ', '_')}.{kind.lower()}"
    size = os.path.getsize(out) / 1024
    print(f"{name:20} {ms(g['wall']):>9} {ms(g['cpu']):>9} {mib(g['rss']):>10} {size:>8.1f} K")
PY
