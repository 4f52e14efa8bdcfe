#!/usr/bin/env bash
# The interpreter benchmarks (bench/programs/*.bas, as bench/run.sh runs them) in rb's
# WebAssembly core under node (rb.run of build-web/site/rb.js) beside native rb, side by side
# in one run: median wall time of N runs each (default 3), and the ratio wasm / native. The
# wasm time is rb.run's alone (compile and run; the module is loaded once, before).
#   bench/web.sh [-n N] [path/to/rb]      (scripts/web.sh builds the site first)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
runs=3
if [ "${1:-}" = "-n" ]; then runs=$2; shift 2; fi
rb="${1:-$here/../build/cmd/rb}"
site="${RB_WEB_SITE:-$here/../build-web/site}"
[ -f "$site/rb.js" ] || { echo "web.sh: no site at $site (run scripts/web.sh)" >&2; exit 66; }
exec node - "$site" "$rb" "$runs" "$here/programs" <<'JS'
const [site, rbBin, runs, dir] = process.argv.slice(2);
const fs = require('fs'), path = require('path'), {execFileSync} = require('child_process');
const rb = require(path.resolve(site, 'rb.js'));
const median = (a) => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];
(async () => {
  let t = performance.now();
  await rb.ready();
  console.log(`wasm core loaded in ${(performance.now() - t).toFixed(0)} ms`);
  console.log('program         native s   wasm s   wasm/native');
  for (const f of fs.readdirSync(dir).filter((f) => f.endsWith('.bas')).sort()) {
    const file = path.join(dir, f), source = fs.readFileSync(file, 'utf8');
    const native = [], wasm = [];
    let nativeOut = '', wasmOut = '';
    for (let i = 0; i < Number(runs); i++) {
      t = performance.now();
      nativeOut = execFileSync(rbBin, ['run', '--seed', '1', file], {encoding: 'utf8', maxBuffer: 1 << 30});
      native.push((performance.now() - t) / 1000);
      t = performance.now();
      const r = await rb.run(source, {seed: 1, png: false});
      wasm.push((performance.now() - t) / 1000);
      if (r.error) throw new Error(`${f}: ${r.error}`);
      wasmOut = r.output;
    }
    if (nativeOut !== wasmOut) throw new Error(`${f}: the wasm output differs from rb run's`);
    const n = median(native), w = median(wasm);
    console.log(`${f.padEnd(15)} ${n.toFixed(3).padStart(8)} ${w.toFixed(3).padStart(8)}   ${(w / n).toFixed(2).padStart(6)}`);
  }
})().catch((e) => { console.error(e.message); process.exit(1); });
JS
