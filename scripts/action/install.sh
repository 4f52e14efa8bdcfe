#!/usr/bin/env bash
# Installs rb for rb's GitHub Action (action.yml). Called from the action's steps:
#   install.sh version            the version of rb in this source tree, and a cache key for a
#                                 build of it (version + a hash of the sources) -> GITHUB_OUTPUT
#   install.sh release VERSION    installs the Debian package of a GitHub release of rb, when the
#                                 release has one (rb_VERSION_ARCH.deb): dpkg -i, with sudo where
#                                 not root. Sets installed=true|false; never fails for a release
#                                 that has no package
#   install.sh build PREFIX       builds rb from this source tree (scripts/setup.sh, Release) and
#                                 installs it into PREFIX (the folder actions/cache keeps)
#   install.sh path PREFIX        puts PREFIX/bin on the PATH of the steps after (GITHUB_PATH)
#   install.sh python             installs python3 (Debian's) when the machine has none, for
#                                 rb_action.py (a debian container has none; GitHub's runners do)
# Environment: GITHUB_OUTPUT, GITHUB_PATH (files, as on a runner); RB_RELEASE_BASE: where
# releases are (default https://github.com/$RB_REPOSITORY/releases/download, the tests give a
# file:// folder); RB_REPOSITORY: owner/name of rb's repository (the action passes its own).
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
out() { if [ -n "${GITHUB_OUTPUT:-}" ]; then echo "$1=$2" >>"$GITHUB_OUTPUT"; fi; echo "$1=$2"; }
as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

# Downloads URL to FILE with whatever the machine has (a Debian container may have neither curl
# nor wget; python3 then, and curl is installed as the last resort).
download() {
  local url=$1 file=$2
  case "$url" in
    file://*) cp "${url#file://}" "$file" 2>/dev/null; return ;;
  esac
  if command -v curl >/dev/null; then curl -fsSL --retry 2 -o "$file" "$url"
  elif command -v wget >/dev/null; then wget -q -O "$file" "$url"
  elif command -v python3 >/dev/null; then
    python3 -c 'import sys, urllib.request; urllib.request.urlretrieve(sys.argv[1], sys.argv[2])' "$url" "$file" 2>/dev/null
  else
    as_root apt-get update -q >/dev/null && as_root apt-get install -y -q --no-install-recommends curl ca-certificates >/dev/null
    curl -fsSL --retry 2 -o "$file" "$url"
  fi
}

case "${1:-}" in
  version)
    version=$(sed -n 's/^project(rb VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
    # What a build depends on: the sources and the build files (not docs or tests).
    hash=$(cd "$src" && find CMakeLists.txt core render drivers grade lsp cmd man lib scripts/setup.sh \
             scripts/build.sh -type f 2>/dev/null | LC_ALL=C sort | xargs sha256sum | sha256sum | cut -c1-16)
    out version "$version"
    out key "rb-$(uname -s)-$(uname -m)-$version-$hash"
    ;;
  release)
    version=${2:?usage: install.sh release VERSION}
    arch=$(dpkg --print-architecture 2>/dev/null || true)
    if [ -z "$arch" ]; then echo "install.sh: no dpkg here: rb is built from source"; out installed false; exit 0; fi
    base=${RB_RELEASE_BASE:-https://github.com/${RB_REPOSITORY:-}/releases/download}
    deb="rb_${version}_${arch}.deb"
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    for tag in "v$version" "$version"; do
      if download "$base/$tag/$deb" "$tmp/$deb" && [ -s "$tmp/$deb" ]; then
        echo "install.sh: installing $deb of release $tag"
        as_root dpkg -i "$tmp/$deb"
        out installed true
        out rb /usr/bin/rb
        exit 0
      fi
    done
    own=$(sed -n 's/^project(rb VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
    if [ "$version" != "$own" ]; then
      echo "install.sh: release $version has no $deb, and the action's own sources are rb $own:" \
           "use the action at that version (uses: OWNER/rb@v$version) or leave out version" >&2
      exit 1
    fi
    echo "install.sh: release $version has no $deb: rb is built from the action's sources"
    out installed false
    ;;
  build)
    prefix=${2:?usage: install.sh build PREFIX}
    "$src/scripts/setup.sh"
    cmake -S "$src" -B "$src/build-action" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
    ninja -C "$src/build-action" -j "$(nproc)" rb rb_man_pages
    cmake --install "$src/build-action" --prefix "$prefix" >/dev/null
    out rb "$prefix/bin/rb"
    ;;
  path)
    prefix=${2:?usage: install.sh path PREFIX}
    if [ -n "${GITHUB_PATH:-}" ]; then echo "$prefix/bin" >>"$GITHUB_PATH"; fi
    out rb "$prefix/bin/rb"
    ;;
  python)
    if command -v python3 >/dev/null; then echo "install.sh: $(python3 --version)"; exit 0; fi
    export DEBIAN_FRONTEND=noninteractive
    as_root apt-get update -q >/dev/null
    as_root apt-get install -y -q --no-install-recommends python3 >/dev/null
    ;;
  *)
    echo "usage: install.sh version | release VERSION | build PREFIX | path PREFIX | python" >&2
    exit 64
    ;;
esac
