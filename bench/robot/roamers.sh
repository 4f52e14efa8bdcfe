#!/usr/bin/env bash
# The course labs' front-bumper-only random roamer (drive while (rBumper() & 4) = 0, then turn
# 120 to 180 degrees), 1,000,000 forward steps for each of N seeds (default 20), in an empty
# arena and among drawn rectangles and circles. Prints how many seeds ran without a crash.
# Usage: bench/robot/roamers.sh [path/to/rb] [-n SEEDS]
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rb="$here/../../build/cmd/rb"
seeds=20
while [ $# -gt 0 ]; do
  case "$1" in
    -n) seeds="$2"; shift 2 ;;
    *) rb="$1"; shift ;;
  esac
done
status=0
for arena in empty obstacles; do
  ok=0 crashed=0 failed=()
  start=$(date +%s%N)
  for seed in $(seq 1 "$seeds"); do
    if out=$("$rb" run --seed "$seed" "$here/roamer_$arena.bas" 2>&1) && [[ $out == "steps 1000000 "* ]]; then
      ok=$((ok + 1))
    else
      crashed=$((crashed + 1)); failed+=("$seed: $(echo "$out" | head -1)")
    fi
  done
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  printf '%-9s %d of %d seeds ran 1,000,000 steps without a crash (%d.%01d s)\n' "$arena" "$ok" "$seeds" $((ms / 1000)) $((ms % 1000 / 100))
  for f in "${failed[@]}"; do echo "  seed $f"; done
  [ "$crashed" -gt 0 ] && status=1
done
exit $status
