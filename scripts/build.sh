#!/usr/bin/env bash
# Configures and builds rb. Usage: scripts/build.sh [--tests] [--sanitize | --fuzz | --fuzz-fast]
#   (default)   Release build of rb in build/
#   --tests     also the unit and golden tests (CMake's BUILD_TESTING)
#   --sanitize  AddressSanitizer + UndefinedBehaviorSanitizer build (-O1, line tables), with the tests,
#               in build-asan/
#   --fuzz      clang build of the libFuzzer targets (only those) in build-fuzz/, with ASan + UBSan
#   --fuzz-fast the same with UBSan only, in build-fuzz-fast/: for long offline runs
# Warnings are errors only when RB_WERROR=ON is in the environment (CI sets it): a user's build
# never fails on a warning a newer compiler invents.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build
targets=()   # all
flags=(-DCMAKE_BUILD_TYPE=Release)
tests=OFF
for arg in "$@"; do
  case "$arg" in
    --tests) tests=ON ;;
    --sanitize) dir=build-asan; tests=ON; flags=(-DCMAKE_BUILD_TYPE=Debug -DRB_SANITIZE=ON) ;;
    --fuzz) dir=build-fuzz; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DRB_FUZZ=ON
                                   -DCMAKE_CXX_COMPILER=clang++)
            targets=(rb_fuzz rb_fuzz_run rb_fuzz_grade rb_fuzz_words) ;;
    --fuzz-fast) dir=build-fuzz-fast; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DRB_FUZZ=ON
                                   -DRB_FUZZ_SANITIZERS=undefined -DCMAKE_CXX_COMPILER=clang++)
            targets=(rb_fuzz rb_fuzz_run rb_fuzz_grade rb_fuzz_words) ;;
    *) echo "usage: $0 [--tests] [--sanitize|--fuzz|--fuzz-fast]" >&2; exit 64 ;;
  esac
done
flags+=(-DBUILD_TESTING="$tests" -DRB_BUILD_TESTS="$tests" -DRB_WERROR="${RB_WERROR:-OFF}")
cmake -S . -B "$dir" -G Ninja "${flags[@]}" >/dev/null
ninja -C "$dir" "${targets[@]}"
