#!/usr/bin/env python3
"""rb's GitHub Action (action.yml) with no runner: its scripts (scripts/action/) run here with
the files and variables a runner gives a step (GITHUB_OUTPUT, GITHUB_STEP_SUMMARY, GITHUB_PATH,
GITHUB_WORKSPACE), on the square class of testdata/grade/square. What they write is checked
against what rb itself wrote in the same run (its CSV grade book, rb check's own output), and
the Classroom result is read by GitHub Classroom's own reporter (its source, run under node:
testdata/action/classroom-reporter/).

Usage: action_test.py PATH/TO/rb SOURCE_DIR [--part NAME]  (parts: test, classroom, untrusted,
merge, check, install, yaml; default all). Exit 77 when a part needs node and it is missing.
"""
import base64
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

RB = os.path.abspath(sys.argv[1])
SRC = os.path.abspath(sys.argv[2])
PART = sys.argv[sys.argv.index("--part") + 1] if "--part" in sys.argv else "all"
ACTION = os.path.join(SRC, "scripts", "action")
REPORTER = os.path.join(SRC, "testdata", "action", "classroom-reporter")
problems = []
checked = 0


def check(ok, what):
    global checked
    checked += 1
    if not ok:
        problems.append(what)
        print("FAIL " + what)
    return ok


def read_outputs(path):
    """GITHUB_OUTPUT as the runner reads it: NAME=VALUE lines and NAME<<DELIMITER blocks."""
    outputs = {}
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        if "<<" in line and ("=" not in line or line.index("<<") < line.index("=")):
            name, delimiter = line.split("<<", 1)
            value = []
            i += 1
            while lines[i] != delimiter:
                value.append(lines[i])
                i += 1
            outputs[name] = "\n".join(value)
        elif "=" in line:
            name, value = line.split("=", 1)
            outputs[name] = value
        i += 1
    return outputs


def parse_commands(stdout):
    """Workflow commands (::error file=F,line=L::message) with GitHub's unescaping."""
    def unescape(s, prop):
        s = s.replace("%0D", "\r").replace("%0A", "\n")
        if prop:
            s = s.replace("%3A", ":").replace("%2C", ",")
        return s.replace("%25", "%")
    out = []
    for line in stdout.splitlines():
        m = re.match(r"^::(\w+)(?: ([^:]*))?::(.*)$", line)
        if not m:
            continue
        props = {}
        if m.group(2):
            for kv in m.group(2).split(","):
                k, _, v = kv.partition("=")
                props[k] = unescape(v, True)
        out.append((m.group(1), props, unescape(m.group(3), False)))
    return out


class Step:
    """A temporary workspace with the files a runner gives a step."""

    def __init__(self):
        self.dir = tempfile.mkdtemp(prefix="rb-action-")
        self.ws = os.path.join(self.dir, "workspace")
        os.makedirs(self.ws)
        for name in ("output", "summary", "path", "env"):
            open(os.path.join(self.dir, name), "w").close()

    def run(self, args, **env_vars):
        env = dict(os.environ)
        for k in list(env):
            if k.startswith("RB_") or k.startswith("INPUT_"):
                del env[k]
        env.update(GITHUB_OUTPUT=os.path.join(self.dir, "output"),
                   GITHUB_STEP_SUMMARY=os.path.join(self.dir, "summary"),
                   GITHUB_PATH=os.path.join(self.dir, "path"),
                   GITHUB_ENV=os.path.join(self.dir, "env"),
                   GITHUB_WORKSPACE=self.ws, RUNNER_TEMP=self.dir, RB=RB)
        env.update(env_vars)
        return subprocess.run(args, cwd=self.ws, env=env, capture_output=True, text=True, timeout=300)

    def outputs(self):
        return read_outputs(os.path.join(self.dir, "output"))

    def summary(self):
        with open(os.path.join(self.dir, "summary"), encoding="utf-8") as f:
            return f.read()

    def close(self):
        shutil.rmtree(self.dir, ignore_errors=True)


