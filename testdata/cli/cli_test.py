#!/usr/bin/env python3
"""Command-line cases of rb, one block each in cases.txt: the command, its exit status and what
its standard error (and output) must contain. Usage: cli_test.py --rb RB --source DIR --work DIR
[--list] [NAME]

A block is a set of `key: value` lines, blocks separated by a blank line:
  name:    the case's name (one CTest test each)
  run:     the command line, split like a shell would; `rb` is the binary under test, {src} the
           project's source folder, {work} a fresh folder for the case
  setup:   a shell command run first in {work} (optional)
  exit:    the expected exit status
  stderr:  a regular expression standard error must match (repeatable)
  stdout:  a regular expression standard output must match (repeatable)
  no-stderr: a regular expression standard error must not match (repeatable)
  after:   a shell command run in {work} afterwards that must succeed (optional)
  sigpipe: ignore  - run rb with SIGPIPE ignored, read one line of its output, close the pipe;
           rb must end within 5 s
  stdin:   silent  - standard input is a pipe that stays open and empty while rb runs
  within:  seconds - rb must end within this many seconds of wall time
  stdout-file: PATH - rb's standard output goes to this file (/dev/full: every write fails)
  timeout: seconds (default 30)
"""
import argparse
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time


def parse(path):
    cases, cur = [], {}
    for raw in open(path, encoding="utf-8"):
        line = raw.rstrip("\n")
        if line.startswith("#"):
            continue
        if not line.strip():
            if cur:
                cases.append(cur)
                cur = {}
            continue
        key, _, value = line.partition(":")
        cur.setdefault(key.strip(), []).append(value.strip())
    if cur:
        cases.append(cur)
    return {c["name"][0]: c for c in cases}


def run_case(case, rb, source, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    subst = lambda s: s.replace("{src}", source).replace("{work}", work).replace("{rb}", rb)
    for setup in case.get("setup", []):
        subprocess.run(subst(setup), shell=True, cwd=work, check=True)
    argv = [subst(a) for a in shlex.split(case["run"][0])]
    if argv[0] == "rb":
        argv[0] = rb
    timeout = float(case.get("timeout", ["30"])[0])
    problems = []
    if case.get("sigpipe", [""])[0] == "ignore":
        start = time.monotonic()
        p = subprocess.Popen(argv, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             preexec_fn=lambda: signal.signal(signal.SIGPIPE, signal.SIG_IGN))
        p.stdout.readline()
        p.stdout.close()
        try:
            err = p.stderr.read().decode("utf-8", "replace")
            code = p.wait(timeout=5)
        except subprocess.TimeoutExpired:
            p.kill()
            return ["rb did not stop within 5 s after its output pipe closed"]
        out = ""
        if time.monotonic() - start > 5:
            problems.append("rb took more than 5 s to stop")
    else:
        start = time.monotonic()
        silent_read, silent_write = os.pipe() if case.get("stdin", [""])[0] == "silent" else (None, None)
        try:
            out_file = open(subst(case["stdout-file"][0]), "wb") if "stdout-file" in case else None
            r = subprocess.run(argv, cwd=work, stdout=out_file or subprocess.PIPE,
                               stderr=subprocess.PIPE, timeout=timeout,
                               stdin=silent_read if silent_read is not None else subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return [f"timed out after {timeout} s"]
        finally:
            for fd in (silent_read, silent_write):
                if fd is not None:
                    os.close(fd)
        took = time.monotonic() - start
        if out_file:
            out_file.close()
        code, out = r.returncode, (r.stdout or b"").decode("utf-8", "replace")
        err = r.stderr.decode("utf-8", "replace")
        if "within" in case and took > float(case["within"][0]):
            problems.append(f"rb took {took:.2f} s, more than {case['within'][0]} s")
    want = int(case["exit"][0])
    if code != want:
        problems.append(f"exit {code}, expected {want}")
    for pat in case.get("stderr", []):
        if not re.search(subst(pat), err):
            problems.append(f"stderr does not match {pat!r}")
    for pat in case.get("no-stderr", []):
        if re.search(subst(pat), err):
            problems.append(f"stderr matches {pat!r}")
    for pat in case.get("stdout", []):
        if not re.search(subst(pat), out):
            problems.append(f"stdout does not match {pat!r}")
    for after in case.get("after", []):
        if subprocess.run(subst(after), shell=True, cwd=work).returncode != 0:
            problems.append(f"check failed: {after}")
    if problems:
        problems.append("stderr was: " + err[:2000])
        problems.append("stdout was: " + out[:500])
    return problems


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb")
    ap.add_argument("--source")
    ap.add_argument("--work")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("names", nargs="*")
    a = ap.parse_args()
    cases = parse(os.path.join(os.path.dirname(os.path.abspath(__file__)), "cases.txt"))
    if a.list:
        print(";".join(cases))
        return 0
    failed = 0
    for name in a.names or list(cases):
        problems = run_case(cases[name], os.path.abspath(a.rb), os.path.abspath(a.source),
                            os.path.join(os.path.abspath(a.work), name))
        if problems:
            failed += 1
            print(f"FAIL {name}:\n  " + "\n  ".join(problems))
        else:
            print(f"ok {name}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
