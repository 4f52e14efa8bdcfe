#!/usr/bin/env python3
"""Compiler tests: small programs in, expected code out (ninja-style golden files).

    code_test.py --rb path/to/rb [--update] FILE.bas...

For every FILE.bas, runs `rb check --dump-code FILE.bas` and compares its standard output with
FILE.code beside it; a difference is shown as a unified diff and fails the test. With --update,
FILE.code is rewritten instead: review the change with `git diff` before committing it.
The .bas files are ordinary golden programs too (golden.py runs them with their // expect:
lines), so each test also shows that the code it pins down does what it should.
"""
import argparse
import difflib
import os
import subprocess
import sys


def dump(rb, path):
    folder, name = os.path.split(os.path.abspath(path))
    result = subprocess.run([rb, "check", "--dump-code", name], cwd=folder, capture_output=True,
                            text=True, timeout=60)
    if result.returncode != 0:
        raise RuntimeError(f"rb check exited with {result.returncode}:\n{result.stdout}{result.stderr}")
    return result.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rb", required=True, help="the rb binary")
    parser.add_argument("--update", action="store_true", help="rewrite the .code files")
    parser.add_argument("files", nargs="+", help=".bas programs")
    args = parser.parse_args()
    args.rb = os.path.abspath(args.rb)
    failed = 0
    for path in args.files:
        expected_path = os.path.splitext(path)[0] + ".code"
        try:
            actual = dump(args.rb, path)
        except (RuntimeError, subprocess.TimeoutExpired) as e:
            print(f"{path}: {e}")
            failed += 1
            continue
        if args.update:
            with open(expected_path, "w") as f:
                f.write(actual)
            print(f"wrote {expected_path}")
            continue
        try:
            with open(expected_path) as f:
                expected = f.read()
        except FileNotFoundError:
            print(f"{path}: no {expected_path} (create it with --update)")
            failed += 1
            continue
        if actual != expected:
            print(f"{path}: the compiled code differs from {os.path.basename(expected_path)}:")
            sys.stdout.writelines(difflib.unified_diff(expected.splitlines(True), actual.splitlines(True),
                                                       "expected", "actual"))
            failed += 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