def square_class(step):
    shutil.copytree(os.path.join(SRC, "testdata", "grade", "square"), os.path.join(step.ws, "square"))


def grade_book(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def number(text):
    return float(text) if text else 0.0


def run_reporter(result, runner="rb"):
    """GitHub Classroom's reporter on a result, as its action runs: INPUT_RUNNERS and
    <RUNNER>_RESULTS in the environment. Returns (exit status, stdout)."""
    env = dict(os.environ)
    env["INPUT_RUNNERS"] = runner
    env[runner.upper() + "_RESULTS"] = result
    p = subprocess.run(["node", os.path.join(REPORTER, "src", "main.js")], env=env,
                       capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout + p.stderr


def have_node():
    return shutil.which("node") and os.path.isdir(os.path.join(REPORTER, "node_modules", "@actions", "core"))


# --- mode test on the square class

def part_test_and_classroom(do_test, do_classroom):
    step = Step()
    try:
        square_class(step)
        p = step.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "test"],
                     RB_PATHS="square/class", RB_ASSIGNMENT="square/assignment.toml",
                     RB_REPORTS="rb-report", RB_PICTURES="true", RB_FEEDBACK="true")
        check(p.returncode == 0, f"rb_action.py test: exit {p.returncode} (0 once rb ran): {p.stderr[-500:]}")
        out = step.outputs()
        reports = os.path.join(step.ws, "rb-report")
        book = grade_book(os.path.join(reports, "grades.csv"))
        points = sum(number(r["points"]) for r in book)
        max_points = sum(number(r["max_points"]) for r in book)
        failed = [r for r in book if r["result"] != "pass"]
        if do_test:
            check(out.get("exit-code") == "1", f"exit-code output {out.get('exit-code')!r}: rb test fails a class with failures (1)")
            check(number(out.get("points")) == points and number(out.get("max-points")) == max_points,
                  f"points {out.get('points')}/{out.get('max-points')}, the grade book says {points}/{max_points}")
            check(out.get("programs") == str(len(book)) and out.get("failed") == str(len(failed))
                  and out.get("passed") == str(len(book) - len(failed)) and out.get("passed-all") == "false",
                  f"programs/passed/failed outputs {out}")
            for name in ("rb-test.json", "junit.xml", "grades.csv"):
                check(os.path.isfile(os.path.join(reports, name)), f"the reports folder has {name}")
            pngs = os.listdir(os.path.join(reports, "pictures")) if os.path.isdir(os.path.join(reports, "pictures")) else []
            # Every program that ran has a picture; one that does not compile has none.
            check(len([n for n in pngs if n.endswith(".png")]) == len(book) - 1 and "not_compiling.png" not in pngs,
                  f"one picture per program that ran: {pngs}")
            feedback = os.listdir(os.path.join(reports, "feedback")) if os.path.isdir(os.path.join(reports, "feedback")) else []
            check(len(feedback) == len(book), f"one feedback file per program: {feedback}")
            check(out.get("report") == os.path.join("rb-report", "rb-test.json"), f"report output {out.get('report')!r}")

            # The summary: an HTML table, a row per program with its points and its failed checks.
            summary = step.summary()
            rows = [l for l in summary.splitlines() if l.startswith("<tr><td>")]
            check(len(rows) == len(book), f"summary: {len(rows)} rows for {len(book)} programs:\n{summary}")
            header = [l for l in summary.splitlines() if l.startswith("<tr><th>program")]
            check(header and header[0].count("<th>") == rows[0].count("<td>") if rows else False, "summary: header and rows have the same columns")
            check_names = [k for k in book[0].keys()][9:]
            for r in book:
                row = next((l for l in rows if "<code>" + r["program"] + "</code>" in l), "")
                check(row, f"summary has a row for {r['program']}")
                want = f"{r['points']}/{r['max_points']}"
                check(f"<td>{want}</td>" in row, f"summary row of {r['program']} shows {want}: {row}")
                check(("<td>pass</td>" in row) == (r["result"] == "pass"), f"summary row of {r['program']}: result {r['result']}")
                # Every check the grade book gives no points (of a failing program) is named in its row.
                for c in check_names:
                    if r["result"] != "pass" and r[c] == "0":
                        check(re.search(r"<b>[^<]*\b" + re.escape(c) + r"\b[^<]*</b>", row),
                              f"summary row of {r['program']} names the failed check {c}: {row}")
            check(summary.count("❌") == 1, "summary: one ❌ total line for a failing class")

            # Annotations: one error per failed program, on a file of the workspace; a program that
            # does not compile is marked where rb check says.
            anns = [a for a in parse_commands(p.stdout) if a[0] == "error"]
            check(len(anns) == len(failed), f"{len(anns)} error annotations for {len(failed)} failed programs:\n{p.stdout}")
            for kind, props, message in anns:
                check(os.path.isfile(os.path.join(step.ws, props.get("file", "?"))), f"annotation file {props.get('file')} is in the workspace")
            ref = subprocess.run([RB, "check", "--format", "github", "square/class/not_compiling.bas"], cwd=step.ws,
                                 capture_output=True, text=True)
            want = [a for a in parse_commands(ref.stdout) if a[0] == "error"][0][1]
            got = [a[1] for a in anns if a[1].get("file") == want["file"]]
            check(got and got[0].get("line") == want["line"] and got[0].get("col") == want["col"],
                  f"not_compiling.bas annotated at {got}, rb check --format github says {want}")
            crash = [a for a in anns if a[1].get("file", "").endswith("crashing.bas")]
            check(crash and "no-error" in crash[0][2] and crash[0][1].get("line"), f"crashing.bas annotated at its line with the failed checks: {crash}")

        if do_classroom:
            result = out.get("result", "")
            doc = json.loads(base64.b64decode(result))
            # The shape autograding-command-grader writes (its generateResult), which the reporter reads.
            check(doc.get("version") == 1 and doc.get("status") in ("pass", "fail", "error")
                  and isinstance(doc.get("max_score"), (int, float)) and isinstance(doc.get("tests"), list),
                  f"classroom result's top level: {list(doc)}")
            for t in doc.get("tests", []):
                check(set(t) >= {"name", "status", "score", "message", "test_code", "filename", "line_no", "duration"},
                      f"classroom test fields: {sorted(t)}")
            if not have_node():
                print("SKIPPED (classroom reporter): node or testdata/action/classroom-reporter/node_modules missing (scripts/setup.sh --test installs them)")
                return "skip"
            code, text = run_reporter(result)
            m = re.search(r"::notice title=Autograding report::(\{.*\})", text)
            check(m, f"the reporter wrote its Autograding report notice:\n{text}")
            if m:
                totals = json.loads(m.group(1))
                check(totals == {"totalPoints": points, "maxPoints": max_points},
                      f"the reporter's points {totals}, the grade book's {points}/{max_points}")
            passed_checks = sum(int(r["checks_passed"]) for r in book)
            all_checks = sum(int(r["checks"]) for r in book)
            check(text.count("✅") == passed_checks and text.count("❌") == all_checks - passed_checks,
                  f"the reporter lists {text.count('✅')} passed and {text.count('❌')} failed checks; the grade book {passed_checks} of {all_checks}")
            check(code != 0 and "::error::Some tests failed." in text, f"the reporter fails a failing class (exit {code})")
    finally:
        step.close()


