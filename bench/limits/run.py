#!/usr/bin/env python3
"""Limits under attack: each reproducer of a runaway program or a hostile input, the limit it
meets, and where and when rb stopped it.

    bench/limits/run.py [path/to/rb]      (default: build/cmd/rb)

Every case runs once in a fresh folder; the table gives the wall time, the exit status, the
peak memory (maximum resident set size, from GNU time) and the first line
rb wrote to standard error. A time-limited case passes when it stopped within 10% and 0.2 s of
its limit with exit 70 and a file:line:col; the other cases say what they expect. The script
exits 1 when a case misses its target.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def sh_quote(s):
    return "'" + s.replace("'", "'\\''") + "'"


# name, program text (or None), files to write, the command after `rb`, the limit in seconds (or
# None), the expected exit status, text standard error must hold, a bound on the wall time for
# cases without a time limit.
CASES = [
    ("dim in a loop", "while 1\n  dim a[1000000]\nwend\n", {}, ["run", "--timeout", "2", "p.bas"], 2, 70, "p.bas:2:7:", None),
    ("four 915 MiB arrays", "dim a[60000000]\ndim b[60000000]\ndim c[60000000]\ndim d[60000000]\n", {},
     ["run", "p.bas"], None, 70, "p.bas:2:5: error: out of memory", 3),
    ("compare 32 MB strings", 's = "a"\nfor i = 1 to 25\n  s = s + s\nnext\nt = s\nwhile 1\n  x = (s = t)\nwend\n', {},
     ["run", "--timeout", "3", "p.bas"], 3, 70, "p.bas:7:10:", None),
    ("print a 32 MB string", 's = "a"\nfor i = 1 to 25\n  s = s + s\nnext\nwhile 1\n  print s\nwend\n', {},
     ["run", "--timeout", "3", "p.bas"], 3, 70, "p.bas:6:3:", None),
    ('print " x"', 'while 1\n  print " x"\nwend\n', {}, ["run", "--timeout", "2", "p.bas"], 2, 70, "p.bas:2:3:", None),
    ("long lines of text", 's = "x"\nfor i = 1 to 12\n  s = s + s\nnext\nwhile 1\n  print s\nwend\n', {},
     ["run", "--timeout", "2", "p.bas"], 2, 70, "p.bas:6:3:", None),
    ("polygon of 1M corners", "dim p[2000000]\nfor i = 0 to 1999999 step 2\n  p[i] = i % 800\n  p[i + 1] = (i * 7) % 600\nnext\npolygon p, red\n", {},
     ["run", "--timeout", "1", "p.bas"], None, 70, "p.bas:6:1: error: argument 1 (points) of polygon has 1000000 corners", 1.5),
    ("replace growing a string", 's = "aaaaaaaaaaaaaaaa"\nfor i = 1 to 30\n  s = replace(s, "a", "aa")\nnext\n', {},
     ["run", "--timeout", "0.5", "p.bas"], 0.5, 70, "p.bas:3:7:", None),
    ("--robot-timeout 1e300", "print 1\n", {}, ["run", "--robot-timeout", "1e300", "p.bas"], None, 64,
     "--robot-timeout", 1),
    ("--timeout 1e10", "print 1\n", {}, ["run", "--timeout", "1e10", "p.bas"], None, 64, "--timeout", 1),
    ("rb test --timeout nan", "while 1\nwend\n", {}, ["test", "--timeout", "nan", "p.bas"], None, 64, "--timeout", 1),
    ("// timeout: 1e300 + --max-steps 0", "// timeout: 1e300\n// args: --max-steps 0\nwhile 1\nwend\n", {},
     ["test", "p.bas"], 30, 1, None, None),
    ("// timeout: 0", "// timeout: 0\nwhile 1\nwend\n", {}, ["test", "p.bas"], None, 1, None, 1),
    ("10 MB keys line", "print 1\n", {"big.events": "keys " + "a" * 10_000_000 + "\n"},
     ["run", "--events", "big.events", "p.bas"], None, 64, "big.events:1: more than 100000 steps", 1),
    ("xyText of 33M characters", 's = "W"\nfor i = 1 to 25\n  s = s + s\nnext\nxytext 10, 10, s, "Arial", 200\n', {},
     ["run", "p.bas"], None, 0, None, 2),
    ("1.5M errors, JSON", None, {"p.bas": "x = )\n" * 1_500_000}, ["check", "--format", "json", "p.bas"], None, 65, None, 2),
    # A robot that answers each command in 1.5 s (the emulator, on a pseudo-terminal): rTurn
    # 10000 is 40 commands.
    ("rTurn 10000, slow robot", "rLocate 400, 300\nrTurn 10000\n", {"@robot": "1500"},
     ["run", "--real", "--port", "robot", "--robot-timeout", "3", "--timeout", "2", "p.bas"], 2, 70, "p.bas:2:1:", None),
    ("regex ([a-z]+)*! on 32 a's", "print \"" + "a" * 32 + "\"\n",
     {"a.toml": '[[check]]\nkind = "output"\nregex = ["([a-z]+)*!"]\n'},
     ["test", "-a", "a.toml", "p.bas"], None, 1, None, 2),
]


def run_case(rb, case, work):
    name, program, files, args, limit, want_exit, want_err, bound = case
    if program is not None:
        with open(os.path.join(work, "p.bas"), "w") as f:
            f.write(program)
    robot = None
    for fname, text in files.items():
        if fname == "@robot":  # the robot emulator, answering after this many milliseconds
            robot = subprocess.Popen([rb, "robot", "--pty", "--link", os.path.join(work, "robot"), "--latency", text],
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
            robot.stdout.readline()  # its device: it is ready
            continue
        with open(os.path.join(work, fname), "w") as f:
            f.write(text)
    start = time.monotonic()
    with open(os.path.join(work, "out"), "wb") as out, open(os.path.join(work, "err"), "wb") as err:
        # GNU time measures the peak: wait4's own figure keeps the high-water mark of earlier
        # children of this process.
        proc = subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", "rss", rb] + args, cwd=work, stdout=out,
                                stderr=err, stdin=subprocess.DEVNULL)
        proc.wait()
    took = time.monotonic() - start
    code = proc.returncode
    if robot:
        robot.terminate()
        robot.wait()
    rss = open(os.path.join(work, "rss")).read().split()
    peak = int(rss[-1]) / 1024 if rss else 0  # MiB
    err_text = open(os.path.join(work, "err"), encoding="utf-8", errors="replace").read()
    out_text = open(os.path.join(work, "out"), encoding="utf-8", errors="replace").read()
    first = next((l for l in (err_text + out_text).splitlines() if l.strip()), "")
    problems = []
    if code != want_exit:
        problems.append(f"exit {code}, expected {want_exit}")
    if want_err and want_err not in err_text and want_err not in out_text:
        problems.append(f"no {want_err!r}")
    if limit is not None and not (limit <= took + 0.05 and took <= limit + max(0.2, 0.1 * limit) + 0.05):
        problems.append(f"{took:.2f} s is not within 10% and 0.2 s of {limit} s")
    if bound is not None and took > bound:
        problems.append(f"{took:.2f} s is more than {bound} s")
    return took, code, peak, first, problems


def main():
    rb = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "cmd", "rb"))
    print("| reproducer | limit | stopped after | exit | peak memory | where / what rb said |")
    print("|---|---|---|---|---|---|")
    failed = 0
    for case in CASES:
        work = tempfile.mkdtemp(prefix="rb-limits-")
        try:
            took, code, peak, first, problems = run_case(rb, case, work)
        finally:
            shutil.rmtree(work, ignore_errors=True)
        name, limit, bound = case[0], case[4], case[7]
        what = f"{limit} s" if limit is not None else (f"answer within {bound} s" if bound else "-")
        said = first.replace("|", "\\|")[:110]
        mark = "" if not problems else " **MISSED: " + "; ".join(problems) + "**"
        failed += bool(problems)
        print(f"| {name} | {what} | {took:.2f} s | {code} | {peak:.0f} MiB | {said}{mark} |")
    print()
    print(f"{len(CASES)} cases, {failed} missed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
