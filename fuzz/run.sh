#!/usr/bin/env bash
# Builds the libFuzzer target and fuzzes rb's lexer, parser, checker and compiler.
# Usage: fuzz/run.sh [seconds]   (default 60)
# Extra arguments after [seconds] are passed to libFuzzer (e.g. -jobs=4, -seed=1).
# Exit status: 0 when nothing was found, libFuzzer's non-zero status when it found a crash,
# leak, sanitizer error or timeout (the input is saved under build-fuzz/fuzz/artifacts/).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds=${1:-60}
[[ $# -gt 0 ]] && shift
if ! [[ "$seconds" =~ ^[0-9]+$ ]]; then
  echo "usage: $0 [seconds] [libFuzzer options...]" >&2
  exit 64
fi

"$root/scripts/build.sh" --fuzz

# A fresh corpus from the test programs, the examples and the saved reproducers (outside the
# source tree; the fuzzer adds the inputs it finds interesting to it, so it is thrown away
# afterwards).
corpus="$(mktemp -d "${TMPDIR:-/tmp}/rb-fuzz-corpus.XXXXXX")"
trap 'rm -rf "$corpus"' EXIT
n=0
while IFS= read -r -d '' f; do
  # Flatten the path into a unique file name: testdata/lang/include/main.bas -> testdata_lang_include_main.bas
  rel="${f#"$root"/}"
  cp "$f" "$corpus/${rel//\//_}"
  n=$((n + 1))
done < <(find "$root/testdata" "$root/examples" "$root/fuzz/repro" -name '*.bas' -type f -print0 2>/dev/null)
echo "run.sh: $n seed programs in $corpus"

artifacts="$root/build-fuzz/fuzz/artifacts"
mkdir -p "$artifacts"
log="$root/build-fuzz/fuzz/last-run.log"

status=0
"$root/build-fuzz/fuzz/rb_fuzz" \
  -max_total_time="$seconds" \
  -max_len=4096 \
  -timeout=10 \
  -dict="$root/fuzz/bas.dict" \
  -artifact_prefix="$artifacts/" \
  -print_final_stats=1 \
  "$@" \
  "$corpus" 2>&1 | tee "$log" || status=${PIPESTATUS[0]}

if [[ $status -ne 0 ]]; then
  echo >&2
  echo "run.sh: the fuzzer failed (exit status $status); log in $log" >&2
  grep -E "^(artifact_prefix|Test unit written to)" "$log" >&2 || true
  echo "run.sh: reproduce with: $root/build-fuzz/fuzz/rb_fuzz <crash file>" >&2
  echo "run.sh: minimize with:  $root/build-fuzz/fuzz/rb_fuzz -minimize_crash=1 -runs=10000 <crash file>" >&2
  exit "$status"
fi
echo "run.sh: no crash in ${seconds}s"
