#!/usr/bin/env bash
# What confining a graded program costs (docs/confinement.md): `rb test` grades N one-line
# programs (`print 1`, a no-error check) with two rb executables side by side, typically one
# built before the scratch folders and the kernel's rules and one after, and prints the median
# wall and processor time (user + system, rb test and every child) of each, and the difference
# per program: the set-up a program's run costs on top of running it.
# Usage: bench/grade/setup.sh OLD_RB NEW_RB [runs] [programs]
set -euo pipefail
old="$1"
new="$2"
runs="${3:-5}"
count="${4:-1000}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
mkdir "$dir/class"
for i in $(seq 1 "$count"); do printf 'print %d\n' "$i" > "$dir/class/p$i.bas"; done
printf '[[check]]\nkind = "no-error"\n' > "$dir/a.toml"
python3 - "$old" "$new" "$dir" "$runs" "$count" <<'PY'
import resource, statistics, subprocess, sys, time
old, new, d, runs, count = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])


def cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


res = {old: ([], []), new: ([], [])}
for _ in range(runs):
    for rb in (old, new):  # interleaved, so that a busy moment costs both alike
        t, c = time.perf_counter(), cpu()
        p = subprocess.run([rb, "test", "-q", "-j", "2", "-a", f"{d}/a.toml", f"{d}/class"],
                           capture_output=True, text=True)
        if p.returncode != 0:
            sys.exit(f"{rb} test failed:\n{p.stdout[-2000:]}\n{p.stderr[-2000:]}")
        res[rb][0].append(time.perf_counter() - t)
        res[rb][1].append(cpu() - c)
med = {rb: (statistics.median(w), statistics.median(c)) for rb, (w, c) in res.items()}
for label, rb in (("before", old), ("after", new)):
    w, c = med[rb]
    print(f"{label:6}  {rb}: wall {w:.2f} s, processor {c:.2f} s for {count} programs "
          f"({w / count * 1000:.2f} ms and {c / count * 1000:.2f} ms per program)")
dw = (med[new][0] - med[old][0]) / count * 1000
dc = (med[new][1] - med[old][1]) / count * 1000
print(f"set-up per program: {dw:+.2f} ms wall (-j 2), {dc:+.2f} ms processor time (median of {runs} runs)")
PY