def part_classroom_pass_and_error():
    if not have_node():
        return "skip"
    # One program that passes: the reporter passes it with all its points.
    step = Step()
    try:
        square_class(step)
        step.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "test"],
                 RB_PATHS="square/class/correct.bas", RB_ASSIGNMENT="square/assignment.toml",
                 RB_PICTURES="false", RB_FEEDBACK="false")
        out = step.outputs()
        book = grade_book(os.path.join(step.ws, "rb-report", "grades.csv"))
        code, text = run_reporter(out.get("result", ""), "grade")
        check(out.get("exit-code") == "0" and out.get("passed-all") == "true", f"correct.bas passes: {out.get('exit-code')}")
        check(f"Points {book[0]['points']}/{book[0]['max_points']}" in text and code == 0 and "::error::" not in text,
              f"the reporter passes correct.bas with {book[0]['points']}/{book[0]['max_points']} (exit {code}):\n{text}")
    finally:
        step.close()
    # An assignment rb refuses: no grade, an error the reporter shows.
    step = Step()
    try:
        square_class(step)
        path = os.path.join(step.ws, "square", "assignment.toml")
        with open(path, encoding="utf-8") as f:
            text = f.read().replace("tolerance = 3\n", "tolerence = 3\n", 1)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        p = step.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "test"],
                     RB_PATHS="square/class", RB_ASSIGNMENT="square/assignment.toml")
        out = step.outputs()
        ref = subprocess.run([RB, "test", "-a", "square/assignment.toml", "square/class"], cwd=step.ws, capture_output=True, text=True)
        check(out.get("exit-code") == str(ref.returncode) and ref.returncode == 64, f"a broken assignment: exit-code {out.get('exit-code')}, rb says {ref.returncode}")
        check("tolerence" in step.summary() and "could not grade" in step.summary(), f"the summary says why:\n{step.summary()}")
        anns = parse_commands(p.stdout)
        check(anns and anns[0][0] == "error" and "tolerence" in anns[0][2], f"an error annotation says why: {p.stdout}")
        code, text = run_reporter(out.get("result", ""))
        check(code != 0 and "Error:" in text and "tolerence" in text, f"the reporter shows the error (exit {code}):\n{text}")
    finally:
        step.close()


