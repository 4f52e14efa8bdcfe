#!/usr/bin/env bash
# Usage: package_test.sh BUILD_DIR SOURCE_DIR
# Packs BUILD_DIR with cpack, installs the .deb with dpkg -i, runs the seed's square from
# /usr/bin/rb, removes it with dpkg -r and checks that nothing it installed is left; then unpacks
# the .tar.gz into a folder of its own and runs rb from there. Exit 77 (skipped) when this
# cannot be done without touching someone's installation: not root, no dpkg, or an rb already
# installed.
set -uo pipefail
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
skip() { echo "SKIPPED: $*"; exit 77; }
[ "$(id -u)" = 0 ] || skip "dpkg -i needs root (CI runs as root; run this test as root to check the package)"
command -v dpkg >/dev/null && command -v dpkg-deb >/dev/null || skip "no dpkg on this machine"
if dpkg-query -W -f='${Status}' rb 2>/dev/null | grep -q "install ok installed"; then
  skip "a package named rb is already installed; this test does not remove someone's rb"
fi
[ -e /usr/bin/rb ] && skip "/usr/bin/rb already exists; this test does not overwrite it"

fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
ok() { echo "ok: $*"; }
tmp=$(mktemp -d)
installed=0
cleanup() {
  [ "$installed" = 1 ] && dpkg -r rb >/dev/null 2>&1
  rm -rf "$tmp"
}
trap cleanup EXIT

# dpkg takes a lock; another apt or dpkg at work on the machine holds it for a while.
dpkg_retry() {
  local out
  for _ in $(seq 60); do
    if out=$("$@" 2>&1); then echo "$out"; return 0; fi
    grep -qi "lock" <<<"$out" || { echo "$out"; return 1; }
    sleep 2
  done
  echo "$out"; return 1
}

