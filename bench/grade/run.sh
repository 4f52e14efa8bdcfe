#!/usr/bin/env bash
# Times `rb test` grading a class of 1,000 programs of the seed's size (Figure 1.7's square)
# against an assignment with seven checks (rb check, no error, the solution's output, corners in
# order, the solution's trail, the end position, the solution's screen), with -j 2: every
# program runs in a child process of its own. For scale it also times the same 1,000 programs
# run bare (`rb run`, two at a time through xargs -P 2).
# Usage: bench/grade/run.sh [path/to/rb] [runs] [programs]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rb="${1:-$here/../../build/cmd/rb}"
runs="${2:-3}"
count="${3:-1000}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 "$here/gen.py" "$dir" "$count"
python3 - "$rb" "$dir" "$runs" "$count" <<'PY'
import json, os, resource, statistics, subprocess, sys, time
rb, d, runs, count = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])


def cpu():
    """Processor time (user + system) of every child process waited for so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


cls = os.path.join(d, "class")
grade = [rb, "test", "-q", "-j", "2", "--format", "json", "-a", os.path.join(d, "assignment.toml"), cls]
bare = f"ls {cls}/*.bas | xargs -P 2 -n 1 {rb} run > /dev/null 2>&1; true"
times, bare_times, cpus, bare_cpus, results = [], [], [], [], None
for _ in range(runs):
    t, c = time.perf_counter(), cpu()
    p = subprocess.run(grade, capture_output=True, text=True)
    times.append(time.perf_counter() - t)
    cpus.append(cpu() - c)
    doc = json.loads(p.stdout)
    got = [(q["program"], q["result"], q["reason"]) for q in doc["programs"]]
    if results is not None and got != results:
        sys.exit("rb test graded the class differently on two runs")
    results = got
    t, c = time.perf_counter(), cpu()
    subprocess.run(bare, shell=True)
    bare_times.append(time.perf_counter() - t)
    bare_cpus.append(cpu() - c)
s = doc["summary"]
med, bare_med = statistics.median(times), statistics.median(bare_times)
print(f"rb test -j 2: {count} programs, {s['passed']} passed, {s['failed']} failed: "
      f"median {med:.2f} s over {runs} runs ({med / count * 1000:.1f} ms per program)")
print(f"rb run, 2 at a time: median {bare_med:.2f} s ({bare_med / count * 1000:.1f} ms per program)")
cpu_med, bare_cpu_med = statistics.median(cpus), statistics.median(bare_cpus)
print(f"processor time (user + system, rb and every child): rb test {cpu_med:.2f} s, bare rb run "
      f"{bare_cpu_med:.2f} s: {cpu_med / bare_cpu_med:.2f}x")
PY
