#!/usr/bin/env bash
# Benchmarks rb against Lua 5.4, LuaJIT's interpreter (luajit -joff, the .lua programs),
# yabasic, brandy (Matrix Brandy BBC BASIC) and, where a benchmark has a .py version, Python 3.
#
#   bench/run.sh [-n N] [path/to/rb]
#
# Every program in bench/programs/ is first run once per implementation and its output checked
# against the expected answer (the script fails loudly on a wrong answer or a crash); then each
# program is run N times per implementation (default 7, in rounds that alternate between the
# implementations so that background load hits them alike) and the median wall time is
# reported with its ratio to Lua 5.4 (rb's also to LuaJIT's interpreter), then the peak memory
# (maximum resident set size, measured once per program and implementation with GNU time).
# The programs run at least half a second in Lua 5.4; the startup row is one line, `print 1`.
# A peer that is not installed, or a benchmark without a version for it, is shown as n/a.
# Results are also written to bench/results/ (git-ignored) as text and JSON.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$here/../scripts/setup.sh" --bench >/dev/null   # the peers: Lua 5.4, LuaJIT, yabasic, brandy, hyperfine
runs=7

usage() {
  sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'
}

while getopts ":n:h" opt; do
  case "$opt" in
    n) runs="$OPTARG" ;;
    h) usage; exit 0 ;;
    :) echo "run.sh: -$OPTARG needs a value" >&2; exit 64 ;;
    *) echo "run.sh: unknown option -$OPTARG (try -h)" >&2; exit 64 ;;
  esac
