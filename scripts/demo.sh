#!/usr/bin/env bash
# Sets up a fresh machine, builds rb and runs a demo program of the seed document: the robot
# draws a square (Figure 1.7). Shows its trace and the final screen, and writes it as PNG/SVG.
# Usage: scripts/demo.sh [examples/PROGRAM.bas]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh >/dev/null
scripts/build.sh >/dev/null
program=${1:-examples/fig_1_7.bas}
rb=build/cmd/rb
echo "\$ rb run $program"
"$rb" run "$program"
echo
echo "\$ rb trace $program"
"$rb" trace "$program"
echo
echo "\$ rb render $program --ascii --cols 80 --rows 30"
"$rb" render "$program" --ascii --cols 80 --rows 30
"$rb" render "$program" -o build/demo.png
"$rb" render "$program" -o build/demo.svg
echo "The final screen is in build/demo.png and build/demo.svg."
