#!/usr/bin/env python3
"""End-to-end tests of `rb test` with an assignment file: the class in square/class/ (a correct
program, one off by one side, one crashing, one looping forever, one not compiling, one with the
wrong output) graded against square/assignment.toml, every verdict and reason asserted; the
reports (JUnit validated against junit.xsd with xmllint, JSON, CSV, pictures), sharding,
determinism, bad assignment files, and rb trace's machine-readable streams.

Usage: grade_test.py --rb PATH/TO/rb --work WORK_DIR CASE

Each CASE is one CTest test (CMakeLists.txt here); WORK_DIR is emptied first. Exit 77: skipped.
"""

import argparse
import csv
import io
import json
import os
import re
import shutil
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SQUARE = os.path.join(HERE, "square")
CLASS = os.path.join(SQUARE, "class")
ASSIGNMENT = os.path.join(SQUARE, "assignment.toml")
SCHEMA = os.path.join(HERE, "junit.xsd")


class Failure(Exception):
    pass


class Skip(Exception):
    pass


def expect(cond, message, *context):
    if not cond:
        raise Failure(message + "".join("\n" + str(c) for c in context))


class Env:
    def __init__(self, rb, work):
        self.rb, self.work = rb, work

    def path(self, name):
        return os.path.join(self.work, name)

    def write(self, name, text):
        with open(self.path(name), "w") as f:
            f.write(text)
        return self.path(name)

    def rb_run(self, *args, cwd=None):
        return subprocess.run([self.rb, *args], capture_output=True, text=True, timeout=300, cwd=cwd)

    def grade(self, *args):
        """rb test --format json over the class; returns (exit code, {file name: program})."""
        r = self.rb_run("test", "--format", "json", "-a", ASSIGNMENT, *args)
        try:
            doc = json.loads(r.stdout)
        except json.JSONDecodeError:
            raise Failure(f"rb test printed no JSON (exit {r.returncode})\n{r.stdout}\n{r.stderr}")
        return r.returncode, {os.path.basename(p["program"]): p for p in doc["programs"]}, doc


def failed_checks(program):
    return [c["name"] for c in program["checks"] if not c["passed"]]


# Every program of the class: its verdict, the reason (a pattern) and the checks it fails.
EXPECTED = {
    "correct.bas": ("pass", r"^$", []),
    "off_by_one.bas": (
        "fail",
        r"^the robot misses point 5 \(400, 300\) after point 4 by 117 px: it comes within 120 px, 3 px allowed$",
        ["corners", "solution-trail", "ends-in"]),
    "crashing.bas": (
        "fail",
        r"^the robot crashed at crashing\.bas:6:1 after 5 steps: robot crashed into an obstacle: the edge of the screen$",
        ["no-error", "solution-output", "corners", "solution-trail", "ends-in", "solution-screen"]),
    "looping.bas": (
        "fail",
        r"^did not finish: stopped at looping\.bas:6:7 after 100000 steps, the step limit \(max-steps = 100000 in "
        r"assignment\.toml\), in the loop of lines 6-9 \(does it ever end\?\)$",
        ["no-error", "solution-output"]),
    "not_compiling.bas": (
        "fail",
        r"^rb check finds 1 error: not_compiling\.bas:7:3: unknown command 'rForwad'; did you mean 'rForward'\?$",
        ["check", "no-error", "solution-output", "corners", "solution-trail", "ends-in", "solution-screen"]),
    "wrong_output.bas": (
        "fail",
        r'^output differs at line 1: expected "perimeter 480", got "perimeter 360" \(the solution\'s output\)$',
        ["solution-output"]),
}


def case_class(env):
    code, programs, doc = env.grade("-j", "2", SQUARE)
    expect(code == 1, f"exit {code}, expected 1 (some programs fail)")
    expect(sorted(programs) == sorted(EXPECTED), "graded programs", sorted(programs))
    for name, (verdict, reason, failing) in EXPECTED.items():
        p = programs[name]
        expect(p["result"] == verdict, f"{name}: result {p['result']}, expected {verdict}", p)
        expect(re.match(reason, p["reason"]), f"{name}: reason {p['reason']!r} does not match {reason!r}")
        expect(failed_checks(p) == failing, f"{name}: failed checks {failed_checks(p)}, expected {failing}", p)
    # By how much: the trail's distance and the end position.
    off = {c["name"]: c["message"] for c in programs["off_by_one.bas"]["checks"]}
    expect(off["solution-trail"].startswith("the trail is 60 px off the solution's at its worst, 3 px allowed"),
           "trail message", off["solution-trail"])
    expect(off["ends-in"] == "the robot ends at (520, 300), 115 px outside the circle of radius 5 around (400, 300)",
           "ends-in message", off["ends-in"])
    # Points: solution-trail is worth 2, the others 1.
    expect(programs["correct.bas"]["points"] == 8 and programs["correct.bas"]["max_points"] == 8, "points of correct.bas")
    expect(programs["off_by_one.bas"]["points"] == 4, "points of off_by_one.bas", programs["off_by_one.bas"])
    expect(programs["looping.bas"]["steps"] == 100000, "steps of looping.bas")
    expect(doc["summary"] == {**doc["summary"], "programs": 6, "passed": 1, "failed": 5, "errors": 0, "skipped": 0},
           "summary", doc["summary"])
    # The solution itself is not graded, even in the folder given.
    expect("solution.bas" not in programs, "the solution was graded")


