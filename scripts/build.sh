#!/usr/bin/env bash
# Configures and builds rb. Usage: scripts/build.sh [--sanitize] [--fuzz]
#   (default) Release build in build/
#   --sanitize  Debug build with AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/
#   --fuzz      clang build of the libFuzzer target in build-fuzz/
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-release}
case "$mode" in
  release|"") dir=build; flags=(-DCMAKE_BUILD_TYPE=Release -DRB_WERROR=ON) ;;
  --sanitize) dir=build-asan; flags=(-DCMAKE_BUILD_TYPE=Debug -DRB_SANITIZE=ON -DRB_WERROR=ON) ;;
  --fuzz) dir=build-fuzz; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DRB_FUZZ=ON -DRB_BUILD_TESTS=OFF
                                 -DCMAKE_CXX_COMPILER=clang++) ;;
  *) echo "usage: $0 [--sanitize|--fuzz]" >&2; exit 64 ;;
esac
cmake -S . -B "$dir" -G Ninja "${flags[@]}" >/dev/null
ninja -C "$dir"
