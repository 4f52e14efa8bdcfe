#!/usr/bin/env bash
# What a colour check costs (issue 36): `rb test` grades one program against `avoid colour =
# "black"` and against `avoid rect = [...]` (a region around the same black: a rectangle check
# costs the run nothing, the path is recorded anyway), and prints the median processor time
# (user + system, rb test and its child) of each and their ratio. Two programs:
#   - circles: 200,000 moves of 1 px, each followed by a turn of 1 degree (a circle driven over
#     and over), a black block far from it;
#   - maze: bench/grade/maze.bas, a robot following the right-hand wall of a maze of black walls
#     with its sensors, 40,000 rounds (about 39,000 moves), close to the walls all the way.
# Given two rb executables (before and after), both side by side, runs taking turns.
# Usage: bench/grade/colour.sh [OLD_RB] NEW_RB [-n RUNS]   (default: build/cmd/rb, 5 runs)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=5
rbs=()
while [ $# -gt 0 ]; do
  case "$1" in
    -n) runs="$2"; shift 2 ;;
    *) rbs+=("$1"); shift ;;
  esac
done
[ ${#rbs[@]} -gt 0 ] || rbs=("$here/../../build/cmd/rb")
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
mkdir "$dir/circles" "$dir/maze"
cat > "$dir/circles/circles.bas" <<'EOF'
rectangle 100, 60, 200, 90, black, black
rLocate 400, 300
for i = 1 to 200000
  rForward 1
  rTurn 1
next
EOF
cp "$here/maze.bas" "$dir/maze/maze.bas"
for program in circles maze; do
  rect="[100, 60, 200, 90]"
  [ "$program" = maze ] && rect="[447, 150, 453, 350]"
  for check in colour rect; do
    what='colour = "black"'
    [ "$check" = rect ] && what="rect = $rect"
    printf '[run]\nmax-steps = 10000000\ntimeout = 120\n[[check]]\nkind = "avoid"\n%s\n' "$what" \
      > "$dir/$program-$check.toml"
  done
done
python3 - "$dir" "$runs" "$here/.." "${rbs[@]}" <<'PY'
import json, sys
d, runs, bench = sys.argv[1], int(sys.argv[2]), sys.argv[3]
rbs = sys.argv[4:]
sys.path.insert(0, bench)
from measure import alternate, machine, run_once

print(f"machine: {machine()}")
jobs, verdicts = {}, {}
for rb in rbs:
    for program in ("circles", "maze"):
        for check in ("colour", "rect"):
            cmd = [rb, "test", "-q", "-j", "1", "--format", "json", "-a", f"{d}/{program}-{check}.toml",
                   f"{d}/{program}"]
            jobs[(rb, program, check)] = (cmd, None)
got = alternate(jobs, runs)
# Every run must have been graded alike, and to the end (not stopped by a limit).
for rb in rbs:
    for program in ("circles", "maze"):
        _, _, _, text = run_once(jobs[(rb, program, "colour")][0])
        p = json.loads(text)["programs"][0]
        if p["result"] != "pass":
            sys.exit(f"{rb}: {program} against the colour check: {p['result']}: {p['reason']}")
print(f"median processor time (user + system, rb test and its child) of {runs} runs, -j 1:")
head = "| program | " + " | ".join(
    f"{label}: `colour` | {label}: `rect` | {label}: colour / rect" for label in
    (["before", "after"] if len(rbs) == 2 else ["rb"])) + " |"
print(head)
print("|---|" + "---:|" * (3 * len(rbs)))
for program in ("circles", "maze"):
    cells = []
    for rb in rbs:
        c, r = got[(rb, program, "colour")]["cpu"], got[(rb, program, "rect")]["cpu"]
        cells += [f"{c:.3f} s", f"{r:.3f} s", f"{c / r:.2f}x"]
    print(f"| {program} | " + " | ".join(cells) + " |")
for i, rb in enumerate(rbs):
    print(f"{['before', 'after'][i] if len(rbs) == 2 else 'rb'}: {rb}")
PY
