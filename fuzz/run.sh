#!/usr/bin/env bash
# Builds the libFuzzer targets and runs them side by side, each for a bounded time:
#   rb_fuzz      the front end (lexer, parser, checker, compiler, diagnostics), inputs <= 4 KiB
#   rb_fuzz_run  whole runs (screen, robot, picture writers) under limits, inputs <= 64 KiB
#   rb_fuzz_grade assignment files, rosters and similarity (rb test's inputs), inputs <= 16 KiB
# Usage: fuzz/run.sh [seconds] [libFuzzer options...]   (seconds per target, default 60)
# RB_FUZZ_TARGETS="rb_fuzz_run" picks targets; RB_FUZZ_BUILD=fuzz-fast uses the UBSan-only build
# (build-fuzz-fast/, for long offline runs) instead of ASan + UBSan (build-fuzz/).
# Exit status: 0 when nothing was found, else libFuzzer's non-zero status (the input is saved
# under build-fuzz*/fuzz/artifacts/).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds=${1:-60}
[[ $# -gt 0 ]] && shift
if ! [[ "$seconds" =~ ^[0-9]+$ ]]; then
  echo "usage: $0 [seconds] [libFuzzer options...]" >&2
  exit 64
fi
targets=${RB_FUZZ_TARGETS:-"rb_fuzz rb_fuzz_run rb_fuzz_grade"}
build=${RB_FUZZ_BUILD:-fuzz}
case "$build" in
  fuzz|fuzz-fast) ;;
  *) echo "run.sh: RB_FUZZ_BUILD must be fuzz or fuzz-fast" >&2; exit 64 ;;
esac
bin="$root/build-$build/fuzz"

"$root/scripts/build.sh" --"$build"

# A fresh corpus from the test programs, the examples and the saved reproducers (outside the
# source tree; the fuzzer adds the inputs it finds interesting to it, so it is thrown away
# afterwards).
work="$(mktemp -d "${TMPDIR:-/tmp}/rb-fuzz.XXXXXX")"
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
seeds="$work/seeds"
mkdir -p "$seeds"
n=0
while IFS= read -r -d '' f; do
  # Flatten the path into a unique file name: testdata/lang/include/main.bas -> testdata_lang_include_main.bas
  rel="${f#"$root"/}"
  cp "$f" "$seeds/${rel//\//_}"
  n=$((n + 1))
done < <(find "$root/testdata" "$root/examples" "$root/fuzz/repro" -name '*.bas' -type f -print0 2>/dev/null)
echo "run.sh: $n seed programs"
# rb test's inputs: the assignment files and rosters of the tests, and the programs.
grade_seeds="$work/grade-seeds"
mkdir -p "$grade_seeds"
cp "$seeds"/* "$grade_seeds"/
while IFS= read -r -d '' f; do
  rel="${f#"$root"/}"
  cp "$f" "$grade_seeds/${rel//\//_}"
done < <(find "$root/testdata/grade" "$root/fuzz/repro" \( -name '*.toml' -o -name '*.csv' \) -type f -print0 2>/dev/null)

# The dictionary: fuzz/bas.dict (keywords, operators, awkward numbers) plus every built-in name
# from rb's own table, so the fuzzer reaches every command and function.
dict="$work/rb.dict"
cp "$root/fuzz/bas.dict" "$dict"
"$bin/rb_fuzz_words" >> "$dict"

artifacts="$bin/artifacts"
mkdir -p "$artifacts"
# The targets run side by side (each is one process; CI has two CPUs or more), each for the
# time given; their output goes to a log each, shown when they are done.
declare -A pids logs
for target in $targets; do
  case "$target" in
    rb_fuzz) maxlen=4096; rss=2048 ;;
    # Whole runs make strings of up to 64 MiB, which ASan's allocator keeps in its quarantine:
    # the process settles near 1.4 GiB.
    rb_fuzz_run) maxlen=65536; rss=3072 ;;
    rb_fuzz_grade) maxlen=16384; rss=2048 ;;
    *) echo "run.sh: unknown target $target" >&2; exit 64 ;;
  esac
  corpus="$work/corpus-$target"
  mkdir -p "$corpus"
  log="$bin/last-run-$target.log"
  logs[$target]="$log"
  "$bin/$target" \
    -max_total_time="$seconds" \
    -max_len="$maxlen" \
    -timeout=10 \
    -rss_limit_mb="$rss" \
    -dict="$dict" \
    -artifact_prefix="$artifacts/$target-" \
    -print_final_stats=1 \
    "$@" \
    "$corpus" "$([ "$target" = rb_fuzz_grade ] && echo "$grade_seeds" || echo "$seeds")" > "$log" 2>&1 &
  pids[$target]=$!
done
failed=0
for target in $targets; do
  status=0
  wait "${pids[$target]}" || status=$?
  log="${logs[$target]}"
  if [[ $status -ne 0 ]]; then
    tail -n 60 "$log" >&2
    echo >&2
    echo "run.sh: $target failed (exit status $status); log in $log" >&2
    grep -E "^(artifact_prefix|Test unit written to)" "$log" >&2 || true
    echo "run.sh: reproduce with: $bin/$target <crash file>" >&2
    failed=$status
    continue
  fi
  grep -E "^stat::" "$log" || true
  echo "run.sh: $target: no crash in ${seconds}s ($(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -Eo '[0-9]+$') executions)"
done
exit "$failed"