# --- what students write reaches the runner and the summary only as text

def runner(stdout):
    """The workflow commands a GitHub runner carries out for a step's output, as actions/runner
    reads it (ActionCommandManager, ActionCommand): lines end at CR or LF; `::NAME props::data`
    after leading blanks, or the older `##[NAME props]data` anywhere in a line; between
    ::stop-commands::TOKEN and ::TOKEN:: nothing but the resume is carried out. Returns
    (name, properties, data) of each command carried out, stop and resume left out."""
    done, token = [], None
    for line in re.split(r"\r\n|\r|\n", stdout):
        text = line.lstrip()
        m = re.match(r"::([^ :]+)(?: ([^:]*))?::(.*)$", text) if text.startswith("::") else None
        if not m:
            old = re.search(r"##\[([^\] ]+)(?: ([^\]]*))?\](.*)$", line)
            m = old
        if not m:
            continue
        name = m.group(1)
        if token is not None:
            if name.lower() == token.lower():
                token = None
            continue
        if name == "stop-commands":
            token = m.group(3)
            continue
        props = dict(kv.partition("=")[::2] for kv in (m.group(2) or "").split(",") if kv)
        done.append((name, props, m.group(3)))
    return done


def summary_tags(summary):
    """The HTML a job summary renders to: GitHub's own renderer (cmark-gfm with its extensions,
    raw HTML kept as GitHub keeps it before its sanitizer) when it is installed, else the raw
    HTML blocks as they are. Returns (the HTML, its tags, whether cmark-gfm rendered it)."""
    import html.parser
    cmark = shutil.which("cmark-gfm")
    rendered = summary
    if cmark:
        rendered = subprocess.run([cmark, "--unsafe", "-e", "table", "-e", "autolink", "-e", "strikethrough"],
                                  input=summary, capture_output=True, text=True, check=True).stdout
    tags = []

    class Tags(html.parser.HTMLParser):
        def handle_starttag(self, tag, attrs):
            tags.append((tag, dict(attrs)))

    Tags().feed(rendered)
    return rendered, tags, bool(cmark)


