#!/usr/bin/env bash
# Start-up: `rb run` of an empty program against `lua5.4 -e ''` (target: under 2 ms), timed by
# hyperfine (no shell, warm-up runs first), medians and peak resident memory. hyperfine and
# lua5.4 show n/a when missing. Usage: bench/startup.sh [path/to/rb] [-n RUNS]  (default 300)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=300
source "$here/args.sh" "$@"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
: > "$dir/empty.bas"
python3 - "$rb" "$dir" "$runs" "$here" <<'PY'
import json, shutil, subprocess, sys
rb, d, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
sys.path.insert(0, sys.argv[4])
from measure import alternate, machine, ms, mib
print(f"machine: {machine()}")
cmds = {"rb run empty.bas": [rb, "run", d + "/empty.bas"]}
if shutil.which("lua5.4"):
    cmds["lua5.4 -e ''"] = ["lua5.4", "-e", ""]
rss = {name: g["rss"] for name, g in alternate({n: (c, "") for n, c in cmds.items()}, 5).items()}
if not shutil.which("hyperfine"):
    print("hyperfine n/a (apt-get install hyperfine)")
    sys.exit(0)
subprocess.run(["hyperfine", "-N", "-w", "30", "-r", str(runs), "--export-json", d + "/h.json"]
               + [subprocess.list2cmdline(c) for c in cmds.values()],
               check=True, stdout=subprocess.DEVNULL)
res = json.load(open(d + "/h.json"))["results"]
print(f"{'start-up':20} {'median':>9} {'mean':>9} {'user+sys':>9} {'peak RSS':>10}")
for name, r in zip(cmds, res):
    print(f"{name:20} {ms(r['median']):>9} {ms(r['mean']):>9} {ms(r['user'] + r['system']):>9} {mib(rss[name]):>10}")
if len(res) == 2:
    print(f"rb / Lua: {res[0]['median'] / res[1]['median']:.2f}x (median)")
PY
