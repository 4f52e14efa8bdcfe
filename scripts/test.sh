#!/usr/bin/env bash
# Sets up a fresh machine, builds rb and runs every test (unit tests, golden programs, the
# shared conformance programs, end-to-end checks, the web page in headless Chromium) through CTest.
# Usage: scripts/test.sh [--sanitize]   (--sanitize: the same suite under ASan + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --test
dir=build
if [ "${1:-}" = "--sanitize" ]; then
  dir=build-asan
  scripts/build.sh --sanitize
else
  scripts/build.sh --tests
  # The web page (WebAssembly) for its browser tests (testdata/web), which skip without it.
  scripts/web.sh
fi
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)"