def hostile_class(ws):
    cls = os.path.join(ws, "class")
    os.makedirs(cls)
    out = ('print "see [my page](https://evil.example/x) ![pixel](https://evil.example/t.png) '
           '<img src=x onerror=alert(1)> https://evil.example www.evil.example @octocat"\n'
           'print "::error file=square.bas::forged from the output"\n'
           'print "  ::add-mask::x"\n'
           'print "##[warning]the old form"\n'
           'print char(27) + "[2J" + char(27) + "]52;c;cm0gLXJmIH4=" + char(7)\n')
    files = {"out.bas": out, "x\n::error::forged.bas": "print 1\n", "[click](javascript:alert(1)).bas": "print 2\n",
             "<img src=x onerror=alert(2)>.bas": "print 3\n", "good.bas": 'print "ok"\n'}
    for name, text in files.items():
        with open(os.path.join(cls, name), "w") as f:
            f.write(text)
    with open(os.path.join(ws, "a.toml"), "w") as f:
        f.write('[[check]]\nkind = "output"\ntext = "ok"\n')
    return len(files) - 1


ALLOWED_TAGS = {"h2", "p", "table", "tr", "th", "td", "code", "b", "br", "pre", "thead", "tbody"}


def part_untrusted():
    step = Step()
    try:
        failing = hostile_class(step.ws)
        p = step.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "test"],
                     RB_PATHS="class", RB_ASSIGNMENT="a.toml", RB_PICTURES="false")
        check(p.returncode == 0, f"rb_action.py test on the hostile class: exit {p.returncode}: {p.stderr[-500:]}")
        done = runner(p.stdout)
        check(len(done) == failing and all(c[0] == "error" and c[1].get("title", "").startswith("rb test%3A") for c in done),
              f"the runner carries out only the action's {failing} annotations, not a student's line:\n{done}\n{p.stdout}")
        check(not runner(p.stderr), f"no command on standard error: {runner(p.stderr)}")
        summary = step.summary()
        rendered, tags, real = summary_tags(summary)
        check(not [t for t in tags if t[0] not in ALLOWED_TAGS],
              f"the summary renders only the action's own markup{' (cmark-gfm)' if real else ''}: "
              f"{[t for t in tags if t[0] not in ALLOWED_TAGS]}\n{rendered}")
        check(not [t for t in tags if t[1]], f"no attributes (links, sources, handlers): {[t for t in tags if t[1]]}")
        for shown in ("[my page](https://evil.example/x)", "![pixel](https://evil.example/t.png)", "&lt;img src=x",
                      "[click](javascript:alert(1)).bas", "&lt;img src=x onerror=alert(2)&gt;.bas"):
            check(shown in rendered, f"the summary shows {shown!r} as text:\n{rendered}")
        if not real:
            print("(cmark-gfm is not installed: the summary's HTML was read as it is; scripts/setup.sh --test installs it)")
    finally:
        step.close()

    # rb's error output is shown, never obeyed; the summary has it in <pre>, escaped.
    step = Step()
    try:
        fake = os.path.join(step.dir, "fake_rb.py")
        with open(fake, "w") as f:
            f.write("import sys\nsys.stderr.write('rb test: x\\n::error::forged\\n  ::add-mask::y\\n##[warning]z\\n"
                    "```\\n[link](https://evil.example) </pre><img src=x>\\n')\nsys.exit(64)\n")
        p = step.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "test"], RB=f"{sys.executable} {fake}")
        done = runner(p.stdout)
        check(len(done) == 1 and done[0][0] == "error" and "could not grade" in done[0][1].get("title", ""),
              f"one annotation, the action's own: {done}\n{p.stdout}")
        check("::error::forged" in p.stdout, f"rb's error output is still shown in the log:\n{p.stdout}")
        check(not runner(p.stderr), f"no command on standard error: {runner(p.stderr)}")
        rendered, tags, real = summary_tags(step.summary())
        check(not [t for t in tags if t[0] not in ALLOWED_TAGS or t[1]], f"only the action's own markup: {tags}\n{rendered}")
        check("[link](https://evil.example) &lt;/pre&gt;&lt;img src=x&gt;" in rendered, f"rb's error output as text:\n{rendered}")
    finally:
        step.close()


