#!/usr/bin/env bash
# Sets up a fresh machine, builds rb and runs every test (unit tests, golden programs, the
# shared conformance programs, end-to-end checks, the web page in headless Chromium) through CTest.
# Usage: scripts/test.sh [--sanitize]   (--sanitize: the same suite under ASan + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build
if [ "${1:-}" = "--sanitize" ]; then
  scripts/setup.sh --test
  dir=build-asan
  scripts/build.sh --sanitize
else
  # What building needs first; then rb builds while the rest of the test tools (Chromium,
  # emscripten, clang...) download and install.
  scripts/setup.sh --test-build
  scripts/build.sh --tests &
  build=$!
  scripts/setup.sh --test
  wait "$build"
  # Configured again now that the test tools are there (Neovim, ...): the tests that use them
  # are registered with them; nothing is rebuilt.
  scripts/build.sh --tests
  # The web page (WebAssembly) for its browser tests (testdata/web), which skip without it.
  scripts/web.sh
fi
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Twice as many tests as processors at once: many wait on a browser, a terminal or a child.
ctest --test-dir "$dir" --output-on-failure -j "$(( $(nproc) * 2 ))"
