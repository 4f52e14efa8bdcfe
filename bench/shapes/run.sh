#!/usr/bin/env bash
# 100,000 mixed shapes (circles, ellipses, rectangles, lines; half of them filled) drawn by rb
# (shapes.bas) and by Pillow (shapes_pil.py, Debian python3-pil; shown as n/a when Python
# cannot import PIL). Checks each one's checksum of the picture, prints medians of RUNS runs
# (startup included), the ratio to Pillow and the peak resident memory.
# Usage: bench/shapes/run.sh [path/to/rb] [-n RUNS]   (default 5)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=5
source "$here/../args.sh" "$@"
python3 - "$rb" "$here" "$runs" <<'PY'
import subprocess, sys
rb, here, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
sys.path.insert(0, here + "/..")
from measure import alternate, machine, ms, mib
jobs = {"rb": ([rb, "run", here + "/shapes.bas"], "121080")}
have_pil = subprocess.run([sys.executable, "-c", "import PIL"], capture_output=True).returncode == 0
if have_pil:
    # Pillow rasterizes a little differently: its own checksum.
    jobs["Pillow"] = ([sys.executable, here + "/shapes_pil.py"], None)
print(f"machine: {machine()}")
got = alternate(jobs, runs)
print(f"{'100k mixed shapes':20} {'wall':>9} {'cpu':>9} {'peak RSS':>10}")
for name, g in got.items():
    print(f"{name:20} {ms(g['wall']):>9} {ms(g['cpu']):>9} {mib(g['rss']):>10}")
if have_pil:
    print(f"rb / Pillow: {got['rb']['wall'] / got['Pillow']['wall']:.2f}x (wall)")
else:
    print("Pillow               n/a (python3 cannot import PIL: apt-get install python3-pil)")
PY
