#!/usr/bin/env bash
# Builds rb's web page: the core (core/base, lang, screen, input, robot, machine) and the
# browser's host (web/host/) as WebAssembly with Debian's emscripten, FreeType built for wasm
# from Debian's own source package (so text has the same pixels as native rb), and the static
# page (web/) beside them. Writes the whole site to build-web/site/ (docs/web.md).
# Usage: scripts/web.sh          (installs emscripten with apt-get when it is missing)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=$root/build-web
mkdir -p "$out"

need=()
command -v emcc >/dev/null || need+=(emscripten)
command -v xz >/dev/null || need+=(xz-utils)
command -v patch >/dev/null || need+=(patch)
command -v npm >/dev/null || need+=(npm)
dpkg-query -W -f='${Status}' libeigen3-dev 2>/dev/null | grep -q "install ok installed" || need+=(libeigen3-dev)
for p in fonts-liberation2 python3-fonttools; do
  dpkg-query -W -f='${Status}' $p 2>/dev/null | grep -q "install ok installed" || need+=($p)
done
if [ ${#need[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" != 0 ] && SUDO="sudo"
  echo "web: installing ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${need[@]}"
fi
# Debian's emscripten runs its JavaScript tools on the system node with Debian's node modules.
export NODE_PATH=/usr/share/nodejs
start=$(date +%s)

# ---- FreeType: the version the native build links (libfreetype-dev), from Debian's source
# package with Debian's patches, fetched by apt-get with a private list of deb-src sources (the
# machine's apt configuration is left alone).
ftver=$(dpkg-query -W -f='${Version}' libfreetype-dev 2>/dev/null || true)
ftsrc=$out/freetype-src
if [ ! -f "$ftsrc/.ready" ]; then
  rm -rf "$out/apt" "$ftsrc"
  mkdir -p "$out/apt/lists/partial"
  # deb-src entries made from the machine's own apt sources (its configured mirrors), for the
  # suites of its own release: no host is named here.
  python3 - "$out/apt/sources.list" <<'PY'
import glob, re, sys
codename = ""
with open("/etc/os-release") as f:
    for line in f:
        if line.startswith("VERSION_CODENAME="):
            codename = line.split("=", 1)[1].strip().strip('"')
entries = []  # (uri, suite, components, signed_by)
def ours(suite):
    return codename and (suite == codename or suite.startswith(codename + "-"))
for path in ["/etc/apt/sources.list"] + sorted(glob.glob("/etc/apt/sources.list.d/*.list")):
    try:
        lines = open(path).read().splitlines()
    except OSError:
        continue
    for line in lines:
        m = re.match(r"\s*deb\s+(\[[^\]]*\]\s+)?(\S+)\s+(\S+)\s+(.+)", line.split("#", 1)[0])
        if m and ours(m.group(3)):
            opts = re.search(r"signed-by=(\S+?)[\s\]]", m.group(1) or "")
            entries.append((m.group(2), m.group(3), m.group(4).strip(), opts.group(1) if opts else ""))
for path in sorted(glob.glob("/etc/apt/sources.list.d/*.sources")):
    for stanza in re.split(r"\n\s*\n", open(path).read()):
        fields = {}
        for line in stanza.splitlines():
            if line.startswith("#") or ":" not in line:
                continue
            key, value = line.split(":", 1)
            fields[key.strip().lower()] = value.strip()
        if "deb" not in fields.get("types", "").split() or fields.get("enabled", "yes").lower() == "no":
            continue
        for uri in fields.get("uris", "").split():
            for suite in fields.get("suites", "").split():
                if ours(suite):
                    entries.append((uri, suite, fields.get("components", "main"), fields.get("signed-by", "")))
if not entries:
    sys.exit("web.sh: no apt source of this release (" + (codename or "unknown") + ") to fetch FreeType's source from")
with open(sys.argv[1], "w") as out:
    for uri, suite, comps, key in entries:
        out.write(f"deb-src {'[signed-by=' + key + '] ' if key else ''}{uri} {suite} {comps}\n")
PY
  apt_opts=(-q -o Dir::Etc::SourceList="$out/apt/sources.list" -o Dir::Etc::SourceParts=-
            -o Dir::State::Lists="$out/apt/lists" -o Debug::NoLocking=1 -o APT::Sandbox::User=root)
  apt-get "${apt_opts[@]}" update >/dev/null
  # The installed version when the mirror still has it, else the newest it has.
  (cd "$out/apt" && { apt-get "${apt_opts[@]}" --download-only source "freetype${ftver:+=$ftver}" >/dev/null 2>&1 ||
                      apt-get "${apt_opts[@]}" --download-only source freetype >/dev/null; })
  mkdir -p "$ftsrc"
  tar -xf "$out"/apt/freetype_*.orig.tar.xz -C "$ftsrc" --strip-components=1
  tar -xf "$out"/apt/freetype_*.debian.tar.xz -C "$ftsrc"
  while read -r p; do
    case "$p" in ''|'#'*) continue ;; esac
    # Patches of the demos and the documentation (other tarballs) are not needed here.
    grep -q '^+++ [^/]*/ft2\(docs\|demos\)/' "$ftsrc/debian/patches/$p" && continue
    patch -s --batch -d "$ftsrc" -p1 < "$ftsrc/debian/patches/$p"
  done < "$ftsrc/debian/patches/series"
  touch "$ftsrc/.ready"
fi
if [ ! -f "$out/freetype-install/lib/libfreetype.a" ]; then
  emcmake cmake -S "$ftsrc" -B "$out/freetype" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$out/freetype-install" -DBUILD_SHARED_LIBS=OFF \
    -DFT_DISABLE_ZLIB=ON -DFT_DISABLE_BZIP2=ON -DFT_DISABLE_PNG=ON -DFT_DISABLE_HARFBUZZ=ON \
    -DFT_DISABLE_BROTLI=ON >/dev/null
  ninja -C "$out/freetype" -j 2 install >/dev/null
fi

# ---- the fonts: the Liberation fonts native rb embeds, cut down to the Latin-1 characters rb
# draws (anything else is drawn as '?', which they keep), with their hinting, metrics and
# tables otherwise as they are: a tenth of the size, the same pixels (testdata/web/fonts_test.js
# compares every character of every face at many sizes with native rb render).
fonts=$out/fonts
if [ ! -f "$fonts/.ready" ]; then
  rm -rf "$fonts"
  mkdir -p "$fonts"
  for f in /usr/share/fonts/truetype/liberation2/Liberation{Mono,Sans,Serif}-{Regular,Bold,Italic,BoldItalic}.ttf; do
    /usr/bin/python3 -m fontTools.subset "$f" --unicodes=U+0000-00FF --notdef-outline --hinting \
      --name-IDs='*' --name-languages='*' --layout-features='' --no-prune-unicode-ranges \
      --output-file="$fonts/$(basename "$f")" 2>/dev/null
  done
  touch "$fonts/.ready"
fi

# ---- the core and the browser's host
emcmake cmake -S web -B "$out/core" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DRB_FREETYPE_DIR="$out/freetype-install" -DRB_FONT_DIRS="$fonts" -DRB_WERROR="${RB_WERROR:-OFF}" >/dev/null
ninja -C "$out/core" -j 2

# ---- the editor: CodeMirror 6 from npm (the versions web/package.json pins), bundled by esbuild
npmdir=$out/npm
if ! cmp -s web/package.json "$npmdir/package.json" || [ ! -d "$npmdir/node_modules" ]; then
  rm -rf "$npmdir"
  mkdir -p "$npmdir"
  cp web/package.json "$npmdir/"
  (cd "$npmdir" && npm install --no-audit --no-fund --loglevel=error >/dev/null)
fi

# ---- the site
site=$out/site
rm -rf "$site"
mkdir -p "$site"
NODE_PATH="$npmdir/node_modules" "$npmdir/node_modules/.bin/esbuild" web/editor.mjs --bundle --minify \
  --format=iife --log-level=warning --outfile="$site/editor.js"
cp web/index.html web/style.css web/app.js web/rb.js web/rbworker.js web/rblive.js "$site/"
cp "$out/core/rbcore.js" "$out/core/rbcore.wasm" "$out/core/rbcore_fast.js" "$out/core/rbcore_fast.wasm" "$site/"
node web/make_examples.js "$root" > "$site/examples.js"
node web/make_sw.js "$site"  # last: it lists and hashes the site's files
echo "web: site in build-web/site ($(du -sh "$site" | cut -f1); built in $(( $(date +%s) - start )) s)"