# --- merge: a matrix of shards, then a job that merges their artifacts

def part_merge():
    """Three shard jobs (rb test --shard K/3, each in a workspace of its own, uploading its
    reports folder), then the merge job: the artifacts downloaded as actions/download-artifact
    lays them out (shards/report-K/, one folder per artifact), the action with `merge`. Its
    outputs, summary, annotations, grade book, pictures and feedback are those of one job that
    grades the whole class."""
    def grade(**inputs):
        step = Step()
        square_class(step)
        p = step.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "test"], RB_PICTURES="true",
                     RB_FEEDBACK="true", **inputs)
        check(p.returncode == 0, f"rb_action.py test {inputs}: exit {p.returncode}: {p.stderr[-500:]}")
        return step, p

    steps = []
    try:
        whole, whole_p = grade(RB_PATHS="square/class", RB_ASSIGNMENT="square/assignment.toml")
        steps.append(whole)
        merging = Step()
        steps.append(merging)
        square_class(merging)  # the merge job checks out the repository too: annotations point into it
        for k in (1, 2, 3):
            shard, _ = grade(RB_PATHS="square/class", RB_ASSIGNMENT="square/assignment.toml", RB_OPTIONS=f"--shard {k}/3")
            steps.append(shard)
            check(shard.outputs().get("programs") == "2", f"shard {k}/3 grades 2 programs: {shard.outputs()}")
            shutil.copytree(os.path.join(shard.ws, "rb-report"), os.path.join(merging.ws, "shards", f"report-{k}"))
        p = merging.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "test"], RB_PICTURES="true",
                        RB_FEEDBACK="true", RB_MERGE="shards/*/rb-test.json")
        check(p.returncode == 0, f"rb_action.py test with merge: exit {p.returncode}: {p.stderr[-500:]}")
        check("--merge shards/report-1/rb-test.json shards/report-2/rb-test.json shards/report-3/rb-test.json" in p.stdout,
              f"the glob expanded in order:\n{p.stdout}")
        got, want = merging.outputs(), whole.outputs()
        for name in ("exit-code", "points", "max-points", "programs", "passed", "failed", "passed-all"):
            check(got.get(name) == want.get(name), f"merge output {name}: {got.get(name)!r}, one job's {want.get(name)!r}")
        result = json.loads(base64.b64decode(got.get("result", "")))
        want_result = json.loads(base64.b64decode(want.get("result", "")))
        for t in result["tests"] + want_result["tests"]:
            t.pop("duration")
        check(result == want_result, "the Classroom result of the merge is one job's")
        strip = lambda text: re.sub(r'(time|timestamp)="[^"]*"', r'\1="T"', text)
        check(merging.summary() == whole.summary(), f"the merge's summary is one job's:\n{merging.summary()}\n{whole.summary()}")
        errors = lambda stdout: [a for a in parse_commands(stdout) if a[0] == "error"]
        check(errors(p.stdout) == errors(whole_p.stdout) and errors(p.stdout),
              f"the merge's annotations are one job's:\n{p.stdout}")
        mine, theirs = os.path.join(merging.ws, "rb-report"), os.path.join(whole.ws, "rb-report")
        check([{k: v for k, v in r.items() if k != "seconds"} for r in grade_book(os.path.join(mine, "grades.csv"))] ==
              [{k: v for k, v in r.items() if k != "seconds"} for r in grade_book(os.path.join(theirs, "grades.csv"))],
              "the merged grade book is one job's")
        for folder in ("pictures", "feedback"):
            names = sorted(os.listdir(os.path.join(theirs, folder)))
            check(sorted(os.listdir(os.path.join(mine, folder))) == names, f"the merge's {folder}/ has one job's files")
            for n in names:
                with open(os.path.join(mine, folder, n), "rb") as a, open(os.path.join(theirs, folder, n), "rb") as b:
                    check(a.read() == b.read(), f"{folder}/{n} is one job's")
        with open(os.path.join(mine, "junit.xml")) as a, open(os.path.join(theirs, "junit.xml")) as b:
            check(strip(a.read()) == strip(b.read()), "the merged JUnit report is one job's")

        # A shard's artifact missing: the merge grades nothing and says why.
        shutil.rmtree(os.path.join(merging.ws, "shards", "report-2"))
        again = Step()
        steps.append(again)
        shutil.copytree(os.path.join(merging.ws, "shards"), os.path.join(again.ws, "shards"))
        p = again.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "test"], RB_MERGE="shards/*/rb-test.json")
        out = again.outputs()
        check(out.get("exit-code") == "66" and out.get("passed-all") == "false",
              f"a shard missing: exit-code {out.get('exit-code')}")
        check("shard 2 of 3 is missing" in again.summary() and "could not grade" in again.summary(),
              f"the summary says which shard is missing:\n{again.summary()}")
    finally:
        for step in steps:
            step.close()


