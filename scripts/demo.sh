#!/usr/bin/env bash
# Sets up a fresh machine, builds rb and runs a demo program of the seed document.
# Usage: scripts/demo.sh [examples/PROGRAM.bas]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh >/dev/null
scripts/build.sh >/dev/null
program=${1:-examples/fig_1_3.bas}
echo "\$ rb run $program"
build/cmd/rb run "$program"
