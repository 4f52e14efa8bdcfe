#!/usr/bin/env bash
# How long the live view takes to show an earlier step of a run of a million statements: it runs
# bench/timeline/timeline.bas in `rb run --tui` inside tmux to its end, then presses Left (one
# statement back), Right (one forward), Home (a tenth of the run back) and, as the baseline of
# what the measurement itself costs, F4/F5 (the speed shown changes, nothing else), each N times,
# timing from the key sent (tmux send-keys) to the screen showing its effect (tmux capture-pane,
# asked again and again). The target: one statement back in under 100 ms.
# Usage: bench/timeline/run.sh [path/to/rb] [-n RUNS]   (default 30 of each key)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=30
source "$here/../args.sh" "$@"
command -v tmux >/dev/null || { echo "bench/timeline: tmux is needed" >&2; exit 1; }
python3 - "$rb" "$here" "$runs" <<'PY'
import os, re, shutil, statistics, subprocess, sys, tempfile, time
rb, here, runs = os.path.abspath(sys.argv[1]), sys.argv[2], int(sys.argv[3])
sys.path.insert(0, here + "/..")
from measure import machine

d = tempfile.mkdtemp(prefix="rb-timeline-")
sock = os.path.join(d, "tmux")
def tmux(*a):
    return subprocess.run(["tmux", "-S", sock, "-f", "/dev/null", *a], capture_output=True, text=True)
def screen():
    return tmux("capture-pane", "-p", "-t", "main").stdout
def title():
    return screen().split("\n")[0]
def wait(pred, timeout=600):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        t = screen()
        if pred(t):
            return t
        time.sleep(0.001)
    raise SystemExit("bench/timeline: timed out; the screen was:\n" + screen())

try:
    tmux("new-session", "-d", "-s", "main", "-x", "120", "-y", "40",
         f"cd {here} && env TERM=xterm-256color LC_ALL=C {rb} run --tui --speed 64 timeline.bas; sleep 600")
    start = time.monotonic()
    wait(lambda t: re.search(r"state +finished", t) is not None)
    ran = time.monotonic() - start
    rss = subprocess.run(["ps", "-o", "rss=", "-C", "rb"], capture_output=True, text=True).stdout.split()
    step = lambda t: (re.search(r"back in time: (step [\d,]+|the end) of ([\d,]+)", t.split("\n")[0]) or [None, None])[1]
    def timed(key, changed):
        before = screen()
        t0 = time.perf_counter()
        tmux("send-keys", "-t", "main", key)
        after = wait(lambda t: changed(before, t))
        return time.perf_counter() - t0, after
    times = {"Left (one statement back)": [], "Right (one forward)": [], "Home (a tenth back)": [],
             "F4/F5 (baseline: the speed shown)": []}
    seen = []
    tmux("send-keys", "-t", "main", "Left")  # from the end to the last statement
    wait(lambda t: step(t) is not None)
    for _ in range(runs):
        dt, t = timed("Left", lambda b, t: step(t) != step(b))
        times["Left (one statement back)"].append(dt)
        seen.append(step(t))
    nums = [int(s.split()[1].replace(",", "")) for s in seen]
    single = all(a - b == 1 for a, b in zip(nums, nums[1:]))
    for _ in range(runs):
        dt, _ = timed("Right", lambda b, t: step(t) != step(b))
        times["Right (one forward)"].append(dt)
    for _ in range(min(runs, 9)):
        dt, _ = timed("Home", lambda b, t: step(t) != step(b))
        times["Home (a tenth back)"].append(dt)
    speed = lambda t: (re.search(r"speed +(x\S+)", t) or [None, None])[1]
    for i in range(runs):
        dt, _ = timed("F4" if i % 2 == 0 else "F5", lambda b, t: speed(t) != speed(b))
        times["F4/F5 (baseline: the speed shown)"].append(dt)
    total = re.search(r"of ([\d,]+)", title()).group(1)
    print(f"machine:  {machine()}")
    print(f"rb:       {rb}")
    print(f"run:      timeline.bas, {total} statements, to its end in {ran:.1f} s in the view "
          f"(--speed 64); rb's resident memory then {int(rss[0]) // 1024 if rss else '?'} MiB")
    print(f"steps:    {'each Left moved exactly one statement' if single else 'Left moved by more than one statement: ' + str(nums[:5])}")
    print()
    print(f"| key | median | max | runs |")
    print(f"|---|---:|---:|---:|")
    for k, v in times.items():
        print(f"| {k} | {statistics.median(v) * 1000:.1f} ms | {max(v) * 1000:.1f} ms | {len(v)} |")
    tmux("send-keys", "-t", "main", "F10")
finally:
    tmux("kill-server")
    shutil.rmtree(d, ignore_errors=True)
PY