def case_text(env):
    r = env.rb_run("test", "-j", "2", "-a", ASSIGNMENT, CLASS)
    expect(r.returncode == 1, f"exit {r.returncode}", r.stdout, r.stderr)
    lines = r.stdout.splitlines()
    expect(lines[0].split() == ["program", "result", "points", "steps", "time", "reason"], "header", lines[0])
    row = next(l for l in lines if "crashing.bas" in l and "FAIL" in l)
    expect(" 5 " in row and "the robot crashed at crashing.bas:6:1" in row, "crashing row", row)
    expect(any(re.match(r"^\s+solution-trail: the trail is 160 px off the solution's", l) for l in lines),
           "details list every failed check", r.stdout)
    expect(lines[-1].startswith("6 programs: 1 passed, 5 failed in "), "total line", lines[-1])
    q = env.rb_run("test", "-q", "-a", ASSIGNMENT, os.path.join(CLASS, "correct.bas"))
    expect(q.returncode == 0, f"one passing program: exit {q.returncode}", q.stdout, q.stderr)


def case_junit(env):
    xmllint = shutil.which("xmllint")
    if not xmllint:
        raise Skip("xmllint is not installed (Debian: libxml2-utils)")
    report = env.path("report.xml")
    r = env.rb_run("test", "-q", "-j", "2", "-a", ASSIGNMENT, "--junit", report, CLASS)
    expect(r.returncode == 1, f"exit {r.returncode}", r.stderr)
    v = subprocess.run([xmllint, "--noout", "--schema", SCHEMA, report], capture_output=True, text=True)
    expect(v.returncode == 0, "the JUnit report does not validate against junit.xsd", v.stderr)
    # The schema must be able to fail: a count that is not a number, a test case without a name.
    for bad in ('<testsuites><testsuite name="s" tests="six"/></testsuites>',
                '<testsuites><testsuite name="s" tests="1"><testcase classname="c"/></testsuite></testsuites>'):
        path = env.write("bad.xml", bad)
        v = subprocess.run([xmllint, "--noout", "--schema", SCHEMA, path], capture_output=True, text=True)
        expect(v.returncode != 0, "junit.xsd accepts a broken report", bad)
    import xml.etree.ElementTree as ET
    root = ET.parse(report).getroot()
    suite = root.find("testsuite")
    expect(suite.get("name") == "square" and suite.get("tests") == "6" and suite.get("failures") == "5",
           "testsuite counts", suite.attrib)
    cases = {c.get("name"): c for c in suite.findall("testcase")}
    expect(sorted(cases) == sorted(EXPECTED), "test cases", sorted(cases))
    expect(cases["correct.bas"].find("failure") is None, "correct.bas has a failure")
    expect(cases["correct.bas"].find("system-out").text == "perimeter 480\n", "correct.bas's output")
    failure = cases["crashing.bas"].find("failure")
    expect(failure is not None and failure.get("type") == "no-error" and
           failure.get("message").startswith("the robot crashed at crashing.bas:6:1 after 5 steps"),
           "crashing.bas's failure", failure.attrib if failure is not None else None)
    expect("solution-trail: the trail is 160 px" in failure.text, "the failure lists every failed check", failure.text)
    expect("error output" not in failure.text and "rb-robot-crash" in cases["crashing.bas"].find("system-err").text,
           "the error output once, in <system-err>", failure.text)