# --- mode check

def part_check():
    step = Step()
    try:
        square_class(step)
        p = step.run([sys.executable, os.path.join(ACTION, "rb_action.py"), "check"], RB_PATHS="square/class")
        out = step.outputs()
        ref = subprocess.run([RB, "check", "square/class"], cwd=step.ws, capture_output=True, text=True)
        errors = len(re.findall(r"^\S+:\d+:\d+: error: ", ref.stdout + ref.stderr, re.M))
        warnings = len(re.findall(r"^\S+:\d+:\d+: warning: ", ref.stdout + ref.stderr, re.M))
        check(out.get("exit-code") == str(ref.returncode), f"check exit-code {out.get('exit-code')}, rb check's {ref.returncode}")
        check(out.get("errors") == str(errors) and out.get("warnings") == str(warnings),
              f"errors/warnings outputs {out.get('errors')}/{out.get('warnings')}, rb check prints {errors}/{warnings}")
        sarif = os.path.join(step.ws, out.get("sarif", "?"))
        if check(os.path.isfile(sarif), f"the SARIF log {out.get('sarif')} is written"):
            with open(sarif, encoding="utf-8") as f:
                log = json.load(f)
            check(log.get("version") == "2.1.0" and log.get("runs"), "the SARIF log is SARIF 2.1.0 with runs")
        anns = [a for a in parse_commands(p.stdout) if a[0] == "error"]
        check(len(anns) == errors, f"{len(anns)} error annotations for rb check's {errors} errors")
        check(f"{errors} errors, {warnings} warnings" in step.summary(), f"summary: {step.summary()}")
    finally:
        step.close()


# --- install.sh

def part_install():
    step = Step()
    try:
        install = os.path.join(ACTION, "install.sh")
        with open(os.path.join(SRC, "CMakeLists.txt"), encoding="utf-8") as f:
            version = re.search(r"^project\(rb VERSION ([0-9.]+)", f.read(), re.M).group(1)
        p = step.run(["bash", install, "version"])
        out = step.outputs()
        check(p.returncode == 0 and out.get("version") == version, f"install.sh version: {out}, CMakeLists.txt says {version}")
        check(re.fullmatch(r"rb-\S+-" + re.escape(version) + r"-[0-9a-f]{16}", out.get("key", "")), f"cache key {out.get('key')!r}")
        empty = os.path.join(step.dir, "releases")
        os.makedirs(empty)
        p = step.run(["bash", install, "release", version], RB_RELEASE_BASE="file://" + empty)
        check(p.returncode == 0 and step.outputs().get("installed") == "false",
              f"a release with no package: build from source (exit {p.returncode}, {step.outputs()}): {p.stdout}{p.stderr}")
        p = step.run(["bash", install, "release", "99.0.0"], RB_RELEASE_BASE="file://" + empty)
        check(p.returncode != 0 and "99.0.0" in p.stderr, f"another version with no package fails and says so: {p.returncode} {p.stderr}")
        p = step.run(["bash", install, "path", "/opt/rb-x"])
        with open(os.path.join(step.dir, "path"), encoding="utf-8") as f:
            check(f.read() == "/opt/rb-x/bin\n", "install.sh path: PREFIX/bin on GITHUB_PATH")
    finally:
        step.close()


