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
import time
import signal
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
# Jenkins' xunit plugin's schema for JUnit reports (github.com/jenkinsci/xunit-plugin, MIT licence
# in its header), kept as fetched: the consumer's own word on what a JUnit report may hold.
JENKINS_SCHEMA = os.path.join(HERE, "jenkins-junit-10.xsd")


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
        r"^did not finish: stopped at looping\.bas:6:7 after 25000 steps, the step limit \(max-steps = 25000 in "
        r"assignment\.toml\), in the loop of lines 6-9 \(does it ever end\?\)$",
        ["no-error", "solution-output"]),
    "not_compiling.bas": (
        "fail",
        r"^the program does not compile: not_compiling\.bas:7:3: unknown command 'rForwad'; did you mean 'rForward'\?$",
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
    expect(programs["looping.bas"]["steps"] == 25000, "steps of looping.bas")
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
    v = subprocess.run([xmllint, "--noout", "--schema", JENKINS_SCHEMA, report], capture_output=True, text=True)
    expect(v.returncode == 0, "the JUnit report does not validate against Jenkins' junit-10.xsd", v.stderr)
    # Jenkins' schema refuses what rb wrote before: `file` on a test case, `skipped` on testsuites.
    for bad in ('<testsuites><testsuite name="s" tests="1" failures="0" errors="0"><testcase name="a" file="a.bas"/>'
                '</testsuite></testsuites>',
                '<testsuites skipped="0"><testsuite name="s" tests="0" failures="0" errors="0"/></testsuites>'):
        path = env.write("bad_jenkins.xml", bad)
        v = subprocess.run([xmllint, "--noout", "--schema", JENKINS_SCHEMA, path], capture_output=True, text=True)
        expect(v.returncode != 0, "jenkins-junit-10.xsd accepts what it should refuse", bad)
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
    files = {p.get("name"): p.get("value") for p in suite.find("properties").findall("property")}
    expect(files.get("file: correct.bas", "").endswith("class/correct.bas"), "each program's path is a property", files)
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
        if name == "not_compiling.bas":
            # Nothing of its own to show: no picture (never the solution's screen instead).
            expect("picture" not in p, f"{name}: a picture of a program that does not compile", p)
            continue
        expect(os.path.isfile(p.get("picture", "")), f"{name}: no picture", p)
        expect(png_size(p["picture"]) == (800, 664), f"{name}: picture size (the arena and the legend below it)")
    expect(len(os.listdir(pics)) == 5, "one picture per program that ran", os.listdir(pics))


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


def case_colour_steps(env):
    # A program that never ends, graded against a colour check: the step limit stops it, not the
    # time limit, so it is graded the same each time. Looking at every pixel of the disc (radius
    # 50: 7,854 of them) at 11 points of each move, as rb did before, would have taken some 25 s
    # of processor time for these 200,000 steps (the time limit stopped it after about 50,000);
    # following the colour along the path takes a fraction of a second.
    env.write("circling.bas", "// Drives in circles for ever, far from the black square it must avoid.\n"
              "rectangle 20, 20, 80, 80, black, black\nrLocate 400, 300, 0, 50\n"
              "while 1\n  rForward 10\n  rTurn 7\nwend\n")
    a = env.write("colour.toml", '[run]\nmax-steps = 200000\ntimeout = 10\n'
                  '[[check]]\nname = "square"\nkind = "avoid"\ncolour = "black"\n'
                  '[[check]]\nname = "ends"\nkind = "no-error"\n')
    runs = []
    for _ in range(2):
        r = env.rb_run("test", "--format", "json", "-a", a, env.path("circling.bas"))
        try:
            p = json.loads(r.stdout)["programs"][0]
        except (json.JSONDecodeError, IndexError, KeyError):
            raise Failure(f"rb test printed no JSON (exit {r.returncode})", r.stdout, r.stderr)
        checks = {c["name"]: c for c in p["checks"]}
        expect(checks["square"]["passed"], "the robot keeps out of the black square", checks["square"])
        expect(p["steps"] == 200000 and "the step limit (max-steps = 200000 in colour.toml)" in p["reason"],
               "stopped by the step limit", p)
        p.pop("seconds")
        runs.append(p)
    expect(runs[0] == runs[1], "graded alike twice", *runs)


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


YARD = os.path.join(HERE, "yard")


def class_grades(env, folder, *args, cls="class"):
    """rb test --format json of FOLDER/class against FOLDER/assignment.toml: (run, doc, programs by
    their path relative to FOLDER)."""
    r = env.rb_run("test", "--format", "json", "-j", "2", "-a", os.path.join(folder, "assignment.toml"),
                   os.path.join(folder, cls), *args)
    try:
        doc = json.loads(r.stdout)
    except json.JSONDecodeError:
        raise Failure(f"rb test printed no JSON (exit {r.returncode})\n{r.stdout}\n{r.stderr}")
    return r, doc, {os.path.relpath(p["program"], folder) if os.path.isabs(p["program"]) or p["program"].startswith(folder)
                    else p["program"]: p for p in doc["programs"]}


def yard_grades(env, *args):
    return class_grades(env, YARD, *args)


def case_yard(env):
    # The golden class: every verdict, grade and reason as expected.csv gives it.
    r, doc, by = yard_grades(env)
    expect(r.returncode == 1, f"exit {r.returncode}", r.stderr)
    with open(os.path.join(YARD, "expected.csv"), newline="") as f:
        rows = list(csv.reader(f))[1:]
    expect(sorted(by) == sorted(row[0] for row in rows), "the grade book lists every file and student", sorted(by))
    for program, student, result, points, *why in rows:
        why = ",".join(why)
        p = by[program]
        expect((p.get("student"), p["result"], p["points"]) == (student, result, float(points)),
               f"{program}: {p.get('student')}, {p['result']}, {p['points']}; expected {student}, {result}, {points}",
               p["reason"])
        expect(re.search(why, p["reason"]), f"{program}: reason {p['reason']!r} does not match {why!r}")
    expect(doc["summary"]["missing"] == 1 and doc["summary"]["programs"] == 12, "summary", doc["summary"])
    # Fair verdicts: nothing counts when the required check fails; `after` leaves a check unchecked.
    big = {c["name"]: c for c in by["class/big.bas"]["checks"]}
    expect(big["check"]["passed"] and big["check"]["earned"] == 0 and "required" in big["check"]["note"], "voided", big)
    ccw = {c["name"]: c for c in by["class/ccw.bas"]["checks"]}
    expect(not ccw["solution-trail"]["checked"] and ccw["solution-trail"]["message"] ==
           'not checked: needs "corners", which did not pass', "after", ccw["solution-trail"])
    expect(ccw["facing up"]["hidden"] and "facing 90 degrees" in ccw["facing up"]["message"], "hidden, teacher", ccw)
    detour = {c["name"]: c for c in by["class/detour.bas"]["checks"]}
    expect(detour["short drive"]["earned"] == 1 and detour["short drive"]["points"] == 2, "tiers", detour)
    near = {c["name"]: c for c in by["class/near_miss.bas"]["checks"]}
    expect(near["corners"]["message"] == "the robot misses point 3 (520, 180) after point 2 by 1 px: it comes within "
           "4 px, 3 px allowed", "a near miss says by how much", near["corners"])
    big_avoid = big["flower bed"]["message"]
    expect(big_avoid.startswith("the robot enters the rectangle (580, 120)-(700, 330) at ") and big_avoid.endswith(
        "(line 7)"), "avoid names where and the line", big_avoid)
    expect("crash" not in by["class/no_place.bas"]["reason"], "an unplaced robot did not crash",
           by["class/no_place.bas"]["reason"])
    # The prompt's wording does not matter; the transcript keeps it, marked.
    ben = by["class/prompt.bas"]
    expect(ben["output"].startswith("Number of sides please: 4\nsides: 4\n") and ben["inputs"][0]["start"] == 0,
           "transcript", ben)

    # The students' view: the hidden check says only that it failed, nowhere its details.
    r, sdoc, sby = yard_grades(env, "--student", "--feedback", env.path("feedback"), "--pictures",
                               env.path("pictures"))
    text = json.dumps(sdoc)
    expect("facing 90 degrees" not in text and "a hidden check failed" in text, "student JSON", text[:2000])
    with open(env.path("feedback/ccw.bas.txt")) as f:
        feedback = f.read()
    expect("a hidden check failed" in feedback and "facing 90" not in feedback and "heading" not in feedback and "7 of 12 points" in feedback and
           "hint: Start at 400, 300" in feedback and "drawn the other way round?" in feedback, "feedback file", feedback)
    pics = sorted(os.listdir(env.path("pictures")))
    expect(len(pics) == 10 and all(png_size(os.path.join(env.path("pictures"), p)) == (800, 664) for p in pics),
           "one picture per program that ran (not typo.bas, which does not compile)", pics)
    # Replays beside the pictures: each program's own run, never the solution's.
    r, rdoc, rby = yard_grades(env, "--pictures", env.path("replays"), "--replays", "html")
    ana = rby["class/correct.bas"]
    expect(ana.get("replay", "").endswith("correct.html") and os.path.getsize(ana["replay"]) > 1000, "replay", ana)
    with open(ana["replay"], encoding="utf-8") as f:
        page = f.read()
    expect(page.lstrip().lower().startswith("<!doctype html") and "http://" not in page.replace("http://www.w3.org", ""),
           "a self-contained page", page[:200])
    expect("replay" not in rby["class/empty.bas"] or os.path.exists(rby["class/empty.bas"]["replay"]), "empty", rby)
    r = env.rb_run("test", "-a", os.path.join(YARD, "assignment.toml"), "--replays", "gif", os.path.join(YARD, "class"))
    expect(r.returncode == 64 and "--pictures" in r.stderr, "--replays needs --pictures", r.stderr)
    t = env.rb_run("test", "--student", "-a", os.path.join(YARD, "assignment.toml"), os.path.join(YARD, "class"))
    expect("facing 90" not in t.stdout and "a hidden check failed" in t.stdout, "student text report", t.stdout)


def write_goal_class(env):
    """A small assignment with a world, teacher checks, colours, groups and limits."""
    # A river the robot's sensors do not see (an invisible colour) but that it must keep out of.
    env.write("world.bas", "Rectangle 300, 250, 340, 500, BLUE, BLUE\nrInvisible BLUE\nrLocate 100, 300, 90\n")
    env.write("goal.bas", 'input first\nprint "first line: " + first\n'
              'if rGPSX() < 600 then print "fail: the robot stops at x = " + rGPSX() + ", short of the finish"\n'
              'print "well driven"\n')
    env.write("solution.bas", 'print "go"\nrPen DOWN\nrTurn -90\nrForward 150\nrTurn 90\n'
              'rForward 600\nrTurn 90\nrForward 150\n')
    return env.write("goals.toml", """solution = "solution.bas"
world = "world.bas"
[[check]]
name = "river"
kind = "avoid"
colour = "blue"
hint = "Drive round the river: it is blue."
[[check]]
name = "lake"
kind = "avoid"
polygon = [[400, 400], [500, 400], [450, 480]]
[[check]]
name = "finish"
kind = "touch"
rect = [680, 250, 760, 350]
[[check]]
name = "either end"
kind = "any-of"
points = 2
[[check.of]]
kind = "ends-in"
circle = [700, 300, 30]
[[check.of]]
kind = "ends-in"
rect = [0, 0, 50, 50]
[[check]]
name = "goal"
post = "goal.bas"
after = "finish"
[[check]]
name = "tidy"
kind = "no-error"
max-statements = 12
""")


def case_goals(env):
    a = write_goal_class(env)
    good = env.write("good.bas", 'print "go"\nrTurn -90\nrForward 150\nrTurn 90\nrForward 600\nrTurn 90\nrForward 150\n')
    wet = env.write("wet.bas", 'print "go"\nrForward 200\n')
    slow = env.write("slow.bas", 'print "go"\nrTurn -90\nrForward 150\nrTurn 90\n'
                     'for i = 1 to 60\n  rForward 10\nnext\nrTurn 90\nrForward 150\n')
    r = env.rb_run("test", "--format", "json", "-a", a, good, wet, slow)
    doc = json.loads(r.stdout)
    by = {os.path.basename(p["program"]): {c["name"]: c for c in p["checks"]} for p in doc["programs"]}
    g = by["good.bas"]
    expect(all(c["passed"] for c in g.values()), "good.bas passes everything", g)
    expect(g["goal"]["message"] == "first line: go" and g["goal"]["feedback"] == ["well driven"],
           "the post program read the student's output and its prints are feedback", g["goal"])
    expect(g["either end"]["message"].startswith("ends-in: "), "any-of names the check that passed", g["either end"])
    w = by["wet.bas"]
    expect(w["river"]["message"].startswith("the robot touches blue at (") and w["river"]["message"].endswith("(line 2)"),
           "the colour it touched, where and the line", w["river"])
    expect(w["river"]["hint"] == "Drive round the river: it is blue.", "hint", w["river"])
    expect(w["finish"]["message"].startswith("the robot never reaches the rectangle (680, 250)-(760, 350): it comes within"),
           "touch says how close", w["finish"])
    expect(not w["goal"]["checked"], "after: the post check waits for finish", w["goal"])
    expect(w["either end"]["message"].startswith("none of 2 passes: "), "any-of lists the misses", w["either end"])
    sl = by["slow.bas"]
    expect(not sl["tidy"]["passed"] and sl["tidy"]["message"] ==
           "it works, but takes 127 statements: at most 12 allowed", "max-statements", sl["tidy"])
    # The post program's fail: line fails the check with its message.
    short = env.write("short.bas", 'print "go"\nrTurn -90\nrForward 150\nrTurn 90\nrForward 400\n')
    env.write("goals2.toml", open(a).read().replace('after = "finish"\n', ""))
    r = env.rb_run("test", "--format", "json", "-a", env.path("goals2.toml"), short)
    checks = {c["name"]: c for c in json.loads(r.stdout)["programs"][0]["checks"]}
    expect(checks["goal"]["message"] == "the robot stops at x = 500, short of the finish", "fail:", checks["goal"])
    # The solution graded by its own assignment: a check it fails is said; a post check it fails
    # stops grading (every student would fail it).
    env.write("goals3.toml", open(a).read() + '[[check]]\nname = "far corner"\nkind = "visits"\nwaypoints = [[10, 10]]\n')
    r = env.rb_run("test", "-q", "-a", env.path("goals3.toml"), good)
    expect("rb test: warning: the solution fails its own check 'far corner': the robot misses point 1 (10, 10)"
           in r.stderr, "warning", r.stderr)
    env.write("strict.bas", 'print "fail: never good enough"\n')
    env.write("goals4.toml", open(a).read() + '[[check]]\nname = "strict"\npost = "strict.bas"\n')
    r = env.rb_run("test", "-q", "-a", env.path("goals4.toml"), good)
    expect(r.returncode == 1 and "the solution fails its own check 'strict': never good enough" in r.stderr,
           f"exit {r.returncode}", r.stderr)


def case_class_files(env):
    # Every file of a class folder is accounted for; hidden ones (.git) are not the class's.
    cls = env.path("class")
    os.makedirs(os.path.join(cls, ".git"))
    env.write("class/.git/config", "x")
    env.write("class/a.bas", 'rLocate 400, 300\nrForward 10\n')
    env.write("class/b.bas.txt", 'rLocate 400, 300\nrForward 10\n')
    env.write("class/notes.docx", "x")
    a = env.write("a.toml", '[[check]]\nkind = "no-error"\n')
    r = env.rb_run("test", "--format", "json", "-a", a, cls)
    doc = json.loads(r.stdout)
    by = {os.path.basename(p["program"]): p for p in doc["programs"]}
    expect(sorted(by) == ["a.bas", "b.bas.txt", "notes.docx"], "every file, no .git", sorted(by))
    expect(by["b.bas.txt"]["result"] == "fail" and "saved as .bas.txt?" in by["b.bas.txt"]["reason"], "txt", by)
    expect(by["notes.docx"]["reason"] == "not graded: not a .bas file", "docx", by["notes.docx"])
    expect(r.returncode == 1, f"not graded files fail: exit {r.returncode}")
    r = env.rb_run("test", "--format", "json", "--include", "*.bas.txt", "-a", a, cls)
    by = {os.path.basename(p["program"]): p for p in json.loads(r.stdout)["programs"]}
    expect(by["b.bas.txt"]["result"] == "pass", "--include grades it", by["b.bas.txt"])
    # Bad input: exit 64 with the file and line.
    r = env.rb_run("test", "--include", "*.py", "-a", a, cls)
    expect(r.returncode == 64 and "--include '*.py' matches no file" in r.stderr, f"glob: exit {r.returncode}", r.stderr)
    env.write("roster.csv", "student,file\nAna,class/a.bas\nBen\n")
    r = env.rb_run("test", "--roster", env.path("roster.csv"), "-a", a, cls)
    expect(r.returncode == 64 and "roster.csv:3: a roster row is a student and a file" in r.stderr, "row", r.stderr)
    env.write("roster.csv", "Ana,elsewhere/a.bas\nBen,elsewhere/b.bas\n")
    r = env.rb_run("test", "--roster", env.path("roster.csv"), "-a", a, cls)
    expect(r.returncode == 64 and "the roster names no file or folder that is being graded" in r.stderr, "none", r.stderr)
    env.write("r.toml", 'roster = "nope.csv"\n')
    r = env.rb_run("test", "-a", env.path("r.toml"), cls)
    expect(r.returncode == 64 and "r.toml:1:10: roster: no such file" in r.stderr, "missing roster", r.stderr)


# --- what a student's program and file names put into the reports

def runner_commands(text):
    """Lines a GitHub Actions runner would take as workflow commands: it splits its input at CR
    and LF, trims blanks (.NET's TrimStart) and looks for `::`, and looks for the older `##[`
    anywhere in a line (actions/runner, ActionCommand.TryParseV2 and TryParse)."""
    return [l for l in re.split(r"\r\n|\r|\n", text) if l.lstrip().startswith("::") or "##[" in l]


def raw_controls(text):
    """Control characters a report must not carry (LF and tab are its own): C0, DEL, C1."""
    return sorted({f"U+{ord(c):04X}" for c in text if (ord(c) < 0x20 and c not in "\n\t") or 0x7F <= ord(c) <= 0x9F})


def hostile_class(env):
    """A class folder made here (such names cannot be kept in git): a program that clears the
    terminal, moves the cursor to print a fake "pass" row, sets the clipboard (OSC 52) and prints
    workflow commands; a file name with a line feed and a workflow command; file names that are
    spreadsheet formulas; a roster name that is one too."""
    cls = env.path("class")
    os.makedirs(cls)
    esc = ('print char(27) + "[2J" + char(27) + "[1;1Hgood.bas   pass   1/1" + char(27) + "[K"\n'
           'print char(27) + "]52;c;cm0gLXJmIH4=" + char(7) + char(155) + "2J"\n'
           'print "::error file=good.bas::forged from the output"\n'
           'print "   ::add-mask::x"\n'
           'print "  ##[error]the old form"\n')
    files = {"esc.bas": esc, "x\n::error::forged.bas": "print 1\n",
             '=HYPERLINK("http:evil","y").bas': "print 2\n", "@SUM(1).bas": "print 3\n",
             "good.bas": 'print "ok"\n'}
    for name, text in files.items():
        with open(os.path.join(cls, name), "w") as f:
            f.write(text)
    env.write("roster.csv", "student,file\n+cmd|' /C calc'!A0,class/esc.bas\nAna,class/good.bas\n")
    return cls, env.write("a.toml", 'roster = "roster.csv"\n[[check]]\nkind = "output"\ntext = "ok"\n')


def case_untrusted_text(env):
    cls, a = hostile_class(env)
    reports = {}
    # Graded from inside the folder, so that the names begin the table's lines and the CSV's cells.
    r = subprocess.run([env.rb, "test", "-a", a, ".", "--csv", env.path("grades.csv"), "--junit", env.path("junit.xml"),
                        "--feedback", env.path("feedback")], capture_output=True, timeout=300, cwd=cls)
    expect(r.returncode == 1, f"rb test: exit {r.returncode}", r.stderr)
    reports["the text report"] = r.stdout.decode("utf-8")
    reports["standard error"] = r.stderr.decode("utf-8")
    j = subprocess.run([env.rb, "test", "--format", "json", "-a", a, "."], capture_output=True, timeout=300, cwd=cls)
    reports["the JSON report"] = j.stdout.decode("utf-8")
    for name in ("grades.csv", "junit.xml"):
        with open(env.path(name), encoding="utf-8") as f:
            reports[name] = f.read()
    for name in os.listdir(env.path("feedback")):
        with open(os.path.join(env.path("feedback"), name), encoding="utf-8") as f:
            reports["feedback " + repr(name)] = f.read()
    expect(len(reports) == 5 + len(os.listdir(cls)), "a feedback file per program", sorted(reports))
    for what, text in reports.items():
        expect(not raw_controls(text), f"{what} carries raw control characters {raw_controls(text)}", text)
        expect(not runner_commands(text), f"{what} has lines a runner takes as workflow commands", runner_commands(text), text)
    text = reports["the text report"]
    # Shown, visibly: the reader sees what the program tried.
    for shown in ("x\\n::error::forged.bas", "^[[2J^[[1;1Hgood.bas   pass   1/1^[[K", "^[]52;c;cm0gLXJmIH4=^G\\x9b2J",
                  "\\x3a:error file=good.bas::forged from the output", "\\x3a:add-mask::x", "\\x23#[error]the old form"):
        expect(shown in text, f"the text report shows {shown!r}", text)
    rows = [l for l in text.splitlines() if l.startswith(("x\\n", "esc.bas")) and " FAIL " in l]
    expect(len(rows) == 2, "one table row each for the program with a line feed in its name and esc.bas", text)
    doc = json.loads(reports["the JSON report"])
    by = {p["program"]: p for p in doc["programs"]}
    expect("x\\n::error::forged.bas" in by and "^[[2J" in by["esc.bas"]["output"], "the JSON report shows the same", sorted(by))
    expect(by["esc.bas"]["student"] == "+cmd|' /C calc'!A0", "the roster's name", by["esc.bas"])
    # The grade book: a text cell never begins a formula; numbers stay numbers.
    with open(env.path("grades.csv"), newline="", encoding="utf-8") as f:
        book = list(csv.DictReader(f))
    for row in book:
        for key in ("student", "program", "reason"):
            expect(not row[key].startswith(("=", "+", "-", "@", "\t", "\r")), f"CSV {key} cell {row[key]!r} is a formula", row)
        expect(re.fullmatch(r"\d+", row["points"]) and re.fullmatch(r"\d+\.\d+", row["seconds"]), "numbers stay numbers", row)
    programs = {row["program"] for row in book}
    expect({"'=HYPERLINK(\"http:evil\",\"y\").bas", "'@SUM(1).bas"} <= programs, "formulas behind a quote", programs)
    expect("'+cmd|' /C calc'!A0" in {row["student"] for row in book}, "the roster's formula too", book)


def case_bad_goals(env):
    # Checks that contradict each other, teacher programs with errors: exit 64, file:line:col.
    write_goal_class(env)
    cases = [
        ('[[check]]\nkind = "avoid"\ncolour = "red"\n[[check]]\nkind = "touch"\ncolour = "Red"\n',
         ":4:1: checks contradict each other: 'touch' must touch red, which 'avoid' must avoid"),
        ('[[check]]\nkind = "avoid"\nrect = [0, 0, 800, 600]\n[[check]]\nkind = "ends-in"\ncircle = [400, 300, 5]\n',
         ":4:1: checks contradict each other: 'ends-in'"),
        ('[[check]]\nname = "a"\nkind = "no-error"\nafter = "b"\n[[check]]\nname = "b"\nkind = "no-crash"\n',
         ":1:1: after = 'b' names a check that comes later"),
        ('[[check]]\nname = "x"\nkind = "no-error"\n[[check]]\nname = "x"\nkind = "no-crash"\n',
         ":4:1: two checks are named 'x'"),
        ('[[check]]\nkind = "efficiency"\nmeasure = "moves"\ntiers = [[10, 1], [20, 5]]\n',
         ":4:9: tiers contradict each other"),
        ('[[check]]\nkind = "avoid"\ncolour = "gren"\n', ":3:10: unknown colour 'gren'; did you mean 'Green'?"),
        ('world = "broken.bas"\n', "broken.bas:2:1: "),
        ('[[check]]\npost = "nope.bas"\n', ":2:8: post: no such file"),
    ]
    env.write("broken.bas", "rLocate 1, 2\nrForwad 5\n")
    for text, message in cases:
        a = env.write("bad.toml", text)
        r = env.rb_run("test", "-a", a, env.write("p.bas", "rLocate 400, 300\n"))
        expect(r.returncode == 64 and message in r.stderr, f"exit {r.returncode}, expected 64 and {message!r}", text,
               r.stderr)


def case_comment_limits(env):
    # A comment's limit is named as the comment wrote it, with the line; the check's verdict
    # survives; the error output is shown once.
    prog = env.write("spin.bas", "// timeout: 1\nwhile 1\nwend\n")
    r = env.rb_run("test", prog)
    expect(r.returncode == 1, f"exit {r.returncode}", r.stdout)
    expect("did not finish: stopped at spin.bas:2:" in r.stdout and "the time limit (// timeout: 1)" in r.stdout and
           "in the loop of lines 2-3" in r.stdout, "where the limit stopped it", r.stdout)
    expect("rb check: killed" not in r.stdout, "rb check's verdict survives", r.stdout)
    expect(r.stdout.count("stopped after 1 seconds") == 1, "the error output once", r.stdout)
    # Serial ports: none unless the assignment grants them (a comment's --trust-comments run may).
    port = env.write("port.bas", "rCommPort 97\nprint rCommand(66, 0)\n")
    a = env.write("ports.toml", '[[check]]\nkind = "no-error"\n')
    r = env.rb_run("test", "--format", "json", "-a", a, port)
    reason = json.loads(r.stdout)["programs"][0]["reason"]
    expect("opens no serial port unless the assignment allows it (ports = true)" in reason, "refused", reason)
    a = env.write("ports.toml", 'ports = true\n[[check]]\nkind = "no-error"\n')
    r = env.rb_run("test", "--format", "json", "-a", a, port)
    reason = json.loads(r.stdout)["programs"][0]["reason"]
    expect("no serial device for port 97" in reason and "ports = true" not in reason, "granted: the port itself is missing", reason)
    r = env.rb_run("test", port)
    expect("opens no serial port" in r.stdout, "comment mode refuses too", r.stdout)
    # Comments may not grant access or raise limits: only the person running rb test may. What a
    # comment asked and rb test left out is said, with why.
    prog = env.write("spawn.bas", "// args: --allow-spawn --events /etc/passwd --max-steps 0 --timeout 1e300\n"
                     "// timeout: 1e300\nprint 1 // expect: 1\n")
    r = env.rb_run("test", "--format", "json", "--max-steps", "1000", prog)
    p = json.loads(r.stdout)["programs"][0]
    notes = "\n".join(p.get("notes", []))
    expect(r.returncode == 0 and p["result"] == "pass", "runs without what was left out", p)
    for part in ("ignored // args: --allow-spawn: only the person running rb test may grant it",
                 "ignored // args: --events /etc/passwd: the events file is outside the program's folder",
                 "ignored // args: --max-steps 0: a comment may lower the step limit",
                 "ignored // args: --timeout 1e300: a comment may lower the time limit",
                 "// timeout: 1e+300 counts as 30 s"):
        expect(part in notes, f"note {part!r}", notes)
    t = env.rb_run("test", prog)
    expect("note: ignored // args: --allow-spawn" in t.stdout, "the text report says it too", t.stdout)
    env.write("keys.events", "key a\n")
    ok = env.write("own.bas", "// args: --events keys.events --max-steps 500\nprint 1 // expect: 1\n")
    r = env.rb_run("test", "--format", "json", ok)
    expect("notes" not in json.loads(r.stdout)["programs"][0], "what only narrows is kept", r.stdout)
    spawn = env.write("spawn2.bas", "// args: --allow-spawn\nprint Spawn(\"true\", 0) // expect: 0\n")
    r = env.rb_run("test", spawn)
    expect(r.returncode == 1 and "Spawn" in r.stdout, "not granted: Spawn is refused", r.stdout)
    r = env.rb_run("test", "--trust-comments", spawn)
    expect(r.returncode == 0, "granted by the person running rb test", r.stdout)


MAZE = os.path.join(HERE, "maze")


def maze_grades(env, *args):
    return class_grades(env, MAZE, "--include", "*.bas.txt", *args)


def magenta_pixels(path):
    sys.path.insert(0, os.path.join(HERE, "..", "render"))
    from replay_browser import read_png  # noqa: E402
    with open(path, "rb") as f:
        w, h, rgb = read_png(f.read())
    return sum(1 for i in range(0, len(rgb), 3) if rgb[i] > 200 and rgb[i + 1] < 60 and rgb[i + 2] > 200)


def case_maze(env):
    # The second golden class: a world that places the robot, a colour to avoid, tiers, a hidden
    # post program and a roster; every verdict, grade and reason as expected.csv gives it.
    r, doc, by = maze_grades(env)
    expect(r.returncode == 1, f"exit {r.returncode}", r.stderr)
    with open(os.path.join(MAZE, "expected.csv"), newline="") as f:
        rows = list(csv.reader(f))[1:]
    expect(sorted(by) == sorted(row[0] for row in rows), "the grade book lists every file and student", sorted(by))
    for program, student, result, points, *why in rows:
        why = ",".join(why)
        p = by[program]
        expect((p.get("student"), p["result"], p["points"]) == (student, result, float(points)),
               f"{program}: {p.get('student')}, {p['result']}, {p['points']}; expected {student}, {result}, {points}",
               p["reason"])
        expect(re.search(why, p["reason"]), f"{program}: reason {p['reason']!r} does not match {why!r}")
    expect(doc["summary"]["missing"] == 1, "Ivy alone is missing (Gus's .bas.txt keeps his name)", doc["summary"])
    # rb check as the program runs: after the world, which placed the robot, no program is
    # told its robot is not placed.
    for name in ("class/ada.bas", "class/ben.bas", "class/cy.bas", "class/hal.bas"):
        check = {c["name"]: c for c in by[name]["checks"]}["check"]
        expect(check["passed"] and check["message"] == "rb check finds nothing", f"{name}: check", check)
    # The teacher sees the hidden check's words and where the lava was touched.
    cy = {c["name"]: c for c in by["class/cy.bas"]["checks"]}
    expect("does not face the exit" in cy["facing the exit"]["message"], "hidden, teacher", cy["facing the exit"])
    expect(cy["lava"]["message"].startswith("the robot touches red at ("), "where the lava was touched", cy["lava"])

    # What students see: hidden checks only as their verdict, on every page and picture; a
    # compile error once, with its line; no option that would have let an include through.
    fb, pics, html = env.path("feedback"), env.path("pictures"), env.path("html")
    r, sdoc, sby = maze_grades(env, "--student", "--feedback", fb, "--pictures", pics, "--html", html)
    everything = r.stdout
    for folder in (fb, html):
        for root, _, files in os.walk(folder):
            for name in files:
                if name.endswith((".txt", ".html", ".json")):
                    with open(os.path.join(root, name), errors="replace") as f:
                        everything += f.read()
    for secret in ("does not face the exit", "exit_check.bas", "--allow-files", "--trust-comments"):
        expect(secret not in everything, f"students see {secret!r}")
    expect("a hidden check failed" in everything, "the hidden check's verdict is shown")
    pngs = [os.path.join(root, n) for root, _, files in os.walk(env.work) for n in files if n.endswith(".png")]
    expect(pngs, "no pictures were written")
    for png in pngs:
        expect(magenta_pixels(png) == 0, f"{png}: a post program's drawing reached a student's picture")
    expect(not any("eve" in os.path.basename(p) for p in pngs), "a program that does not compile has a picture", pngs)
    with open(os.path.join(fb, "eve.bas.txt")) as f:
        eve = f.read()
    expect(eve.count("does not compile") == 1 and "hint:" not in eve, "eve: the error once, no hints", eve)
    expect('11 | print "reached in " + n " moves"' in eve, "eve: the line it is on", eve)
    # The teacher's picture of Cy says what it draws: the path, where checks failed, the lava.
    r, _, tby = maze_grades(env, "--html", env.path("teacher"))
    page = next(f for f in os.listdir(os.path.join(env.path("teacher"), "programs")) if f.startswith("cy"))
    with open(os.path.join(env.path("teacher"), "programs", page)) as f:
        text = f.read()
    for part in ("your robot&#39;s path", "where checks failed", "keep off: lava: red", "reach: goal"):
        expect(part in text or part.replace("&#39;", "'") in text, f"cy's caption names {part!r}", text[:3000])


def case_misspelt_closer(env):
    # A student's misspelt `next`: the reason is that line, which says the loop it leaves
    # open, not the loop's line (reported before it, as "for without next", until issue 28).
    prog = env.write("nxt.bas", "// The square, with next misspelt.\nrLocate 400,300\nrInvisible GREEN\n"
                     "LineWidth 4\nrPen DOWN\nfor n = 1 to 4\n  rForward 120\n  rTurn 90\nnxt\n"
                     "print \"perimeter \" + 4 * 120\n")
    code, programs, _ = env.grade(prog)
    p = programs["nxt.bas"]
    expect(code == 1 and p["result"] == "fail", f"exit {code}", p)
    expect(p["reason"] == "the program does not compile: nxt.bas:9:1: unknown command 'nxt'; did you mean 'next'? "
           "(the for at line 6 has no next)", "reason", p["reason"])
    r = env.rb_run("test", "-a", ASSIGNMENT, prog)
    row = next((l for l in r.stdout.splitlines() if "nxt.bas" in l and "FAIL" in l), "")
    expect("nxt.bas:9:1: unknown command 'nxt'; did you mean 'next'?" in row, "the text report's row", r.stdout)


def case_regex_linear(env):
    # A pattern that backtracks for ever in a backtracking engine, against a student's output:
    # RE2 matches in time linear in the line, so the class is graded at once.
    a = env.write("rx.toml", '[[check]]\nkind = "output"\nregex = ["([a-z]+)*!"]\n')
    prog = env.write("rx.bas", 'print "' + "a" * 64 + '"\n')
    r = subprocess.run([env.rb, "test", "--format", "json", "-a", a, prog], capture_output=True, text=True, timeout=20)
    p = json.loads(r.stdout)["programs"][0]
    expect(p["result"] == "fail" and "does not match" in p["reason"], "graded", p)
    bad = env.write("bad.toml", '[[check]]\nkind = "output"\nregex = ["(a"]\n')
    r = env.rb_run("test", "-a", bad, prog)
    expect(r.returncode == 64 and "bad.toml:3:9: bad regex '(a': missing )" in r.stderr, "bad pattern", r.stderr)


def case_interrupt(env):
    # Ctrl-C while programs run: every child ends with what it started (its process group), the
    # temporary files go, and rb test ends by SIGINT, as a shell expects.
    tmp = env.path("tmp")
    os.makedirs(tmp)
    os.makedirs(env.path("hung"))
    for name in ("a", "b"):
        env.write(f"hung/{name}.bas", "// timeout: 20\nwhile 1\nwend\n")
    proc = subprocess.Popen([env.rb, "test", "-j", "2", env.path("hung")], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=dict(os.environ, TMPDIR=tmp))
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline and len(children(proc.pid)) < 2:
        time.sleep(0.05)
    kids = children(proc.pid)
    expect(len(kids) == 2, "two programs running", kids)
    proc.send_signal(signal.SIGINT)
    proc.communicate(timeout=10)
    expect(proc.returncode == -signal.SIGINT, f"ended by SIGINT, not {proc.returncode}")
    alive = [k for k in kids if os.path.exists(f"/proc/{k}") and ") Z" not in open(f"/proc/{k}/stat").read()]
    expect(not alive, "no program left running", alive)
    expect(os.listdir(tmp) == [], "no temporary files left", os.listdir(tmp))


def children(pid):
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = open(f"/proc/{entry}/stat").read()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                found.append(int(entry))
    return found


def case_similarity(env):
    # A disguised copy (names, numbers, comments and layout changed) is found with its lines side
    # by side; a program of one's own is not; students never see it.
    src = open(os.path.join(YARD, "class", "detour.bas")).read()
    os.makedirs(env.path("class"))
    env.write("class/chloe.bas", src)
    disguised = (src.replace("n = ", "count = ").replace(" n\n", " count\n").replace("+ n", "+ count")
                 .replace("n *", "count *").replace("120", "110").replace("// Chloe", "' my own work")
                 .replace("  rForward", "    rForward"))
    env.write("class/copy.bas", disguised)
    env.write("class/own.bas", open(os.path.join(YARD, "class", "ccw.bas")).read())
    a = env.write("a.toml", '[[check]]\nkind = "no-error"\n')
    r = env.rb_run("test", "--format", "json", "--similarity", "-a", a, env.path("class"))
    sim = json.loads(r.stdout)["similarity"]
    expect(len(sim) == 1 and {os.path.basename(sim[0]["a"]), os.path.basename(sim[0]["b"])} == {"chloe.bas", "copy.bas"}
           and sim[0]["score"] == 1.0, "the copy and only the copy", sim)
    t = env.rb_run("test", "-q", "--similarity", "-a", a, env.path("class"))
    expect("never a verdict" in t.stdout and "| " in t.stdout, "side by side in the text report", t.stdout)
    s = env.rb_run("test", "-q", "--student", "--similarity", "-a", a, env.path("class"))
    expect("Similar code" not in s.stdout, "not in a student's report", s.stdout)


# --- rb test --merge: the shards' JSON reports of a CI matrix made into the class's reports

MERGE_REPORTS = ["--junit", "report.xml", "--csv", "grades.csv", "--html", "report", "--feedback", "feedback"]


def normalised(kind, text):
    """A report with what differs between two gradings of one class taken out: the times, the
    timestamps, the page's nonce."""
    if kind == "json":
        doc = json.loads(text)
        for p in doc["programs"]:
            p.pop("seconds")
        doc["summary"].pop("seconds")
        doc.pop("timestamp")
        return json.dumps(doc, indent=1, sort_keys=True)
    if kind == "text":
        text = re.sub(r" +\d+\.\d\ds(?=  |$)", " T", text, flags=re.M)
        return re.sub(r" in \d+\.\d\d s$", " in T s", text, flags=re.M)
    if kind == "csv":
        rows = list(csv.reader(io.StringIO(text)))
        col = rows[0].index("seconds")
        return [r[:col] + r[col + 1:] for r in rows]
    if kind == "junit":
        return re.sub(r'(time|timestamp)="[^"]*"', r'\1="T"', text)
    if kind == "html":
        text = re.sub(r"nonce-[0-9a-f]+'", "nonce-N'", text)
        text = re.sub(r'nonce="[0-9a-f]+"', 'nonce="N"', text)
        text = re.sub(r"Graded [0-9T:-]+ by rb test", "Graded T by rb test", text)
        return re.sub(r"steps, \d+\.\d\d s", "steps, T s", text)
    return text


def read(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def folder_files(path):
    return sorted(os.path.relpath(os.path.join(d, f), path) for d, _, fs in os.walk(path) for f in fs)


def same_reports(whole, merged, what):
    """Every report file of the merge in folder `merged` is the one run's in `whole`: the JSON
    and text on standard output (whole.json, whole.txt), the CSV, the JUnit report (valid for
    both schemas), the HTML pages, the feedback files, and the pictures, byte for byte."""
    for name, kind in (("out.json", "json"), ("out.txt", "text"), ("grades.csv", "csv"), ("report.xml", "junit")):
        a, b = normalised(kind, read(os.path.join(whole, name))), normalised(kind, read(os.path.join(merged, name)))
        if a != b:
            import difflib
            diff = "\n".join(difflib.unified_diff(str(a).splitlines(), str(b).splitlines(), "one run", "merged", lineterm=""))
            raise Failure(f"{what}: the merged {name} is not the one run's\n{diff[:6000]}")
    xmllint = shutil.which("xmllint")
    for schema in (SCHEMA, JENKINS_SCHEMA):
        v = subprocess.run([xmllint, "--noout", "--schema", schema, os.path.join(merged, "report.xml")],
                           capture_output=True, text=True)
        expect(v.returncode == 0, f"{what}: the merged JUnit report does not validate against {schema}", v.stderr)
    for folder in ("report", "feedback"):
        files = folder_files(os.path.join(whole, folder))
        expect(files == folder_files(os.path.join(merged, folder)), f"{what}: the merged {folder}/ has other files",
               files, folder_files(os.path.join(merged, folder)))
        for f in files:
            a, b = os.path.join(whole, folder, f), os.path.join(merged, folder, f)
            if f.endswith(".png") or "/pictures/" in "/" + f:
                expect(read(a, "rb") == read(b, "rb"), f"{what}: {folder}/{f} differs")
            else:
                expect(normalised("html", read(a)) == normalised("html", read(b)), f"{what}: {folder}/{f} differs",
                       read(b)[:3000])
    expect(len(folder_files(os.path.join(whole, "report", "pictures"))) > 0, f"{what}: the one run drew no picture")


def grade_whole(env, folder, common, paths):
    """One run over the whole class in `folder`: every report, the JSON and the text."""
    os.makedirs(folder)
    r = env.rb_run("test", *common, *MERGE_REPORTS, "--format", "json", *paths, cwd=folder)
    expect(r.returncode in (0, 1), f"one run: exit {r.returncode}", r.stderr)
    with open(os.path.join(folder, "out.json"), "w") as f:
        f.write(r.stdout)
    t = env.rb_run("test", *common, "-q", *paths, cwd=folder)
    with open(os.path.join(folder, "out.txt"), "w") as f:
        f.write(t.stdout)
    return r


def grade_shards(env, folder, common, paths, n):
    """The class as n shards in `folder`, each with its own JSON report and --html folder."""
    os.makedirs(folder)
    for k in range(1, n + 1):
        r = env.rb_run("test", *common, "--shard", f"{k}/{n}", "--format", "json", "--html", f"shard{k}", *paths,
                       cwd=folder)
        expect(r.returncode in (0, 1), f"shard {k}/{n}: exit {r.returncode}", r.stderr)
        with open(os.path.join(folder, f"shard{k}.json"), "w") as f:
            f.write(r.stdout)


def merge(env, folder, reports, *options):
    """rb test --merge in `folder`: every report, the JSON and the text."""
    r = env.rb_run("test", "--merge", *reports, *options, *MERGE_REPORTS, "--format", "json", cwd=folder)
    if r.returncode in (0, 1):
        with open(os.path.join(folder, "out.json"), "w") as f:
            f.write(r.stdout)
        t = env.rb_run("test", "--merge", *reports, *options, "-q", cwd=folder)
        with open(os.path.join(folder, "out.txt"), "w") as f:
            f.write(t.stdout)
    return r


def case_merge(env):
    if not shutil.which("xmllint"):
        raise Skip("xmllint is not installed (Debian: libxml2-utils)")
    # The square: one run over the class, and three shards merged; in folders of the same name,
    # so that the pictures' paths read alike.
    common = ["-j", "2", "-a", ASSIGNMENT]
    whole = grade_whole(env, env.path("whole"), common, [CLASS])
    grade_shards(env, env.path("split"), common, [CLASS], 3)
    shards = ["shard1.json", "shard2.json", "shard3.json"]
    m = merge(env, env.path("split"), shards)
    expect(m.returncode == whole.returncode == 1, f"merge: exit {m.returncode}, the one run's {whole.returncode}", m.stderr)
    expect(m.stderr == "", "the merge says nothing on standard error", m.stderr)
    same_reports(env.path("whole"), env.path("split"), "the square in 3 shards")
    doc = json.loads(m.stdout)
    expect(doc["summary"]["programs"] == 6 and doc["shard"] == {"index": 1, "of": 1}, "merged summary", doc["summary"])
    # The class took as long as its shards, from the first one's start to the last one's end.
    longest = max(json.loads(read(env.path(f"split/{s}")))["summary"]["seconds"] for s in shards)
    expect(doc["summary"]["seconds"] >= longest, f"merged seconds {doc['summary']['seconds']} < the longest shard's {longest}")

    # In any order, and from artifacts downloaded elsewhere (each report with its pictures folder
    # beside it, as the action uploads them), found beside the reports or where --merge-pictures says.
    art = env.path("artifacts")
    for k in (1, 2, 3):
        os.makedirs(os.path.join(art, f"report-{k}"))
        shutil.copy(env.path(f"split/shard{k}.json"), os.path.join(art, f"report-{k}", "rb-test.json"))
        shutil.copytree(env.path(f"split/shard{k}/pictures"), os.path.join(art, f"report-{k}", "pictures"))
    os.makedirs(env.path("elsewhere"))
    reports = [os.path.join(art, f"report-{k}", "rb-test.json") for k in (3, 1, 2)]
    m = merge(env, env.path("elsewhere"), reports)
    expect(m.returncode == 1, f"merge of artifacts: exit {m.returncode}", m.stderr)
    same_reports(env.path("whole"), env.path("elsewhere"), "the square's artifacts")
    pics = env.path("pics")
    for k in (1, 2, 3):
        shutil.copytree(os.path.join(art, f"report-{k}", "pictures"), os.path.join(pics, str(k)))
        shutil.rmtree(os.path.join(art, f"report-{k}", "pictures"))
    os.makedirs(env.path("given"))
    m = merge(env, env.path("given"), reports, "--merge-pictures", *[os.path.join(pics, str(k)) for k in (3, 1, 2)])
    expect(m.returncode == 1, f"merge with --merge-pictures: exit {m.returncode}", m.stderr)
    same_reports(env.path("whole"), env.path("given"), "the square with --merge-pictures")
    # Pictures nowhere to be found: an error when the merge must copy them, else a note.
    r = env.rb_run("test", "--merge", *reports, "--html", "page", cwd=env.path("given"))
    expect(r.returncode == 66 and "--merge-pictures" in r.stderr and "not found" in r.stderr,
           f"pictures not found for --html: exit {r.returncode}", r.stderr)
    r = env.rb_run("test", "--merge", *reports, "--format", "json", cwd=env.path("given"))
    named = sum(k in p for s in shards for p in json.loads(read(env.path(f"split/{s}")))["programs"]
                for k in ("picture", "screen", "replay"))
    expect(r.returncode == 1 and f"note: {named} pictures" in r.stderr, f"pictures not found, no --html: exit {r.returncode}",
           r.stderr)
    expect(not any("picture" in p for p in json.loads(r.stdout)["programs"]), "the merged JSON names no picture not found")

    # Reports that are not one class's shards.
    split = env.path("split")
    refusals = [
        (["shard1.json", "shard3.json"], 66, "shard 2 of 3 is missing"),
        (["shard1.json", "shard2.json", "shard2.json", "shard3.json"], 64, "are both shard 2 of 3"),
        (["shard1.json", "nothing.json"], 66, "cannot read the report nothing.json: no such file"),
        (["shard1.json", "grades.csv"], 64, "grades.csv: not JSON"),
    ]
    doc = json.loads(read(os.path.join(split, "shard2.json")))
    doc.pop("report_version")
    env.write("split/old.json", json.dumps(doc))
    refusals.append((["shard1.json", "old.json", "shard3.json"], 64, "older rb test"))
    doc = json.loads(read(os.path.join(split, "shard2.json")))
    doc["title"] = "circle"
    env.write("split/other.json", json.dumps(doc))
    refusals.append((["shard1.json", "other.json", "shard3.json"], 64, "of 'square', other.json (shard 2 of 3) of 'circle'"))
    shutil.copytree(SQUARE, env.path("square"), ignore=shutil.ignore_patterns("class"))
    changed = env.write("square/assignment.toml", read(ASSIGNMENT) + "\n# changed\n")
    r = env.rb_run("test", "-j", "2", "-a", changed, "--shard", "2/3", "--format", "json", CLASS)
    env.write("split/changed.json", r.stdout)
    refusals.append((["shard1.json", "changed.json", "shard3.json"], 64, "graded against one assignment"))
    r = env.rb_run("test", "-j", "2", "-a", ASSIGNMENT, "--shard", "2/4", "--format", "json", CLASS)
    env.write("split/four.json", r.stdout)
    refusals.append((["shard1.json", "four.json", "shard3.json"], 64, "split the class differently"))
    for reports, code, message in refusals:
        r = env.rb_run("test", "--merge", *reports, cwd=split)
        expect(r.returncode == code and message in r.stderr and r.stdout == "",
               f"--merge {' '.join(reports)}: exit {r.returncode} (expected {code}, saying {message!r})", r.stderr)
    # A warning (the solution fails one of its own checks) that every shard gives: said once.
    shutil.copytree(SQUARE, env.path("warned"), ignore=shutil.ignore_patterns("class"))
    warned = env.write("warned/assignment.toml", read(ASSIGNMENT) +
                       '[[check]]\nname = "far corner"\nkind = "visits"\nwaypoints = [[10, 10]]\n')
    os.makedirs(env.path("warned/shards"))
    for k in (1, 2):
        r = env.rb_run("test", "-j", "2", "-a", warned, "--shard", f"{k}/2", "--format", "json", CLASS)
        env.write(f"warned/shards/{k}.json", r.stdout)
    one = env.rb_run("test", "-j", "2", "-a", warned, "--format", "json", CLASS)
    r = env.rb_run("test", "--merge", "1.json", "2.json", "--format", "json", cwd=env.path("warned/shards"))
    warning = "rb test: warning: the solution fails its own check 'far corner'"
    expect(one.stderr.count(warning) == 1 and r.stderr.count(warning) == 1, "the warning, once", one.stderr, r.stderr)
    expect(json.loads(r.stdout)["warnings"] == json.loads(one.stdout)["warnings"], "the merged JSON's warnings are one run's",
           r.stdout[:2000])
    for args, message in ((["--merge", "shard1.json", "-a", ASSIGNMENT], "leave out --assignment"),
                          (["shard1.json", "--merge", "shard2.json"], "leave out the paths to grade"),
                          (["--merge", "shard1.json", "--student"], "leave out --student"),
                          (["--merge", "shard1.json", "shard2.json", "--merge-pictures", "x"], "one folder per report"),
                          (["--merge-pictures", "x", CLASS], "goes with --merge")):
        r = env.rb_run("test", *args, cwd=split)
        expect(r.returncode == 64 and message in r.stderr, f"rb test {' '.join(args)}: exit {r.returncode}", r.stderr)


def case_merge_roster(env):
    if not shutil.which("xmllint"):
        raise Skip("xmllint is not installed (Debian: libxml2-utils)")
    # The yard with its roster, without forever.bas (stopped by the clock, so never quite the same
    # twice): Hana and Mo have no submission, square.bas.txt is not a program, input is marked,
    # a check is hidden, the post program writes feedback; with --similarity, and a copy of
    # detour.bas that lands in another shard: only the merge can find the pair.
    yard = env.path("yard")
    shutil.copytree(YARD, yard)
    os.remove(os.path.join(yard, "class", "forever.bas"))
    shutil.copy(os.path.join(yard, "class", "detour.bas"), os.path.join(yard, "class", "zz_copy.bas"))
    common = ["-j", "2", "-a", os.path.join(yard, "assignment.toml"), "--similarity"]
    paths = [os.path.join(yard, "class")]
    grade_whole(env, env.path("whole"), common, paths)
    grade_shards(env, env.path("split"), common, paths, 3)
    shards = ["shard1.json", "shard2.json", "shard3.json"]
    missing = [[p["student"] for p in json.loads(read(env.path(f"split/{s}")))["programs"] if p["result"] == "missing"]
               for s in shards]
    expect(missing == [["Hana", "Mo"], [], []], "shard 1 lists the missing students", missing)
    # Without --similarity the shards' lists (each of its own programs) are left out, and said so.
    r = env.rb_run("test", "--merge", *shards, "--format", "json", cwd=env.path("split"))
    expect(r.returncode == 1 and "similarity" not in json.loads(r.stdout) and "give --similarity" in r.stderr,
           f"merge without --similarity: exit {r.returncode}", r.stderr)
    m = merge(env, env.path("split"), shards, "--similarity")
    expect(m.returncode == 1, f"merge: exit {m.returncode}", m.stderr)
    same_reports(env.path("whole"), env.path("split"), "the yard in 3 shards")
    doc = json.loads(m.stdout)
    expect([p["student"] for p in doc["programs"] if p["result"] == "missing"] == ["Hana", "Mo"],
           "the missing students once, last", doc["programs"])
    expect(doc["summary"]["missing"] == 2 and doc["summary"]["programs"] == 12, "merged summary", doc["summary"])
    pairs = [(os.path.basename(p["a"]), os.path.basename(p["b"])) for p in doc.get("similarity", [])]
    expect(pairs == [("detour.bas", "zz_copy.bas")], "the merge compares the whole class", pairs)
    for s in shards:  # a shard compares its own programs only (and so finds other pairs)
        found = [(os.path.basename(p["a"]), os.path.basename(p["b"])) for p in json.loads(read(env.path(f"split/{s}")))["similarity"]]
        expect(("detour.bas", "zz_copy.bas") not in found, f"{s} found the pair across shards", found)


CHALLENGES = os.path.join(HERE, "..", "..", "web", "challenges")


def grade_both(env, assignment, folder, *args):
    """The same class graded by rb test --format json with a child per run and --in-process (the
    web page's way): both documents, without their times."""
    docs = []
    for extra in ([], ["--in-process"]):
        r = env.rb_run("test", "--format", "json", "-a", assignment, *extra, *args, folder)
        try:
            doc = strip_times(json.loads(r.stdout))
        except json.JSONDecodeError:
            raise Failure(f"rb test {' '.join(extra)} printed no JSON (exit {r.returncode})\n{r.stdout}\n{r.stderr}")
        # Where a run stopped by the time limit got depends on the machine's speed, in any two
        # gradings alike (and a post program after it races the deadline's alarm): of such a
        # program, the verdict, its reason (but the statement and the step it stopped at) and
        # which checks there are.
        timed = re.compile(r"after [0-9]+ steps, the time limit")
        for n, p in enumerate(doc["programs"]):
            if timed.search(p["reason"]):
                reason = timed.sub("after N steps, the time limit", p["reason"])
                reason = re.sub(r"stopped at (\S+):[0-9]+:[0-9]+ ", r"stopped at \1:L:C ", reason)
                doc["programs"][n] = {"program": p["program"], "result": p["result"], "reason": reason,
                                      "checks": [c["name"] for c in p["checks"]]}
        docs.append(doc)
    return docs


def same_grading(env, assignment, folder, student=True):
    """Child processes and --in-process grade alike: the teacher's report but for what confined
    the runs (the kernel, or rb's own rules in its own process), and (`student`) the students'
    report whole."""
    child, inproc = grade_both(env, assignment, folder)
    expect("rb's own process" in inproc.get("confinement", ""), "--in-process says how it was confined",
           inproc.get("confinement"))
    child.pop("confinement", None)
    inproc.pop("confinement")
    expect(child == inproc, f"{folder}: --in-process grades differently",
           json.dumps(child, indent=1), json.dumps(inproc, indent=1))
    if student:
        child, inproc = grade_both(env, assignment, folder, "--student")
        expect(child == inproc, f"{folder}: --in-process --student grades differently",
               json.dumps(child, indent=1), json.dumps(inproc, indent=1))
    return {os.path.basename(p["program"]): p for p in child["programs"]}


def case_in_process(env):
    # Pass, fail, a crash, the step limit, a program that does not compile (the square), the
    # time limit and input (the yard), a world program and a hidden post check (the maze).
    programs = same_grading(env, ASSIGNMENT, CLASS)
    expect(programs["looping.bas"]["steps"] == 25000, "the step limit", programs["looping.bas"])
    for folder in ("yard", "maze"):
        same_grading(env, os.path.join(HERE, folder, "assignment.toml"), os.path.join(HERE, folder, "class"), student=False)
    # A student's program that includes the solution from the folder above its own is refused.
    os.makedirs(env.path("escape/class"))
    shutil.copy(os.path.join(SQUARE, "solution.bas"), env.path("escape/solution.bas"))
    shutil.copy(ASSIGNMENT, env.path("escape/assignment.toml"))
    env.write("escape/class/cheat.bas", '#include "../solution.bas"\n')
    programs = same_grading(env, env.path("escape/assignment.toml"), env.path("escape/class"))
    cheat = programs["cheat.bas"]
    expect(cheat["result"] == "fail" and "../solution.bas' not found" in cheat["reason"] and cheat["points"] == 0,
           "the include of ../solution.bas is refused", cheat)
    # --in-process is rb's own confinement alone: never with --require-sandbox.
    r = env.rb_run("test", "--in-process", "--require-sandbox", "-a", ASSIGNMENT, CLASS)
    expect(r.returncode == 64 and "--in-process" in r.stderr, f"exit {r.returncode}", r.stderr)


def case_challenges(env):
    # Each challenge the web page ships: its solution passes with every point, the program the
    # page starts the student with fails, and --in-process grades both alike.
    names = sorted(os.listdir(CHALLENGES))
    expect(len(names) >= 3, "at least three challenges", names)
    for name in names:
        folder = os.path.join(CHALLENGES, name)
        klass = env.path(name)
        os.makedirs(klass)
        shutil.copy(os.path.join(folder, "solution.bas"), os.path.join(klass, "ok.bas"))
        shutil.copy(os.path.join(folder, "start.bas"), os.path.join(klass, "start.bas"))
        programs = same_grading(env, os.path.join(folder, "assignment.toml"), klass)
        ok, start = programs["ok.bas"], programs["start.bas"]
        expect(ok["result"] == "pass" and ok["points"] == ok["max_points"], f"{name}: the solution passes", ok)
        expect(start["result"] == "fail" and start["points"] < start["max_points"], f"{name}: the start fails", start)


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
