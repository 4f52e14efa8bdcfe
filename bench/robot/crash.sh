#!/usr/bin/env bash
# A run that ends in a crash against the same program's clean run (issue 28): the seed's square
# with the pen down (examples/fig_1_7.bas, whose rInvisible GREEN keeps the trail out of the
# robot's sight) and the same square without rInvisible, whose black trail is an obstacle: the
# robot draws it step by step and crashes into it at the start of the fourth side. Checks each
# run (the clean one exits 0; the crash exits 70 with the same message at crash.bas:5:3), prints
# the machine, the median processor time (user + system, from wait4) and wall time of each, and
# the ratio crash / clean (target: at most 1.5).
# Usage: bench/robot/crash.sh [path/to/rb] [-n RUNS]   (default 7 runs each, taking turns)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=7
source "$here/../args.sh" "$@"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cp "$here/../../examples/fig_1_7.bas" "$dir/clean.bas"
sed '/^rInvisible/d' "$here/../../examples/fig_1_7.bas" > "$dir/crash.bas"
grep -q rInvisible "$dir/clean.bas" && ! grep -q rInvisible "$dir/crash.bas"
python3 - "$rb" "$dir" "$runs" "$here/.." <<'PY'
import os, statistics, subprocess, sys, time
rb, d, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
sys.path.insert(0, sys.argv[4])
from measure import machine, ms

crash_message = ("crash.bas:5:3: error: robot crashed into an obstacle: its own pen trail (colour Black); "
                 "add 'rInvisible Black' before 'rPen down' so the robot does not see its trail")
jobs = {"clean": ("clean.bas", 0, None), "crash": ("crash.bas", 70, crash_message)}

def once(program, code, message):
    t = time.perf_counter()
    p = subprocess.Popen([rb, "run", program], cwd=d, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read().decode()
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t
    got = os.waitstatus_to_exitcode(status)
    if got != code or (message and message not in err) or (not message and err):
        sys.exit(f"rb run {program}: exit {got} (expected {code}): {err[:300]}")
    return usage.ru_utime + usage.ru_stime, wall

print(f"machine: {machine()}")
print(f"command: {os.path.realpath(rb)} run clean.bas | crash.bas (median of {runs}, taking turns)")
got = {name: [] for name in jobs}
for _ in range(runs):
    for name, job in jobs.items():
        got[name].append(once(*job))
cpu = {name: statistics.median(c for c, _ in got[name]) for name in jobs}
wall = {name: statistics.median(w for _, w in got[name]) for name in jobs}
for name in jobs:
    print(f"{name:6} cpu {ms(cpu[name]):>9}   wall {ms(wall[name]):>9}")
ratio = cpu["crash"] / cpu["clean"]
print(f"crash / clean processor time: {ratio:.2f}x (target: at most 1.5x)")
PY
