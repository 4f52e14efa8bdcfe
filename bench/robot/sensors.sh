#!/usr/bin/env bash
# Cost of one call of each sensor, in open space and beside a wall: 1,000,000 calls each, minus
# the same loop without the call. Usage: bench/robot/sensors.sh [path/to/rb]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rb="${1:-$here/../../build/cmd/rb}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
calls=1000000
time_of() {  # median of 5 runs, in seconds
  python3 - "$rb" "$1" <<'PY'
import statistics, subprocess, sys, time
ts = []
for _ in range(5):
    t = time.perf_counter()
    subprocess.run([sys.argv[1], "run", sys.argv[2]], check=True, stdout=subprocess.DEVNULL)
    ts.append(time.perf_counter() - t)
print(statistics.median(ts))
PY
}
program() {  # place, expression
  local setup="rLocate 400, 300"
  [ "$1" = wall ] && setup="rectangle 380, 250, 420, 265, black, black
rLocate 400, 300"
  printf '%s\nfor i = 1 to %d\n  x = %s\nnext\n' "$setup" "$calls" "$2"
}
program open 0 > "$dir/base.bas"
base=$(time_of "$dir/base.bas")
printf "%-16s %12s %12s\n" "sensor" "open space" "beside wall"   # per call
for s in "rBumper()" "rFeel()" "rRange()" "rLook()" "rRange(90)" "rBeacon(RED)" "rSense()" "rCompass()" "rGPSX()"; do
  program open "$s" > "$dir/open.bas"
  program wall "$s" > "$dir/wall.bas"
  o=$(time_of "$dir/open.bas")
  w=$(time_of "$dir/wall.bas")
  python3 -c "import sys; b,o,w,n=map(float,sys.argv[1:5]); print(f'{sys.argv[5]:<16} {(o-b)/n*1e9:9.0f} ns {(w-b)/n*1e9:9.0f} ns')" "$base" "$o" "$w" "$calls" "$s"
done