def case_csv(env):
    book = env.path("grades.csv")
    r = env.rb_run("test", "-q", "-a", ASSIGNMENT, "--csv", book, CLASS)
    expect(r.returncode == 1, f"exit {r.returncode}", r.stderr)
    with open(book, newline="") as f:
        rows = list(csv.DictReader(f))
    expect(len(rows) == 6, f"{len(rows)} rows")
    by = {os.path.basename(row["program"]): row for row in rows}
    expect(by["correct.bas"]["result"] == "pass" and by["correct.bas"]["points"] == "8", "correct.bas", by["correct.bas"])
    expect(by["wrong_output.bas"]["points"] == "7" and by["wrong_output.bas"]["solution-output"] == "0" and
           by["wrong_output.bas"]["solution-trail"] == "2", "wrong_output.bas", by["wrong_output.bas"])
    expect(by["off_by_one.bas"]["reason"].startswith("the robot misses point 5"), "reason", by["off_by_one.bas"])


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    expect(head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", f"{path} is not a PNG file")
    return struct.unpack(">II", head[16:24])


def case_pictures(env):
    pics = env.path("pictures")
    code, programs, _ = env.grade("--pictures", pics, CLASS)
    expect(code == 1, f"exit {code}")
    for name, p in programs.items():
        expect(os.path.isfile(p.get("picture", "")), f"{name}: no picture", p)
        expect(png_size(p["picture"]) == (800, 664), f"{name}: picture size (the arena and the legend below it)")
    expect(len(os.listdir(pics)) == 6, "one picture per program", os.listdir(pics))


def case_shard(env):
    seen = []
    for k in (1, 2, 3):
        code, programs, _ = env.grade("--shard", f"{k}/3", CLASS)
        expect(len(programs) == 2, f"shard {k}/3 has {len(programs)} programs", sorted(programs))
        seen += programs
    expect(sorted(seen) == sorted(EXPECTED), "the shards together are the class, once each", sorted(seen))
    r = env.rb_run("test", "--shard", "4/3", CLASS)
    expect(r.returncode == 64 and "--shard" in r.stderr, f"--shard 4/3: exit {r.returncode}", r.stderr)


def strip_times(doc):
    for p in doc["programs"]:
        p.pop("seconds")
    doc["summary"].pop("seconds")
    doc.pop("timestamp")
    return doc


def case_deterministic(env):
    _, _, one = env.grade("-j", "1", CLASS)
    _, _, two = env.grade("-j", "2", CLASS)
    expect(strip_times(one) == strip_times(two), "-j 1 and -j 2 grade differently")


def case_comments(env):
    # Without an assignment, each program's own // expect comments decide: correct.bas has one.
    r = env.rb_run("test", os.path.join(CLASS, "correct.bas"))
    expect(r.returncode == 0, f"correct.bas against its comments: exit {r.returncode}", r.stdout)
    # A program that prints what no comment expects fails, saying what differs.
    r = env.rb_run("test", os.path.join(CLASS, "wrong_output.bas"))
    expect(r.returncode == 1 and 'output has 1 line, expected 0; line 1 is "perimeter 360"' in r.stdout,
           f"wrong_output.bas against its comments: exit {r.returncode}", r.stdout)
    # A student's test: // expect lines and an expected runtime error.
    prog = env.write("student.bas", 'print "hello"  // expect: hello\nx = 1 / 0  // expect-runtime-error: division by zero\n')
    r = env.rb_run("test", prog)
    expect(r.returncode == 0, f"student.bas: exit {r.returncode}", r.stdout)
    env.write("student.bas", 'print "hullo"  // expect: hello\n')
    r = env.rb_run("test", prog)
    expect(r.returncode == 1 and 'expected "hello", got "hullo"' in r.stdout, f"student.bas: exit {r.returncode}", r.stdout)


def case_bad_assignment(env):
    bad = env.write("bad.toml", '[[check]]\nkind = "trail"\npath = [[1, 2]]\ntolerence = 3\n')
    r = env.rb_run("test", "-a", bad, CLASS)
    expect(r.returncode == 64, f"exit {r.returncode}", r.stderr)
    expect(f"{bad}:4:1: unknown key 'tolerence' in check 'trail'; did you mean 'tolerance'?" in r.stderr, "message", r.stderr)
    bad = env.write("bad.toml", '[[check]]\nkind = "solution-trail"\n')
    r = env.rb_run("test", "-a", bad, CLASS)
    expect(r.returncode == 64 and "need the reference solution" in r.stderr, f"exit {r.returncode}", r.stderr)
    bad = env.write("bad.toml", 'title = "unclosed\n')
    r = env.rb_run("test", "-a", bad, CLASS)
    expect(r.returncode == 64 and f"{bad}:1:" in r.stderr, f"TOML syntax: exit {r.returncode}", r.stderr)
    r = env.rb_run("test", env.path("no_such_folder"))
    expect(r.returncode == 66 and "no such file or folder" in r.stderr, f"missing path: exit {r.returncode}", r.stderr)


def case_timeout(env):
    # No step limit: a loop that never ends runs into the time limit, and the rest is still
    # graded. (A loop of cheap statements: the run checks the clock every 65,536 of them.)
    solution = os.path.join(SQUARE, "solution.bas")
    spin = env.write("spin.bas", "x = 0\nwhile 1\n  x = x + 1\nwend\n")
    a = env.write("timeout.toml", f'solution = "{solution}"\n[run]\nmax-steps = 0\ntimeout = 1\n'
                  '[[check]]\nkind = "no-error"\n[[check]]\nkind = "solution-output"\n')
    r = env.rb_run("test", "--format", "json", "-j", "2", "-a", a, spin, os.path.join(CLASS, "correct.bas"))
    doc = json.loads(r.stdout)
    by = {os.path.basename(p["program"]): p for p in doc["programs"]}
    expect(r.returncode == 1, f"exit {r.returncode}", r.stderr)
    expect(by["correct.bas"]["result"] == "pass", "correct.bas", by["correct.bas"])
    # The limit as the assignment set it, where the run was and the loop it was in; the robot
    # never moved in an assignment about the robot (the solution moves it), so nothing counts.
    expect(re.match(r"^did not finish: stopped at spin\.bas:2:7 after \d+ steps, the time limit \(timeout = 1 in "
                    r"timeout\.toml\), in the loop of lines 2-4 \(does it ever end\?\); the robot never moved before that$",
                    by["spin.bas"]["reason"]), "spin.bas", by["spin.bas"])
    expect(by["spin.bas"]["points"] == 0 and not by["spin.bas"]["checks"][0]["checked"], "gated", by["spin.bas"])
    expect("(timeout = 1 in timeout.toml)" in by["spin.bas"]["errors"] and "--timeout" not in by["spin.bas"]["errors"],
           "the error output names the limit as the assignment set it", by["spin.bas"]["errors"])


def case_trace(env):
    out = env.path("traces")
    sol = os.path.join(SQUARE, "solution.bas")
    crash = os.path.join(CLASS, "crashing.bas")
    r = env.rb_run("trace", "--format", "jsonl", "--out", out, sol, crash)
    expect(r.returncode == 70, f"exit {r.returncode} (the second program crashes)", r.stderr)
    with open(os.path.join(out, "solution.jsonl")) as f:
        sol_events = [json.loads(l) for l in f]
    with open(os.path.join(out, "crashing.jsonl")) as f:
        crash_events = [json.loads(l) for l in f]
    expect(sol_events[0]["args"] == [400, 300], "args as numbers", sol_events[0])
    output = [e for e in sol_events if e["event"] == "output"]
    expect(len(output) == 1 and output[0]["text"] == "perimeter 480\n" and output[0]["line"] == 11,
           "the print as an output event with its line", output)
    end = sol_events[-1]
    expect(end["event"] == "end" and end["status"] == "finished" and end["steps"] == 18 and
           (end["x"], end["y"], end["heading"]) == (400, 300, 0), "the solution's end record", end)
    end = crash_events[-1]
    expect(end["status"] == "error" and (end["line"], end["col"]) == (6, 1) and
           end["message"] == "robot crashed into an obstacle: the edge of the screen" and end["steps"] == 5 and end["exit"] == 70,
           "the crash's end record", end)
    # Several files on standard output: each record names its program.
    r = env.rb_run("trace", "--format", "jsonl", sol, os.path.join(CLASS, "not_compiling.bas"))
    lines = [json.loads(l) for l in r.stdout.splitlines()]
    expect(r.returncode == 65 and {l["program"] for l in lines} == {sol, os.path.join(CLASS, "not_compiling.bas")},
           f"two streams on stdout: exit {r.returncode}", r.stdout)
    rejected = lines[-1]
    expect(rejected["status"] == "rejected" and rejected["errors"][0]["line"] == 7, "a rejected program's end", rejected)


CASES = {name[5:]: fn for name, fn in globals().items() if name.startswith("case_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("case", choices=sorted(CASES))
    args = ap.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    try:
        CASES[args.case](Env(os.path.abspath(args.rb), args.work))
    except Skip as s:
        print(f"SKIP {args.case}: {s}")
        return 77
    except Failure as f:
        print(f"FAIL {args.case}: {f}")
        return 1
    print(f"ok {args.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
