#!/usr/bin/env bash
# rb check's speed and memory:
#   1. 1,000 generated programs of 300 lines each checked in one call (target: well under a
#      second);
#   2. one file of 10,000, 100,000 and 1,000,000 lines (the same kind of program, 300-line
#      programs one after another) against Lua 5.4 compiling the same program written in Lua
#      (lua5.4 -e 'assert(loadfile(FILE))': parse and compile, no run); peak resident memory
#      of each (target for the 1M-line file: under 100 MiB, and no slower than Lua).
# Every run's output is checked (rb check: no diagnostics). Lua shows n/a when lua5.4 is missing.
# Usage: bench/check/run.sh [path/to/rb] [runs]   (default 5)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rb="${1:-$here/../../build/cmd/rb}"
runs="${2:-5}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 "$here/gen.py" "$dir/many" 1000
for n in 10000 100000 1000000; do python3 "$here/gen.py" --one "$n" "$dir/one$n"; done
"$rb" check "$dir"/many/*.bas > /dev/null || { echo "rb check reported errors in the generated programs" >&2; exit 1; }
python3 - "$rb" "$dir" "$runs" "$here/.." <<'PY'
import glob, shutil, sys
rb, d, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
sys.path.insert(0, sys.argv[4])
from measure import alternate, machine, ms, mib
print(f"machine: {machine()}")
files = sorted(glob.glob(d + "/many/*.bas"))
lines = sum(open(f).read().count("\n") for f in files)
g = alternate({"many": ([rb, "check"] + files, "")}, runs)["many"]
print(f"rb check: {len(files)} files, {lines} lines: median {ms(g['wall'])} over {runs} runs "
      f"({lines / g['wall'] / 1e6:.2f} million lines/s), peak {mib(g['rss'])}")
lua = shutil.which("lua5.4")
print(f"{'one file':16} {'rb check':>10} {'cpu':>9} {'peak RSS':>10} {'Lua loadfile':>13} {'cpu':>9} {'peak RSS':>10} {'rb/Lua':>7}")
for n in (10000, 100000, 1000000):
    stem = f"{d}/one{n}"
    jobs = {"rb": ([rb, "check", stem + ".bas"], "")}
    if lua:
        jobs["lua"] = ([lua, "-e", f"assert(loadfile('{stem}.lua'))"], "")
    got = alternate(jobs, runs if n < 1000000 else max(1, runs // 2 + 1))
    r = got["rb"]
    row = f"{n:>9,} lines {ms(r['wall']):>10} {ms(r['cpu']):>9} {mib(r['rss']):>10}"
    if lua:
        l = got["lua"]
        row += f" {ms(l['wall']):>13} {ms(l['cpu']):>9} {mib(l['rss']):>10} {r['cpu'] / l['cpu']:6.2f}x"
    else:
        row += f" {'n/a':>13}"
    print(row)
PY