version=$(sed -n 's/^project(rb VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
arch=$(dpkg --print-architecture)
start=$(date +%s%N)
if ! cpack --config "$build/CPackConfig.cmake" -B "$tmp/out" >"$tmp/cpack.log" 2>&1; then
  cat "$tmp/cpack.log"; echo "FAIL: cpack"; exit 1
fi
echo "cpack: $(( ($(date +%s%N) - start) / 1000000 )) ms"
deb="$tmp/out/rb_${version}_${arch}.deb"
tgz=$(ls "$tmp"/out/rb-"$version"-linux-*.tar.gz 2>/dev/null | head -1)
[ -f "$deb" ] && ok "cpack wrote $(basename "$deb")" || { ls "$tmp/out"; fail "no $(basename "$deb")"; exit 1; }
[ -n "$tgz" ] && ok "cpack wrote $(basename "$tgz")" || fail "no rb-$version-linux-*.tar.gz"

# The package depends on libc alone (rb links its other libraries statically).
depends=$(dpkg-deb -f "$deb" Depends)
if [[ "$depends" =~ ^libc6\ \(\>=\ [0-9.]+\)$ ]]; then ok "Depends: $depends"; else fail "Depends: '$depends' (expected libc6 alone)"; fi
[ "$(dpkg-deb -f "$deb" Package)" = rb ] && [ "$(dpkg-deb -f "$deb" Version)" = "$version" ] \
  && [ "$(dpkg-deb -f "$deb" Architecture)" = "$arch" ] && ok "Package rb, Version $version, Architecture $arch" \
  || fail "control fields: $(dpkg-deb -I "$deb")"

# Installed the way rb's GitHub Action installs a release's package (scripts/action/install.sh
# release: the .deb attached to release vVERSION, installed with dpkg -i), from a folder standing
# for the releases: one dpkg -i and one dpkg -r (each about 5 s, man-db's index most of it).
mkdir -p "$tmp/releases/v$version"
cp "$deb" "$tmp/releases/v$version/"
: >"$tmp/gh_output"
t0=$(date +%s%N)
if ! out=$(GITHUB_OUTPUT="$tmp/gh_output" RB_RELEASE_BASE="file://$tmp/releases" \
           dpkg_retry bash "$src/scripts/action/install.sh" release "$version"); then
  echo "$out"; fail "install.sh release $version (dpkg -i)"; exit 1
fi
installed=1
grep -qx "installed=true" "$tmp/gh_output" && ok "install.sh release $version: dpkg -i, installed=true" \
  || fail "install.sh release $version wrote $(cat "$tmp/gh_output")"
# What it installed, files and links (the folders it made are checked by name below).
dpkg -L rb | while read -r p; do [ -d "$p" ] && [ ! -L "$p" ] || echo "$p"; done >"$tmp/files"
ok "dpkg -i installed $(wc -l <"$tmp/files") files in $(( ($(date +%s%N) - t0) / 1000000 )) ms"

# Only libc's libraries are loaded.
libs=$(ldd /usr/bin/rb | awk '{print $1}' | sed 's/\.so.*//; s,.*/,,' | sort -u | tr '\n' ' ')
extra=$(tr ' ' '\n' <<<"$libs" | grep -Ev '^(linux-vdso|ld-linux-x86-64|ld-linux-aarch64|ld-linux|libc|libm|)$' || true)
[ -z "$extra" ] && ok "ldd /usr/bin/rb: $libs" || fail "ldd /usr/bin/rb loads more than libc: $extra"

for f in /usr/share/rb/lib/RB-9.bas /usr/share/man/man1/rb.1.gz /usr/share/man/man1/rb-test.1.gz; do
  [ -f "$f" ] && ok "$f" || fail "$f is not installed"
done
if command -v man >/dev/null; then
  where=$(man -w rb-test 2>&1)
  [ "$where" = /usr/share/man/man1/rb-test.1.gz ] && ok "man -w rb-test: $where" || fail "man -w rb-test: $where"
  (cd / && MANWIDTH=80 man -P cat rb-test 2>/dev/null | grep -q "rb test") && ok "man rb-test shows the page" \
    || fail "man rb-test does not show the page"
fi

# The seed's square (Figure 1.7) and Figure 1.13 (which includes RB-9.bas) from a folder of
# their own: the installed rb finds RB-9.bas in /usr/share/rb/lib, never in the sources.
mkdir "$tmp/work"
cp "$src/examples/fig_1_7.bas" "$src/examples/fig_1_13_sim.bas" "$tmp/work/"
for name in fig_1_7 fig_1_13_sim; do
  got=$(cd "$tmp/work" && RB_LIB_PATH= /usr/bin/rb trace "$name.bas" 2>&1)
  if [ "$got" = "$(cat "$src/testdata/seed/$name.trace")" ]; then ok "/usr/bin/rb trace $name.bas: the seed's trace"
  else fail "/usr/bin/rb trace $name.bas differs from testdata/seed/$name.trace:"; echo "$got" | head -5; fi
done
(cd "$tmp/work" && /usr/bin/rb render fig_1_7.bas -o square.png >/dev/null 2>&1) && [ -s "$tmp/work/square.png" ] \
  && ok "/usr/bin/rb render fig_1_7.bas -o square.png" || fail "/usr/bin/rb render fig_1_7.bas"

t0=$(date +%s%N)
if ! out=$(dpkg_retry dpkg -r rb); then echo "$out"; fail "dpkg -r rb"; else installed=0; fi
echo "dpkg -r: $(( ($(date +%s%N) - t0) / 1000000 )) ms"
left=0
while read -r path; do
  [ -e "$path" ] || [ -L "$path" ] || continue
  echo "left behind: $path"; left=$((left + 1))
done <"$tmp/files"
for d in /usr/share/rb /usr/share/doc/rb; do [ -e "$d" ] && { echo "left behind: $d"; left=$((left + 1)); }; done
dpkg-query -W -f='${Status}' rb 2>/dev/null | grep -q "installed" && fail "dpkg still lists rb as installed"
[ "$left" = 0 ] && ok "dpkg -r rb left no file behind" || fail "dpkg -r rb left $left paths"

# The archive: unpacked anywhere, bin/rb finds ../share/rb/lib; man finds ../share/man from PATH.
if [ -n "$tgz" ]; then
  mkdir "$tmp/somewhere"
  tar -xzf "$tgz" -C "$tmp/somewhere"
  top=$(ls "$tmp/somewhere")
  rb="$tmp/somewhere/$top/bin/rb"
  got=$(cd "$tmp/work" && RB_LIB_PATH= "$rb" trace fig_1_13_sim.bas 2>&1)
  [ "$got" = "$(cat "$src/testdata/seed/fig_1_13_sim.trace")" ] && ok "$top/bin/rb trace fig_1_13_sim.bas (RB-9.bas from $top/share/rb/lib)" \
    || { fail "unpacked rb trace fig_1_13_sim.bas:"; echo "$got" | head -5; }
  for f in share/rb/lib/RB-9.bas share/man/man1/rb.1.gz; do
    [ -f "$tmp/somewhere/$top/$f" ] && ok "$top/$f" || fail "$top/$f is not in the archive"
  done
  if command -v man >/dev/null; then
    where=$(cd / && env -u MANPATH PATH="$tmp/somewhere/$top/bin:/usr/bin:/bin" man -w rb-test 2>&1)
    [ "$where" = "$tmp/somewhere/$top/share/man/man1/rb-test.1.gz" ] && ok "man -w rb-test with $top/bin on PATH: the archive's page" \
      || fail "man -w rb-test with the archive's bin on PATH: $where"
  fi
fi

echo "$fails failed"
[ "$fails" = 0 ]
