#!/usr/bin/env bash
# The class report page (rb test --html): a class of 1,000 programs (gen.py's, graded against
# its seven-check assignment with -j 2) and
#   - the time rb takes to write the report after grading: the wall time of `rb test --html`
#     less the grading time it reports (the JSON summary's `seconds`): the 1,000 program pages,
#     the class page (the pictures, final screens and replays are written while grading);
#     target: under 10 s;
#   - grading with --html against without (the pictures, screens and replays it adds);
#   - the class page opened in headless Chromium from file:// (load event, and the time until
#     the first cards' final screens are drawn); target: under 2 s;
#   - the size of the report's folder.
# Usage: bench/grade/html.sh [path/to/rb] [-n RUNS] (default 3 runs; COUNT=N for another class size)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=3
source "$here/../args.sh" "$@"
count="${COUNT:-1000}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 "$here/gen.py" "$dir" "$count"
python3 - "$rb" "$here" "$dir" "$runs" "$count" <<'PY'
import json, os, resource, shutil, statistics, subprocess, sys, time
rb, here, d, runs, count = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
sys.path.insert(0, here + "/..")
sys.path.insert(0, here + "/../../testdata/render")
from measure import machine
from replay_browser import Browser, find_chromium

print(f"machine: {machine()}")
base = [rb, "test", "-q", "-j", "2", "--format", "json", "-a", os.path.join(d, "assignment.toml"),
        os.path.join(d, "class")]
out = os.path.join(d, "report")


def cpu():
    """Processor time (user + system) of every child process waited for so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


rows = {"rb test (no report)": [], "rb test --html": [], "writing the report": []}
cpus = {"rb test (no report)": [], "rb test --html": []}
for _ in range(runs):
    t, c = time.perf_counter(), cpu()
    subprocess.run(base, capture_output=True, check=False)
    rows["rb test (no report)"].append(time.perf_counter() - t)
    cpus["rb test (no report)"].append(cpu() - c)
    shutil.rmtree(out, ignore_errors=True)
    t, c = time.perf_counter(), cpu()
    p = subprocess.run(base + ["--html", out], capture_output=True, text=True)
    total = time.perf_counter() - t
    cpus["rb test --html"].append(cpu() - c)
    graded = json.loads(p.stdout)["summary"]["seconds"]
    rows["rb test --html"].append(total)
    rows["writing the report"].append(total - graded)

size = sum(os.path.getsize(os.path.join(r, f)) for r, _, fs in os.walk(out) for f in fs)
files = sum(len(fs) for _, _, fs in os.walk(out))
index = os.path.getsize(os.path.join(out, "index.html"))
for name, values in rows.items():
    extra = f"; processor time (rb and its children) median {statistics.median(cpus[name]):.2f} s" if name in cpus else ""
    print(f"{name:24} wall median {statistics.median(values):7.2f} s  (runs: {', '.join(f'{v:.2f}' for v in values)}){extra}")
print(f"report: {files} files, {size / 1e6:.1f} MB; index.html {index / 1e6:.2f} MB")

chromium = find_chromium()
if not chromium:
    sys.exit("Chromium is not installed (scripts/setup.sh --test)")
loads, drawn, cards = [], [], 0
for _ in range(runs):
    b = Browser(chromium, d)
    try:
        t = time.perf_counter()
        b.open(os.path.join(out, "index.html"))
        loads.append(time.perf_counter() - t)
        if b.js("document.readyState") != "complete":
            sys.exit("the load event came before the page was complete")
        b.js("""new Promise(r => { const imgs = Array.from(document.querySelectorAll('#cards img')).slice(0, 8);
            const check = () => imgs.every(i => i.complete && i.naturalWidth) ? r() : setTimeout(check, 5); check(); })""")
        drawn.append(time.perf_counter() - t)
        cards = b.js("document.querySelectorAll('#cards .card').length")
        if b.errors:
            sys.exit("console errors: " + "; ".join(b.errors))
    finally:
        b.close()
print(f"open in Chromium: {cards} cards, load event median {statistics.median(loads):.2f} s, first screens drawn "
      f"median {statistics.median(drawn):.2f} s (runs: {', '.join(f'{v:.2f}' for v in loads)})")
PY
