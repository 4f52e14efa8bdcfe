#!/usr/bin/env bash
# rb test --merge: a class of 1,000 programs (gen.py's, its seven-check assignment) graded once
# whole and once as 4 shards (rb test --shard K/4 --format json --html shardK, one after the
# other, -j 2), then the shards' reports merged, twice: into the reports without pictures
# (JSON, text, CSV, JUnit, feedback) and with --html (the class page, 1,000 program pages, every
# picture, final screen and replay copied beside it). For each merge (run RUNS times): the
# median wall time, the median processor time and the peak memory of the merging process (its
# own rusage, from wait4); and that every merged report is the whole run's, times and timestamps
# aside (the JSON, the CSV, the JUnit report, the class page, the pictures' names).
# Usage: bench/grade/merge.sh [path/to/rb] [programs] [shards] [runs]   (default 1000 4 5)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rb="$(realpath "${1:-$here/../../build/cmd/rb}")"
count="${2:-1000}"
shards="${3:-4}"
runs="${4:-5}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 "$here/gen.py" "$dir" "$count"
python3 - "$rb" "$dir" "$count" "$shards" "$here" "$runs" <<'PY'
import csv, io, json, os, re, shutil, statistics, subprocess, sys, time
rb, d, count, n, runs = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[6])
sys.path.insert(0, sys.argv[5] + "/..")
from measure import machine

print(f"machine: {machine()}")
grade = ["test", "-q", "-j", "2", "-a", os.path.join(d, "assignment.toml")]
cls = os.path.join(d, "class")


def run(args, cwd):
    """Runs rb in cwd: (stdout, wall seconds, peak resident memory in MiB, processor seconds)."""
    out = open(os.path.join(cwd, "stdout"), "w+")
    t = time.perf_counter()
    p = subprocess.Popen([rb] + args, cwd=cwd, stdout=out, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t
    err = p.stderr.read().decode()
    out.seek(0)
    text = out.read()
    code = os.waitstatus_to_exitcode(status)
    if code not in (0, 1):
        sys.exit(f"rb {' '.join(args)}: exit {code}\n{err}")
    return text, wall, usage.ru_maxrss / 1024, usage.ru_utime + usage.ru_stime


def normalised(kind, text):
    if kind == "json":
        doc = json.loads(text)
        for p in doc["programs"]:
            p.pop("seconds")
        doc["summary"].pop("seconds")
        doc.pop("timestamp")
        return doc
    if kind == "csv":
        rows = list(csv.reader(io.StringIO(text)))
        col = rows[0].index("seconds")
        return [r[:col] + r[col + 1:] for r in rows]
    if kind == "junit":
        return re.sub(r'(time|timestamp)="[^"]*"', 'T', text)
    text = re.sub(r"nonce-[0-9a-f]+'|nonce=\"[0-9a-f]+\"", "N", text)
    return re.sub(r"Graded [0-9T:-]+ by", "Graded T by", text)


def read(*parts):
    with open(os.path.join(*parts)) as f:
        return f.read()


reports = ["--junit", "report.xml", "--csv", "grades.csv", "--feedback", "feedback", "--format", "json"]
whole = os.path.join(d, "whole")
os.makedirs(whole)
_, whole_wall, _, _ = run(grade + reports + ["--html", "report", cls], whole)
split = os.path.join(d, "split")
os.makedirs(split)
shard_walls, sizes = [], []
for k in range(1, n + 1):
    text, wall, _, _ = run(grade + ["--shard", f"{k}/{n}", "--format", "json", "--html", f"shard{k}", cls], split)
    with open(os.path.join(split, f"shard{k}.json"), "w") as f:
        f.write(text)
    shard_walls.append(wall)
    sizes.append(len(text.encode()))
files = [f"shard{k}.json" for k in range(1, n + 1)]
plain = os.path.join(d, "plain")
os.makedirs(plain)


def merges(args, cwd):
    """The merge run `runs` times: its last output, the median wall time, each run's, the peak
    memory, the median processor time."""
    walls, mems, cpus = [], [], []
    for _ in range(runs):
        shutil.rmtree(os.path.join(cwd, "report"), ignore_errors=True)
        text, wall, mem, cpu = run(args, cwd)
        walls.append(wall)
        mems.append(mem)
        cpus.append(cpu)
    return text, statistics.median(walls), walls, max(mems), statistics.median(cpus)


plain_json, plain_wall, plain_walls, plain_mem, plain_cpu = merges(
    ["test", "--merge"] + [os.path.join(split, f) for f in files] + reports, plain)
html_json, html_wall, html_walls, html_mem, html_cpu = merges(["test", "--merge"] + files + reports + ["--html", "report"], split)

whole_json = read(whole, "stdout")
problems = []
for name, got in (("merge", plain_json), ("merge --html", html_json)):
    a, b = normalised("json", whole_json), normalised("json", got)
    if name == "merge":  # without --html the pictures stay where the shards wrote them
        for doc in (a, b):
            for p in doc["programs"]:
                for key in ("picture", "screen", "replay"):
                    p.pop(key, None)
    if a != b:
        problems.append(f"{name}: the JSON differs")
for folder in (plain, split):
    if normalised("csv", read(whole, "grades.csv")) != normalised("csv", read(folder, "grades.csv")):
        problems.append(f"{folder}: the CSV differs")
    if normalised("junit", read(whole, "report.xml")) != normalised("junit", read(folder, "report.xml")):
        problems.append(f"{folder}: the JUnit report differs")
if normalised("html", read(whole, "report", "index.html")) != normalised("html", read(split, "report", "index.html")):
    problems.append("the class page differs")
names = sorted(os.listdir(os.path.join(split, "report", "pictures")))
pictures = len(names)
if names != sorted(os.listdir(os.path.join(whole, "report", "pictures"))):
    problems.append("the pictures' names differ")
s = json.loads(whole_json)["summary"]
print(f"class: {count} programs ({s['passed']} passed, {s['failed']} failed), {n} shards; "
      f"shard reports {min(sizes) / 1e6:.2f} to {max(sizes) / 1e6:.2f} MB")
print(f"grading whole with --html: {whole_wall:.1f} s; the shards one after the other: "
      f"{', '.join(f'{w:.1f}' for w in shard_walls)} s")
each = lambda walls: ", ".join(f"{w:.2f}" for w in walls)
print(f"rb test --merge ({n} reports; JSON, text, CSV, JUnit, feedback): median {plain_wall:.2f} s "
      f"({each(plain_walls)}), processor {plain_cpu:.2f} s, peak {plain_mem:.0f} MiB")
print(f"rb test --merge ... --html ({pictures} pictures copied): median {html_wall:.2f} s ({each(html_walls)}), "
      f"processor {html_cpu:.2f} s, peak {html_mem:.0f} MiB")
print("equal to the whole run (times aside): " + ("yes" if not problems else "NO: " + "; ".join(problems)))
sys.exit(1 if problems else 0)
PY