done
shift $((OPTIND - 1))
if [[ $# -gt 1 ]]; then
  echo "run.sh: at most one argument, the path to rb (try -h)" >&2
  exit 64
fi
if ! [[ "$runs" =~ ^[1-9][0-9]*$ ]]; then
  echo "run.sh: -n wants a positive whole number, not '$runs'" >&2
  exit 64
fi

rb="${1:-$here/../build/cmd/rb}"
if [[ ! -x "$rb" ]]; then
  echo "run.sh: rb not found or not executable at '$rb' (build it: ninja -C build)" >&2
  exit 66
fi
rb="$(cd "$(dirname "$rb")" && pwd)/$(basename "$rb")"

if ! command -v python3 >/dev/null; then
  echo "run.sh: python3 is needed to time the runs" >&2
  exit 69
fi

exec python3 - "$here" "$rb" "$runs" <<'PYTHON'
import datetime
import json
import os
import platform
import shutil
import statistics
import tempfile
import subprocess
import sys
import threading
import time

here, rb, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
programs = os.path.join(here, "programs")

# name -> expected output (the whole of stdout, without the final newline)
BENCHMARKS = [
    ("startup", "1"),
    ("loop", "25000002500000"),
    ("calls", "40000000"),
    ("strings", "29477790"),
    ("arrays", "148933"),
    ("matmul", "546750000"),
    ("fib", "5702887"),
    ("fib_sub", "5702887"),
    ("callparams", "1500007500000"),
    ("appends", "150000"),
    ("appends10m", "10000000"),
]

# Brandy on Debian is an SDL build: the dummy video driver keeps it off any display, and the
# programs write their answer to /dev/stdout themselves (PRINT goes to the SDL window). Its
# stdout must be a pipe, not a file: OPENOUT truncates a file.
BRANDY_ENV = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")

# (label, executable, extension, argv builder, environment)
IMPLS = [
    ("rb", rb, "bas", lambda exe, f: [exe, "run", f], None),
    ("lua", shutil.which("lua5.4"), "lua", lambda exe, f: [exe, f], None),
    ("luajit -joff", shutil.which("luajit"), "lua", lambda exe, f: [exe, "-joff", f], None),
    ("yabasic", shutil.which("yabasic"), "yab", lambda exe, f: [exe, f], None),
    ("brandy", shutil.which("brandy"), "bbc", lambda exe, f: [exe, "-quit", f], BRANDY_ENV),
    ("python", sys.executable, "py", lambda exe, f: [exe, f], None),
]


def program(name, ext):
    """The benchmark's version for an implementation, or None when it has none."""
    path = os.path.join(programs, f"{name}.{ext}")
    return path if os.path.exists(path) else None


def first_line(cmd, env=None):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return "?"
    text = (p.stdout or p.stderr).strip()
    return text.splitlines()[0] if text else "?"


def machine():
    model, cores = "unknown CPU", os.cpu_count()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            kb = int(f.readline().split()[1])
            mem = f", {kb / 1024 / 1024:.0f} GiB RAM"
    except (OSError, ValueError, IndexError):
        pass
    return f"{model}, {cores} cores{mem}, {platform.system()} {platform.release()}"


def version(label, exe):
    if exe is None:
        return "not installed"
    if label == "rb":
        v = first_line([exe, "--version"])
        try:
            rev = subprocess.run(["git", "-C", here, "rev-parse", "--short", "HEAD"],
                                 capture_output=True, text=True, timeout=10).stdout.strip()
            if rev:
                v += f", repository at {rev}"
        except OSError:
            pass
        built = datetime.datetime.fromtimestamp(os.path.getmtime(exe)).astimezone()
        return f"{v}, binary {exe} built {built:%Y-%m-%d %H:%M}"
    if label == "lua":
        return first_line([exe, "-v"])
    if label.startswith("luajit"):
        return first_line([exe, "-v"]) + " (its interpreter: -joff)"
    if label in ("yabasic", "python"):
        return first_line([exe, "--version"])
    return first_line([exe, "-version"], BRANDY_ENV)


class Ran:
    """What one run left: exit status, output, wall and CPU seconds."""


# Peak memory comes from GNU time (%M, the maximum resident set size), run as the program's
# parent: Linux counts in a process's maximum RSS the memory of the process that called exec,
# so a child that Python forks and execs never reports less than Python's own 15 MiB.
TIME = "/usr/bin/time" if os.access("/usr/bin/time", os.X_OK) else None


def peak_memory(argv, env):
    """The program's peak memory in bytes (one run), or None without GNU time."""
    if TIME is None:
        return None
    with tempfile.NamedTemporaryFile("r") as out:
        subprocess.run([TIME, "-f", "%M", "-o", out.name] + argv, stdin=subprocess.DEVNULL,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
        try:
            return int(out.read().split()[-1]) * 1024
        except (ValueError, IndexError):
            return None


def run_once(argv, env):
    """Runs argv to its end and returns a Ran (CPU time from os.wait4: this child's own)."""
    start = time.perf_counter()
    p = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, env=env)
    err = []
    reader = threading.Thread(target=lambda: err.append(p.stderr.read()))
    reader.start()
    out = p.stdout.read()
    reader.join()
    _, status, usage = os.wait4(p.pid, 0)
    r = Ran()
    r.elapsed = time.perf_counter() - start
    p.returncode = r.returncode = os.waitstatus_to_exitcode(status)
    p.stdout.close()
    p.stderr.close()
    r.stdout, r.stderr = out, err[0]
    r.cpu = usage.ru_utime + usage.ru_stime
    return r


stamp = datetime.datetime.now().astimezone()
header = [
    f"date:     {stamp:%Y-%m-%d %H:%M %Z}",
    f"machine:  {machine()}",
]
for label, exe, *_ in IMPLS:
    header.append(f"{label + ':':9} {version(label, exe)}")
header.append(f"runs:     {runs} per program and implementation; median wall time, "
              f"ratio to Lua 5.4 in parentheses (rb's also to LuaJIT's interpreter); then peak memory "
              f"(max RSS, one run)")
for line in header:
    print(line)
print(flush=True)

# 1. Check every answer (this is also the warm-up run), and measure peak memory once.
failures = []
peak = {name: {label: None for label, *_ in IMPLS} for name, _ in BENCHMARKS}
for name, expected in BENCHMARKS:
    for label, exe, ext, argv_of, env in IMPLS:
        path = program(name, ext)
        if exe is None or path is None:
            continue
        p = run_once(argv_of(exe, path), env)
        got = p.stdout.decode(errors="replace").rstrip("\n")
        if p.returncode != 0 or got != expected:
            err = p.stderr.decode(errors="replace").strip()
            failures.append(f"{name}.{ext} ({label}): exit {p.returncode}, printed {got!r}, "
                            f"expected {expected!r}" + (f"\n    stderr: {err[-500:]}" if err else ""))
        else:
            peak[name][label] = peak_memory(argv_of(exe, path), env)
if failures:
    print("FAILED: wrong answers, nothing was timed:", file=sys.stderr)
    for f in failures:
        print("  " + f, file=sys.stderr)
    sys.exit(1)
print("answers: all implementations print the expected results\n", flush=True)

# 2. Time: N rounds, each round runs every implementation once, per benchmark.
results = {}
for name, expected in BENCHMARKS:
    times = {label: [] for label, *_ in IMPLS}
    cpus = {label: [] for label, *_ in IMPLS}
    for _ in range(runs):
        for label, exe, ext, argv_of, env in IMPLS:
            path = program(name, ext)
            if exe is None or path is None:
                continue
            p = run_once(argv_of(exe, path), env)
            got = p.stdout.decode(errors="replace").rstrip("\n")
            if p.returncode != 0 or got != expected:
                print(f"FAILED: {name}.{ext} ({label}) printed {got!r} (exit {p.returncode}) "
                      f"while timing, expected {expected!r}", file=sys.stderr)
                sys.exit(1)
            times[label].append(p.elapsed * 1000.0)
            cpus[label].append(p.cpu * 1000.0)
    results[name] = {label: (statistics.median(t) if t else None) for label, t in times.items()}
    results[name + ":all"] = times
    results[name + ":cpu"] = cpus
    results[name + ":rss"] = peak[name]

# 3. Table.
labels = [label for label, *_ in IMPLS]


def cell(name, label):
    ms = results[name][label]
    if ms is None:
        return "n/a"
    shown = f"{ms:.1f} ms" if ms < 20 else f"{ms:.0f} ms"
    lua = results[name]["lua"]
    if label == "lua" or lua is None:
        return shown
    if label == "rb" and results[name]["luajit -joff"] is not None:
        return f"{shown} ({ms / lua:.2f}x; {ms / results[name]['luajit -joff']:.2f}x LuaJIT)"
    return f"{shown} ({ms / lua:.2f}x)"


def memory(name, label):
    b = results[name + ":rss"][label]
    return "n/a" if b is None else f"{b / 1048576:.1f} MiB"


def layout(rows):
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    return ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in rows]


rows = [["benchmark"] + labels]
for name, _ in BENCHMARKS:
    rows.append([name] + [cell(name, label) for label in labels])
rows_mem = [["peak memory"] + labels]
for name, _ in BENCHMARKS:
    rows_mem.append([name] + [memory(name, label) for label in labels])
table = layout(rows) + [""] + layout(rows_mem)
for line in table:
    print(line)

# 4. Save.
outdir = os.path.join(here, "results")
os.makedirs(outdir, exist_ok=True)
base = os.path.join(outdir, f"{stamp:%Y%m%d-%H%M%S}")
with open(base + ".txt", "w") as f:
    f.write("\n".join(header) + "\n\n" + "\n".join(table) + "\n")
with open(base + ".json", "w") as f:
    json.dump({
        "date": stamp.isoformat(timespec="seconds"),
        "machine": machine(),
        "versions": {label: version(label, exe) for label, exe, *_ in IMPLS},
        "runs": runs,
        "median_ms": {name: results[name] for name, _ in BENCHMARKS},
        "all_ms": {name: results[name + ":all"] for name, _ in BENCHMARKS},
        "all_cpu_ms": {name: results[name + ":cpu"] for name, _ in BENCHMARKS},
        "peak_memory_bytes": {name: results[name + ":rss"] for name, _ in BENCHMARKS},
    }, f, indent=2)
shown = os.path.relpath(base)
print(f"\nsaved {shown if not shown.startswith('..') else base}.txt and .json")
PYTHON
