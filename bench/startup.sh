#!/usr/bin/env bash
# Start-up: `rb run` of an empty program and of a one-line one (`print 1`) against Lua 5.4's and
# LuaJIT's interpreter's (`luajit -joff`) one-line `print(1)` and empty `-e ''` (target, issue
# 38: the one-line program at most Lua 5.4's time, the empty one's peak memory under 4 MiB),
# timed by hyperfine (no shell, warm-up runs first), medians and peak resident memory.
# hyperfine, lua5.4 and luajit show n/a when missing.
# Usage: bench/startup.sh [path/to/rb] [-n RUNS]  (default 300)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=300
source "$here/args.sh" "$@"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
: > "$dir/empty.bas"
echo 'print 1' > "$dir/one.bas"
python3 - "$rb" "$dir" "$runs" "$here" <<'PY'
import json, shutil, subprocess, sys
rb, d, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
sys.path.insert(0, sys.argv[4])
from measure import alternate, machine, ms, mib
print(f"machine: {machine()}")
cmds = {"rb run empty.bas": [rb, "run", d + "/empty.bas"], "rb run one.bas": [rb, "run", d + "/one.bas"]}
if shutil.which("lua5.4"):
    cmds["lua5.4 -e ''"] = ["lua5.4", "-e", ""]
    cmds["lua5.4 -e 'print(1)'"] = ["lua5.4", "-e", "print(1)"]
if shutil.which("luajit"):
    cmds["luajit -joff -e ''"] = ["luajit", "-joff", "-e", ""]
    cmds["luajit -joff -e 'print(1)'"] = ["luajit", "-joff", "-e", "print(1)"]
rss = {name: g["rss"] for name, g in alternate({n: (c, None) for n, c in cmds.items()}, 5).items()}
if not shutil.which("hyperfine"):
    print("hyperfine n/a (apt-get install hyperfine)")
    sys.exit(0)
subprocess.run(["hyperfine", "-N", "-w", "30", "-r", str(runs), "--export-json", d + "/h.json"]
               + [subprocess.list2cmdline(c) for c in cmds.values()],
               check=True, stdout=subprocess.DEVNULL)
res = json.load(open(d + "/h.json"))["results"]
print(f"{'start-up':28} {'median':>9} {'mean':>9} {'user+sys':>9} {'peak RSS':>10}")
for name, r in zip(cmds, res):
    print(f"{name:28} {ms(r['median']):>9} {ms(r['mean']):>9} {ms(r['user'] + r['system']):>9} {mib(rss[name]):>10}")
median = {name: r["median"] for name, r in zip(cmds, res)}
for peer in ("lua5.4 -e 'print(1)'", "luajit -joff -e 'print(1)'"):
    if peer in median:
        print(f"rb run one.bas / {peer}: {median['rb run one.bas'] / median[peer]:.2f}x (median)")
PY
