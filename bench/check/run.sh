#!/usr/bin/env bash
# Times `rb check` on 1,000 generated programs of 300 lines in one call (target: well under
# a second). Usage: bench/check/run.sh [path/to/rb] [runs]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rb="${1:-$here/../../build/cmd/rb}"
runs="${2:-7}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 "$here/gen.py" "$dir" 1000
lines=$(cat "$dir"/*.bas | wc -l)
"$rb" check "$dir"/*.bas > /dev/null || { echo "rb check reported errors in the generated programs" >&2; exit 1; }
python3 - "$rb" "$dir" "$runs" "$lines" <<'PY'
import glob, statistics, subprocess, sys, time
rb, d, runs, lines = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
files = sorted(glob.glob(d + "/*.bas"))
times = []
for _ in range(runs):
    t = time.perf_counter()
    subprocess.run([rb, "check"] + files, check=True, stdout=subprocess.DEVNULL)
    times.append(time.perf_counter() - t)
med = statistics.median(times)
print(f"rb check: {len(files)} files, {lines} lines: median {med*1000:.0f} ms over {runs} runs "
      f"({lines/med/1e6:.2f} million lines/s)")
PY
