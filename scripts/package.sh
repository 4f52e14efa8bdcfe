#!/usr/bin/env bash
# Builds rb's packages from a Release build: a Debian package (rb_<version>_<arch>.deb, installs
# into /usr, depends only on libc) and a relocatable archive (rb-<version>-linux-<arch>.tar.gz:
# unpack it anywhere; bin/rb finds its library files in ../share/rb/lib).
# Usage: scripts/package.sh [OUTDIR]   (default: build/packages). Prints the two files' paths.
# It builds build/ as scripts/build.sh does (Release, tests off); on a built tree it takes seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/packages}"
scripts/setup.sh
scripts/build.sh                      # Release, no tests: what the packages hold
mkdir -p "$out"
out="$(cd "$out" && pwd)"
# cpack installs the build into a staging folder under -B and packs it from there.
cpack --config build/CPackConfig.cmake -B "$out" >"$out/cpack.log" 2>&1 || { cat "$out/cpack.log" >&2; exit 1; }
rm -rf "$out/_CPack_Packages"
version=$(sed -n 's/^project(rb VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
ls "$out"/rb_"$version"_*.deb "$out"/rb-"$version"-linux-*.tar.gz
