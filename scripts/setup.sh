#!/usr/bin/env bash
# Installs rb's dependencies from Debian packages. Idempotent: packages already present are left
# alone. Run as root or with sudo available.
#   scripts/setup.sh           what building and running rb needs (the demo calls this)
#   scripts/setup.sh --test-build  also what building the tests needs (Catch2)
#   scripts/setup.sh --test    also the test tools (scripts/test.sh and .ci/run call this), and
#                              the npm packages testdata/action/classroom-reporter needs (npm ci)
#   scripts/setup.sh --bench   also the benchmark peers (bench/*.sh call this)
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libcli11-dev libeigen3-dev libpng-dev libncurses-dev
  libfreetype-dev fonts-liberation2   # text: FreeType rasterizes the Liberation fonts compiled into rb
  libtomlplusplus-dev nlohmann-json3-dev   # rb test's assignment files (TOML); JSON everywhere
  libserialport-dev     # rb ports: the serial ports and what is known of each
  libsixel-dev          # rb run --tui --cells pixels: the screen as a sixel image
  libgif-dev            # rb render --animate OUT.gif: giflib writes the animated GIF
  libre2-dev            # rb test: output patterns matched in linear time (RE2)
  libseccomp-dev        # the seccomp filter every run of a program is under (docs/confinement.md)
  zlib1g-dev libbrotli-dev   # static archives libpng and FreeType need (RB_STATIC_LIBS)
  dpkg-dev file         # cpack's Debian package (scripts/package.sh): dpkg-shlibdeps finds what rb links
)
# What building the tests needs (scripts/test.sh installs it first, then builds while the rest
# of the test tools install).
test_build_packages=(
  catch2                # unit tests
)
test_packages=(
  libxml2-utils         # xmllint: the JUnit report is validated against its schema in the tests
  cmark-gfm             # GitHub's Markdown renderer: the action's job summary rendered as GitHub does (testdata/action)
  clang libclang-rt-14-dev   # libFuzzer target and sanitizer runtime
  tmux                  # end-to-end tests of the terminal view
  python3               # golden-test helpers and PNG checks
  neovim                # the Neovim snippet tested in a real (headless) Neovim, Debian 12's 0.7.2
  chromium              # the replays of rb render --animate played in a real browser (headless, driven
                        # over the DevTools protocol on a pipe by testdata/render/replay_browser.py),
                        # rb test --html's class report page (testdata/grade/html_browser.py) and
                        # the web page (testdata/web)
  emscripten xz-utils patch python3-fonttools   # scripts/web.sh: the core as WebAssembly for the web page's tests (testdata/web)
)
bench_packages=(
  lua5.4 yabasic brandy hyperfine   # benchmark peers
  python3-tk xvfb       # Python's turtle, the pen benchmark's peer (bench/robot/run.sh)
  python3-pil           # Pillow, the shapes benchmark's peer (bench/shapes/run.sh)
)
with_tools=0
for arg in "$@"; do
  case "$arg" in
    --test-build) packages+=("${test_build_packages[@]}") ;;
    --test) packages+=("${test_build_packages[@]}" "${test_packages[@]}"); with_tools=1 ;;
    --bench) packages+=("${test_build_packages[@]}" "${test_packages[@]}" "${bench_packages[@]}"); with_tools=1 ;;
    *) echo "usage: scripts/setup.sh [--test-build] [--test] [--bench]" >&2; exit 64 ;;
  esac
done

# npm packages the tests need (testdata/action/classroom-reporter: GitHub Classroom's reporter
# runs under node on rb's results). Node.js and npm come from Debian where the machine has none.
npm_folders=()
if [[ " $* " == *" --test "* || " $* " == *" --bench "* ]]; then
  command -v node >/dev/null || packages+=(nodejs)
  command -v npm >/dev/null || packages+=(npm)
  npm_folders+=(testdata/action/classroom-reporter)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
else
  SUDO=""
  if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Test tools from npm, pinned by tools/package-lock.json: Microsoft's SARIF Multitool, which
# validates rb's SARIF against the schema and GitHub code scanning's rules, and axe-core, whose
# WCAG 2.1 rules testdata/a11y runs on the pages in headless Chromium. npm runs no install
# scripts here, so the tool's binary is made executable by hand.
if [ "$with_tools" = 1 ]; then
  tools="$(cd "$(dirname "$0")/../tools" && pwd)"
  if [ ! -x "$tools/node_modules/@microsoft/sarif-multitool-linux/Sarif.Multitool" ] ||
     [ ! -f "$tools/node_modules/axe-core/axe.min.js" ] ||
     [ "$tools/package-lock.json" -nt "$tools/node_modules/.package-lock.json" ]; then
    echo "setup: npm ci in tools/"
    (cd "$tools" && npm ci --no-audit --no-fund --ignore-scripts)
    chmod u+x "$tools/node_modules/@microsoft/sarif-multitool-linux/Sarif.Multitool"
  else
    echo "setup: npm tools present"
  fi
fi
# npm ci installs exactly the lock file's versions; skipped when they are already there.
cd "$(dirname "$0")/.."  # (tools/ above was found from the script's own folder too)
for dir in "${npm_folders[@]}"; do
  if ! (cd "$dir" && node -e 'const l = require("./package-lock.json");
      for (const [k, v] of Object.entries(l.packages))
        if (k && require("./" + k + "/package.json").version !== v.version) process.exit(1);' 2>/dev/null); then
    echo "setup: npm ci in $dir"
    (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error)
  fi
done
