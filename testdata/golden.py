#!/usr/bin/env python3
"""Runs one golden test program through `rb check` and `rb run` and compares the results with
the expectations written in its comments (see testdata/README.md for the syntax).

Usage: golden.py --rb PATH/TO/rb FILE.bas [FILE.bas ...]
Exit status 0 when every file passes; the differences are printed otherwise.
"""
import argparse
import os
import re
import shlex
import subprocess
import sys

# Several expectations may share a line: each runs up to the next "// expect".
EXPECT = re.compile(r"//\s*expect(?P<kind>-error|-warning|-runtime-error|-stderr)?:\s?(?P<text>.*?)(?=\s*//\s*expect|$)")
DIRECTIVE = re.compile(r"//\s*(?P<key>stdin|args|check-args|skip|nontest|timeout|exit|expect-empty-line)\b:?\s?(?P<text>.*)$")
INCLUDE = re.compile(r'^\s*#include\s+"(?P<file>[^"]+)"', re.I)
DIAG = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<col>\d+): (?P<sev>error|warning|note): (?P<msg>.*)$")


class Spec:
    def __init__(self):
        self.stdout = []          # expected lines of standard output
        self.errors = set()       # (file, line, message) load-time errors
        self.warnings = set()     # (file, line, message) rb check warnings
        self.runtime = None       # (file, line, message)
        self.stderr = []          # substrings rb run's standard error must contain
        self.stdin = []
        self.args = []
        self.check_args = []
        self.skip = None
        self.nontest = False
        self.timeout = 30.0
        self.exit = None


def parse(path, spec, main=True, seen=None):
    seen = seen if seen is not None else set()
    real = os.path.realpath(path)
    if real in seen:
        return spec
    seen.add(real)
    base = os.path.basename(path)
    with open(path, encoding="latin-1") as f:
        lines = f.read().split("\n")
    for number, line in enumerate(lines, start=1):
        found = list(EXPECT.finditer(line))
        for m in found:
            kind, text = m.group("kind"), m.group("text").rstrip()
            if kind is None:
                if main:
                    spec.stdout.append(m.group("text").rstrip("\r"))
            elif kind == "-error":
                spec.errors.add((base, number, text))
            elif kind == "-warning":
                spec.warnings.add((base, number, text))
            elif kind == "-runtime-error":
                spec.runtime = (base, number, text)
            elif kind == "-stderr":
                spec.stderr.append(text)
        if found:
            continue
        d = DIRECTIVE.search(line)
        if d and main:
            key, text = d.group("key"), d.group("text").rstrip()
            if key == "stdin":
                spec.stdin.append(text)
            elif key == "args":
                spec.args += shlex.split(text)
            elif key == "check-args":
                spec.check_args += shlex.split(text)
            elif key == "skip":
                spec.skip = text or "skipped"
            elif key == "nontest" and number == 1:
                spec.nontest = True
            elif key == "timeout":
                spec.timeout = float(text)
            elif key == "exit":
                spec.exit = int(text)
            elif key == "expect-empty-line":
                spec.stdout.append("")
        inc = INCLUDE.match(line)
        if inc:
            target = os.path.join(os.path.dirname(path), inc.group("file"))
            if os.path.exists(target):
                parse(target, spec, main=False, seen=seen)
    return spec


def diagnostics(text):
    out = []
    for line in text.splitlines():
        m = DIAG.match(line)
        if m:
            out.append((os.path.basename(m.group("file")), int(m.group("line")), m.group("sev"), m.group("msg")))
    return out


def run(cmd, stdin_text, timeout, cwd):
    try:
        p = subprocess.run(cmd, input=stdin_text.encode(), capture_output=True, timeout=timeout, cwd=cwd)
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {timeout}s"
    return p.returncode, p.stdout.decode("latin-1"), p.stderr.decode("latin-1")


def check_file(rb, path):
    spec = parse(path, Spec())
    name = os.path.basename(path)
    cwd = os.path.dirname(os.path.abspath(path))
    if spec.nontest:
        return []
    if spec.skip:
        print(f"SKIP {path}: {spec.skip}")
        return []
    problems = []

    # 1. rb check: exactly the expected errors and warnings, and the matching exit status.
    code, out, err = run([rb, "check"] + spec.check_args + [name], "", spec.timeout, cwd)
    if code is None:
        problems.append(f"rb check {err}")
    else:
        got = diagnostics(out)
        got_errors = {(f, l, m) for f, l, s, m in got if s == "error"}
        got_warnings = {(f, l, m) for f, l, s, m in got if s == "warning"}
        for e in sorted(spec.errors - got_errors):
            problems.append(f"rb check: missing error {e[0]}:{e[1]}: {e[2]}")
        for e in sorted(got_errors - spec.errors):
            problems.append(f"rb check: unexpected error {e[0]}:{e[1]}: {e[2]}")
        for w in sorted(spec.warnings - got_warnings):
            problems.append(f"rb check: missing warning {w[0]}:{w[1]}: {w[2]}")
        for w in sorted(got_warnings - spec.warnings):
            problems.append(f"rb check: unexpected warning {w[0]}:{w[1]}: {w[2]}")
        want_code = 65 if spec.errors else 0
        if code != want_code:
            problems.append(f"rb check: exit status {code}, expected {want_code}")

    # 2. rb run: standard output, runtime error and exit status.
    stdin_text = "".join(s + "\n" for s in spec.stdin)
    code, out, err = run([rb, "run"] + spec.args + [name], stdin_text, spec.timeout, cwd)
    if code is None:
        problems.append(f"rb run {err}")
        return problems
    if spec.errors:
        want_code = 65
        got_errors = {(f, l, m) for f, l, s, m in diagnostics(err) if s == "error"}
        if got_errors != spec.errors:
            problems.append(f"rb run: errors differ from rb check's: {sorted(got_errors)}")
        if out:
            problems.append(f"rb run: printed output although the program was rejected: {out[:200]!r}")
    else:
        want_code = 70 if spec.runtime else 0
        expected = "".join(s + "\n" for s in spec.stdout)
        if out != expected:
            problems.append("rb run: standard output differs\n--- expected\n" + expected + "--- got\n" + out + "---")
        if spec.runtime:
            diags = [d for d in diagnostics(err) if d[2] == "error"]
            got = (diags[0][0], diags[0][1], diags[0][3]) if diags else None
            if got != spec.runtime:
                problems.append(f"rb run: runtime error {got}, expected {spec.runtime}\n{err}")
        elif err and not spec.stderr:
            problems.append("rb run: unexpected standard error:\n" + err)
    for s in spec.stderr:
        if s not in err:
            problems.append(f"rb run: standard error lacks {s!r}:\n{err}")
    if spec.exit is not None:
        want_code = spec.exit
    if code != want_code:
        problems.append(f"rb run: exit status {code}, expected {want_code}\n{err}")
    return problems


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    rb = os.path.abspath(args.rb)
    failed = 0
    for f in args.files:
        problems = check_file(rb, f)
        if problems:
            failed += 1
            print(f"FAIL {f}")
            for p in problems:
                print("  " + p.replace("\n", "\n  "))
    if len(args.files) > 1:
        print(f"{len(args.files) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
