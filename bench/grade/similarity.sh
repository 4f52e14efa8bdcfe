#!/usr/bin/env bash
# rb test --similarity's comparison alone (the hidden `rb test-similarity`, which grades nothing)
# on generated classes: COUNTS programs of LINES lines each (similar_gen.py: a shared template,
# shared libraries, the students' own code and copies, all edited), with the median wall and
# processor time (user + system) of RUNS runs and the peak memory (max RSS, GNU time) of one.
# Target (issue 38): 2,000 programs of 10,000 lines within 5 s and 200 MB.
# Usage: bench/grade/similarity.sh [path/to/rb] [-n RUNS]   (default 3 runs)
#   COUNTS="200 2000 20000" LINES=10000 THREADS=0 (0: one a processor) select the classes;
#   the classes are written under TMPDIR (20,000 programs of 10,000 lines take 4.3 GB).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=3
source "$here/../args.sh" "$@"
counts="${COUNTS:-200 2000}"
lines="${LINES:-10000}"
threads="${THREADS:-0}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 - "$rb" "$here" "$dir" "$runs" "$lines" "$threads" $counts <<'PY'
import os, resource, shutil, statistics, subprocess, sys, tempfile, time
rb, here, d, runs, lines, threads = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5], sys.argv[6]
counts = [int(c) for c in sys.argv[7:]]
sys.path.insert(0, here + "/..")
from measure import machine
print(f"machine: {machine()}")


def cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


print(f"{'programs':>9} {'lines':>6} {'MB':>6} {'wall':>8} {'cpu':>8} {'peak RSS':>9}  pairs")
for count in counts:
    cls = os.path.join(d, f"class{count}")
    subprocess.run([sys.executable, os.path.join(here, "similar_gen.py"), cls, str(count), lines], check=True)
    size = sum(os.path.getsize(os.path.join(cls, f)) for f in os.listdir(cls)) / 1e6
    cmd = [rb, "test-similarity", "--threads", threads, cls]
    walls, cpus, first = [], [], None
    for _ in range(runs):
        t, c = time.perf_counter(), cpu()
        p = subprocess.run(cmd, capture_output=True, text=True)
        walls.append(time.perf_counter() - t)
        cpus.append(cpu() - c)
        if p.returncode != 0:
            sys.exit(f"rb test-similarity failed: {p.stderr[-2000:]}")
        if first is None:
            first = p.stdout
        elif p.stdout != first:
            sys.exit("two runs gave different reports")
    with tempfile.NamedTemporaryFile("r") as out:
        subprocess.run(["/usr/bin/time", "-f", "%M", "-o", out.name] + cmd, stdout=subprocess.DEVNULL, check=True)
        peak = int(out.read().split()[-1]) / 1024
    heading = first.splitlines()[0] if first else ""
    print(f"{count:>9} {lines:>6} {size:>6.0f} {statistics.median(walls):>7.2f}s {statistics.median(cpus):>7.2f}s "
          f"{peak:>7.0f} MB  {heading}", flush=True)
    shutil.rmtree(cls)
PY