# --- action.yml itself: every input, step and output it names exists

def part_yaml():
    if not have_node():
        return "skip"
    js = ("const y=require('js-yaml'),fs=require('fs');"
          "process.stdout.write(JSON.stringify(y.load(fs.readFileSync(process.argv[1],'utf8'))))")
    p = subprocess.run(["node", "-e", js, os.path.join(SRC, "action.yml")], cwd=REPORTER, capture_output=True, text=True)
    if not check(p.returncode == 0, f"action.yml parses as YAML: {p.stderr}"):
        return
    action = json.loads(p.stdout)
    check(action.get("runs", {}).get("using") == "composite", "a composite action")
    steps = action["runs"]["steps"]
    ids = {s["id"] for s in steps if "id" in s}
    with open(os.path.join(SRC, "action.yml"), encoding="utf-8") as f:
        text = f.read()
    for name in set(re.findall(r"inputs\.([\w-]+)", text)):
        check(name in action["inputs"], f"action.yml uses input {name}, which it declares")
    for sid, name in set(re.findall(r"steps\.([\w-]+)\.outputs\.([\w-]+)", text)):
        check(sid in ids, f"action.yml reads step {sid}, which exists")
    with open(os.path.join(ACTION, "rb_action.py"), encoding="utf-8") as f:
        written = set(re.findall(r'set_output\("([\w-]+)"', f.read()))
    with open(os.path.join(ACTION, "install.sh"), encoding="utf-8") as f:
        written |= set(re.findall(r"\bout ([\w-]+) ", f.read()))
    written |= {"cache-hit"}
    for sid, name in set(re.findall(r"steps\.([\w-]+)\.outputs\.([\w-]+)", text)):
        check(name in written, f"action.yml reads output {name} of step {sid}, which a script writes")
    for s in steps:
        if "uses" in s:
            check(re.fullmatch(r"[\w-]+/[\w/-]+@v\d+", s["uses"]), f"{s['uses']} is pinned to a major version")
        else:
            check(s.get("shell") == "bash", f"a run step names its shell: {s}")
    for script in set(re.findall(r"\$GITHUB_ACTION_PATH/([\w/.-]+)", text)):
        check(os.path.isfile(os.path.join(SRC, script)), f"action.yml runs {script}, which exists")


def main():
    skipped = []
    if PART in ("all", "test", "classroom"):
        if part_test_and_classroom(PART in ("all", "test"), PART in ("all", "classroom")) == "skip":
            skipped.append("classroom")
    if PART in ("all", "classroom"):
        if part_classroom_pass_and_error() == "skip":
            skipped.append("classroom")
    if PART in ("all", "untrusted"):
        part_untrusted()
    if PART in ("all", "merge"):
        part_merge()
    if PART in ("all", "check"):
        part_check()
    if PART in ("all", "install"):
        part_install()
    if PART in ("all", "yaml"):
        if part_yaml() == "skip":
            skipped.append("yaml")
    print(f"{checked - len(problems)} passed, {len(problems)} failed")
    if problems:
        return 1
    if skipped and PART != "all":
        print("SKIPPED: node or the reporter's packages are missing (scripts/setup.sh --test installs them)")
        return 77
    return 0


if __name__ == "__main__":
    sys.exit(main())
