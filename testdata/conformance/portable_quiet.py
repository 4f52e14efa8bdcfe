#!/usr/bin/env python3
"""rb check --portable on the seed's programs and on the shared conformance programs.

Usage: portable_quiet.py RB SOURCE_DIR CONFORMANCE_DIR

Every program of the seed document (examples/, as printed) must give no rb-not-portable
warning: the seed is RobotBASIC. The shared conformance programs are written in RobotBASIC too
and must give exactly the warnings listed in CONFORMANCE below (none else, and each of those):
today none, since what they use beyond the public sources (pixelClr, step) the research notes
recall from RobotBASIC's manual (docs/compatibility.md, "recalled"). A program that newly warns
here shows either a gap in the evidence table or a form rb wrongly calls its own. Without the
conformance programs (CONFORMANCE_DIR missing) only the seed's are checked.
"""
import glob
import os
import re
import subprocess
import sys

CONFORMANCE = []
LINE = re.compile(r"^(?P<file>[^:\n]+):(?P<line>\d+):\d+: warning: (?P<msg>.*) \[rb-not-portable\]$", re.M)


def portable_warnings(rb, path):
    r = subprocess.run([rb, "check", "--color=never", "--portable", os.path.basename(path)],
                       cwd=os.path.dirname(path), capture_output=True, text=True, timeout=60)
    return [(os.path.basename(m["file"]), int(m["line"]), m["msg"]) for m in LINE.finditer(r.stdout)]


def main():
    rb, source, conformance = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
    failures = []
    seed = sorted(glob.glob(os.path.join(source, "examples", "*.bas")))
    if not seed:
        failures.append("no seed programs in examples/")
    for path in seed:
        for w in portable_warnings(rb, path):
            failures.append(f"seed program {w[0]}:{w[1]}: {w[2]}")
    programs = sorted(glob.glob(os.path.join(conformance, "*.bas")))
    if programs:
        got = []
        for path in programs:
            got += portable_warnings(rb, path)
        # The same warning twice on a line counts twice: compare as lists.
        want = list(CONFORMANCE)
        for w in sorted(got):
            if w in want:
                want.remove(w)
            else:
                failures.append(f"conformance program {w[0]}:{w[1]}: unexpected: {w[2]}")
        for w in want:
            failures.append(f"conformance program {w[0]}:{w[1]}: expected and missing: {w[2]}")
    else:
        print(f"no conformance programs at {conformance}: only the seed's checked")
    for f in failures:
        print(f)
    print(f"{len(seed)} seed programs, {len(programs)} conformance programs: "
          f"{'ok' if not failures else str(len(failures)) + ' problems'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
