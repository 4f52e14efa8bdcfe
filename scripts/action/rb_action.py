#!/usr/bin/env python3
"""The steps of rb's GitHub Action (action.yml at the repository's root), as one script the
action calls. Python 3 standard library only: it runs on GitHub's runners and in a Debian
container, and the tests run it here with GITHUB_OUTPUT, GITHUB_STEP_SUMMARY and
GITHUB_WORKSPACE set to temporary files (testdata/action/).

  rb_action.py test      runs `rb test` on the inputs (RB_* variables, below); writes the
                         reports into RB_REPORTS, a job summary, annotations and the outputs;
                         with RB_MERGE, `rb test --merge` of the shards' reports instead
  rb_action.py check     runs `rb check --format sarif` (for code scanning) and
                         `rb check --format github` (annotations); a summary and the outputs
  rb_action.py classroom REPORT.json
                         prints what GitHub Classroom's autograding reporter reads (base64 of
                         its JSON) for a report of `rb test --format json`

Inputs (environment): RB (the rb to run, default `rb`), RB_PATHS (programs and folders, split
like a shell's words; default .), RB_ASSIGNMENT, RB_OPTIONS (more options for rb, split like a
shell's words), RB_REPORTS (folder for the reports, default rb-report), RB_PICTURES (true:
--pictures), RB_FEEDBACK (true: --feedback), RB_MERGE (shard reports to merge: paths or globs,
split like a shell's words; RB_PATHS and RB_ASSIGNMENT are then not used), RB_CLASSROOM_NAME (a test's name prefix; default
none). Outputs (GITHUB_OUTPUT): see action.yml.

Both commands end with status 0 when rb ran (its own status is the exit-code output, which the
action turns into the job's result after the reports are uploaded), and 2 when they could not
do their work (no rb, no report).
"""
import base64
import glob
import html
import json
import os
import re
import secrets
import shlex
import subprocess
import sys

# GitHub's limits (docs: "Adding a job summary"): a step's summary holds at most 1 MiB; it shows
# 10 error annotations of a step and 50 of a job.
SUMMARY_LIMIT = 1000 * 1000
MAX_ANNOTATIONS = 10


def env(name, default=""):
    value = os.environ.get(name, "")
    return value if value.strip() else default


def truthy(name):
    return env(name).strip().lower() in ("1", "true", "yes", "on")


def append(path_var, text):
    """Appends text to the file a GitHub variable names (GITHUB_OUTPUT, GITHUB_STEP_SUMMARY)."""
    path = os.environ.get(path_var)
    if not path:
        return
    with open(path, "a", encoding="utf-8") as f:
        f.write(text)


def set_output(name, value):
    """One output, in the multi-line form GitHub documents (name<<DELIMITER), so any value is safe."""
    value = str(value)
    delimiter = "RB_EOF"
    while delimiter in value:
        delimiter += "_"
    append("GITHUB_OUTPUT", f"{name}<<{delimiter}\n{value}\n{delimiter}\n")


def escape_data(text):
    """A workflow command's message (GitHub's escaping: %, CR, LF)."""
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def escape_property(text):
    """A workflow command's property value: also ':' and ','."""
    return escape_data(text).replace(":", "%3A").replace(",", "%2C")


def annotation(level, message, file=None, line=None, col=None, title=None):
    props = []
    if file:
        props.append("file=" + escape_property(file))
    if line:
        props.append(f"line={line}")
    if col:
        props.append(f"col={col}")
    if title:
        props.append("title=" + escape_property(title))
    return f"::{level} {','.join(props)}::{escape_data(message)}" if props else f"::{level}::{escape_data(message)}"


def echo_untrusted(text, stream=None):
    """Text the runner must only show (rb's own error output, which quotes the students' file
    names and messages): written between ::stop-commands::TOKEN and ::TOKEN:: with a token no
    one can guess, so that no line of it is taken as a workflow command. The runner looks for
    commands in a step's standard output and error alike, in the order each arrives: all three
    go to one stream, standard output unless another is given."""
    if not text:
        return
    stream = stream or sys.stdout
    token = "rb-" + secrets.token_hex(16)
    stream.write(f"::stop-commands::{token}\n")
    stream.write(text if text.endswith("\n") else text + "\n")
    stream.write(f"::{token}::\n")
    stream.flush()


def workspace_path(path):
    """A path as GitHub's annotations want it: relative to the workspace (the repository)."""
    workspace = os.environ.get("GITHUB_WORKSPACE") or os.getcwd()
    full = os.path.abspath(path)
    try:
        rel = os.path.relpath(full, os.path.abspath(workspace))
    except ValueError:
        return path
    return path if rel.startswith("..") else rel


def cell(text):
    """Text for the job summary, which GitHub renders as Markdown: one line (blanks and line
    ends as one space), HTML's specials as character references. The summary puts it only
    inside HTML blocks (a <table>, <h2>, <p>, <pre>), where Markdown makes no link, image,
    emphasis or markup of anything: a student's `[x](url)`, `![x](url)`, `<img>` or bare URL
    stays text."""
    return html.escape(" ".join(str(text).split()), quote=True)


def code(text):
    """A student's text (a file name, a name, a message quoting their output) in <code>: shown
    as it is, and left alone by GitHub's own passes over rendered text (mentions, references)."""
    return f"<code>{cell(text)}</code>"


def points_text(value):
    """Points as rb prints them: 3 rather than 3.0, 2.5 as it is."""
    value = float(value)
    return str(int(value)) if value == int(value) else f"{value:g}"


def failed_checks(program):
    return [c for c in program.get("checks", []) if not c.get("passed")]


def failed_groups(program):
    """The failed checks as (names, message, hint), checks that fail for one reason (a program
    that does not compile) together, as rb test's own table groups them."""
    groups = []
    for c in failed_checks(program):
        key = (c.get("message", ""), c.get("hint", ""))
        for g in groups:
            if (g[1], g[2]) == key:
                g[0].append(c.get("name", ""))
                break
        else:
            groups.append(([c.get("name", "")], key[0], key[1]))
    return groups


# --- GitHub Classroom
#
# GitHub Classroom's reporter (classroom-resources/autograding-grading-reporter) reads, for each
# step id listed in its `runners` input, the environment variable <ID>_RESULTS: base64 of a JSON
# object {version, status, max_score, tests: [{name, status, score, message, test_code, filename,
# line_no, duration}]}, the shape autograding-command-grader writes. It adds up every test's
# `score` and the runners' `max_score` into the "Points X/Y" that Classroom records. So each of
# rb's checks becomes a test whose score is the points it earned, and max_score is the points
# the programs could earn. A program graded against its comments (no assignment, no points) is
# one test of 1 point, earned when it passes.

def classroom_result(report, name_prefix=""):
    programs = [p for p in report.get("programs", [])]
    several = len(programs) > 1
    tests = []
    max_score = 0.0
    for p in programs:
        label = p.get("student") or p.get("program", "")
        prefix = name_prefix + (label + ": " if several else "")
        checks = p.get("checks", [])
        if float(p.get("max_points", 0) or 0) > 0 and checks:
            max_score += float(p["max_points"])
            for c in checks:
                earned = float(c.get("earned", 0) or 0)
                points = float(c.get("points", 0) or 0)
                message = c.get("message", "")
                if c.get("hint") and not c.get("passed"):
                    message += " (hint: " + c["hint"] + ")"
                tests.append({
                    "name": f"{prefix}{c.get('name', '')} ({points_text(earned)}/{points_text(points)})",
                    "status": "pass" if c.get("passed") else "fail",
                    "score": earned,
                    "message": message,
                    "test_code": "",
                    "filename": p.get("program", ""),
                    "line_no": 0,
                    "duration": 0,
                })
        else:
            passed = p.get("result") == "pass"
            max_score += 1
            status = "pass" if passed else ("error" if p.get("result") == "error" else "fail")
            tests.append({
                "name": prefix + (p.get("program", "") if not several else "passes"),
                "status": status,
                "score": 1 if passed else 0,
                "message": p.get("reason", ""),
                "test_code": "",
                "filename": p.get("program", ""),
                "line_no": 0,
                "duration": int(round(float(p.get("seconds", 0) or 0) * 1000)),
            })
    results = [t["status"] for t in tests]
    status = "error" if "error" in results else ("fail" if "fail" in results or not tests else "pass")
    # Whole numbers stay integers in the JSON (the reporter prints them as they are).
    for t in tests:
        if float(t["score"]) == int(t["score"]):
            t["score"] = int(t["score"])
    return {
        "version": 1,
        "status": status,
        "max_score": int(max_score) if max_score == int(max_score) else max_score,
        "tests": tests,
    }


def classroom_error(message):
    """What the reporter reads when rb could not grade at all (a broken assignment, no programs)."""
    return {"version": 1, "status": "error", "max_score": 0,
            "tests": [{"name": "rb test", "status": "error", "score": 0, "message": message,
                       "test_code": "", "filename": "", "line_no": 0, "duration": 0}]}


def encode(result):
    return base64.b64encode(json.dumps(result, ensure_ascii=False).encode("utf-8")).decode("ascii")


# --- rb test

ERROR_LINE = re.compile(r"^(?P<file>[^\n:]+):(?P<line>\d+):(?P<col>\d+): (?:error|runtime error): ", re.M)


def error_location(program):
    """The first `file:line:col: error:` of a program's error output, as a path in the workspace."""
    m = ERROR_LINE.search(program.get("errors", "") or "")
    if not m:
        return None
    name = m.group("file")
    base = os.path.dirname(program.get("program", ""))
    for candidate in (name, os.path.join(base, name)):
        if os.path.isfile(candidate):
            return workspace_path(candidate), int(m.group("line")), int(m.group("col"))
    if os.path.basename(name) == os.path.basename(program.get("program", "")):
        return workspace_path(program["program"]), int(m.group("line")), int(m.group("col"))
    return None


def summary_markdown(report, exit_code, reports_dir):
    """The job summary: a heading, the totals, and a table with a row per program. What comes
    from the report is in HTML blocks with its text escaped (cell()): nothing a student wrote
    becomes a link, an image or markup. Each block has no blank line inside, which would end it."""
    s = report.get("summary", {})
    programs = report.get("programs", [])
    points = sum(float(p.get("points", 0) or 0) for p in programs)
    max_points = sum(float(p.get("max_points", 0) or 0) for p in programs)
    title = report.get("title") or "rb test"
    lines = [f"<h2>{cell(title)}</h2>", ""]
    total = f"{s.get('programs', len(programs))} programs: {s.get('passed', 0)} passed, {s.get('failed', 0)} failed"
    for key in ("errors", "skipped", "missing"):
        if s.get(key):
            total += f", {s[key]} {'not graded' if key == 'errors' else key}"
    if max_points > 0:
        total += f"; {points_text(points)} of {points_text(max_points)} points"
    lines += [("✅ " if exit_code == 0 else "❌ ") + total, ""]
    has_students = any(p.get("student") for p in programs)
    head = ["program"] + (["student"] if has_students else []) + ["result", "points", "failed checks"]
    lines.append("<table>")
    lines.append("<tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr>")
    rows = []
    for p in programs:
        failed = failed_groups(p)
        if failed:
            why = "<br>".join(f"<b>{cell(', '.join(names))}</b>: {code(message)}" + (f" (hint: {cell(hint)})" if hint else "")
                              for names, message, hint in failed)
        else:
            why = code(p["reason"]) if p.get("reason") else ""
        pts = f"{points_text(p.get('points', 0))}/{points_text(p.get('max_points', 0))}" if p.get("max_points") else ""
        row = [code(p.get("program", ""))] + ([code(p["student"]) if p.get("student") else ""] if has_students else [])
        row += [("pass" if p.get("result") == "pass" else f"<b>{cell(p.get('result', '').upper())}</b>"), pts, why]
        rows.append("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>")
    text = "\n".join(lines) + "\n"
    shown = 0
    for r in rows:
        if len(text.encode("utf-8")) + len(r.encode("utf-8")) > SUMMARY_LIMIT - 500:
            break
        text += r + "\n"
        shown += 1
    text += "</table>\n"
    if shown < len(rows):
        text += f"\n<p>{len(rows) - shown} more programs are in the report ({code(reports_dir + '/rb-test.json')}).</p>\n"
    return text + "\n"


def failure_summary(heading, what, why):
    """The summary when rb could not do its work: its error output in a <pre> block, escaped."""
    return f"<h2>{cell(heading)}</h2>\n\n❌ {what}:\n\n<pre>{html.escape(why, quote=True)}</pre>\n\n"


def annotations_for(report):
    out = []
    for p in report.get("programs", []):
        if p.get("result") == "pass" or p.get("result") == "skipped":
            continue
        failed = failed_groups(p)
        pts = f" ({points_text(p.get('points', 0))} of {points_text(p.get('max_points', 0))} points)" if p.get("max_points") else ""
        title = f"rb test: {p.get('student') or os.path.basename(p.get('program', ''))} {p.get('result', '')}s{pts}"
        if failed:
            message = "\n".join(f"{', '.join(names)}: {message}" + (f" (hint: {hint})" if hint else "")
                                for names, message, hint in failed)
        else:
            message = p.get("reason", "") or p.get("result", "")
        where = error_location(p)
        if where:
            out.append(annotation("error", message, where[0], where[1], where[2], title))
        elif p.get("program") and os.path.isfile(p["program"]):
            out.append(annotation("error", message, workspace_path(p["program"]), title=title))
        else:
            out.append(annotation("error", message, title=title))
    if len(out) > MAX_ANNOTATIONS:
        rest = len(out) - (MAX_ANNOTATIONS - 1)
        out = out[:MAX_ANNOTATIONS - 1] + [annotation("error", f"{rest} more programs failed: see the job summary")]
    return out


def rb_command():
    return shlex.split(env("RB", "rb"))


def merged_reports(patterns):
    """The shard reports RB_MERGE names: each word a path or a glob (`shards/*/rb-test.json`),
    expanded and sorted; a word that matches nothing is passed on as it is, for rb to say so."""
    found = []
    for word in shlex.split(patterns):
        matches = sorted(glob.glob(word, recursive=True)) if glob.has_magic(word) else []
        for path in matches or [word]:
            if path not in found:
                found.append(path)
    return found


def run_test():
    reports = env("RB_REPORTS", "rb-report")
    os.makedirs(reports, exist_ok=True)
    merging = env("RB_MERGE")
    cmd = rb_command() + ["test", "--format", "json",
                          "--junit", os.path.join(reports, "junit.xml")]
    if env("RB_ASSIGNMENT") and not merging:
        cmd += ["--assignment", env("RB_ASSIGNMENT")]
    if env("RB_ASSIGNMENT") or merging:
        cmd += ["--csv", os.path.join(reports, "grades.csv")]
    if truthy("RB_PICTURES"):
        cmd += ["--pictures", os.path.join(reports, "pictures")]
    if truthy("RB_FEEDBACK"):
        cmd += ["--feedback", os.path.join(reports, "feedback")]
    cmd += shlex.split(env("RB_OPTIONS"))
    if merging:
        # The shards' reports (rb test --shard K/N, downloaded from their jobs' artifacts) made
        # into the class's: nothing is graded, so the paths and the assignment are not used.
        cmd += ["--merge"] + merged_reports(merging)
    else:
        cmd += shlex.split(env("RB_PATHS", "."))
    print("rb_action: " + " ".join(shlex.quote(c) for c in cmd), flush=True)
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    except OSError as e:
        print(annotation("error", f"cannot run rb: {e}", title="rb test"))
        set_output("exit-code", 2)
        return 2
    stderr = proc.stderr.decode("utf-8", "replace")
    echo_untrusted(stderr)
    set_output("exit-code", proc.returncode)
    set_output("report", os.path.join(reports, "rb-test.json"))
    try:
        report = json.loads(proc.stdout.decode("utf-8"))
    except ValueError:
        report = None
    if proc.returncode not in (0, 1) or report is None:
        # rb graded nothing: a mistake in the assignment or the command line, a missing path.
        why = stderr.strip() or f"rb test ended with status {proc.returncode} and no report"
        print(annotation("error", why, title=f"rb test could not grade (exit {proc.returncode})"))
        append("GITHUB_STEP_SUMMARY", failure_summary("rb test", f"rb test could not grade (exit status {proc.returncode})", why))
        set_output("result", encode(classroom_error(why)))
        for name in ("points", "max-points", "programs", "passed", "failed"):
            set_output(name, 0)
        set_output("passed-all", "false")
        return 0
    with open(os.path.join(reports, "rb-test.json"), "wb") as f:
        f.write(proc.stdout)
    write_test_results(report, proc.returncode, reports)
    return 0


def write_test_results(report, exit_code, reports):
    programs = report.get("programs", [])
    s = report.get("summary", {})
    append("GITHUB_STEP_SUMMARY", summary_markdown(report, exit_code, reports))
    for line in annotations_for(report):
        print(line)
    points = sum(float(p.get("points", 0) or 0) for p in programs)
    max_points = sum(float(p.get("max_points", 0) or 0) for p in programs)
    set_output("points", points_text(points))
    set_output("max-points", points_text(max_points))
    set_output("programs", s.get("programs", len(programs)))
    set_output("passed", s.get("passed", 0))
    set_output("failed", s.get("failed", 0) + s.get("errors", 0) + s.get("missing", 0))
    set_output("passed-all", "true" if exit_code == 0 else "false")
    set_output("result", encode(classroom_result(report, env("RB_CLASSROOM_NAME"))))


# --- rb check

def run_check():
    reports = env("RB_REPORTS", "rb-report")
    os.makedirs(reports, exist_ok=True)
    sarif_path = os.path.join(reports, "rb.sarif")
    paths = shlex.split(env("RB_PATHS", "."))
    options = shlex.split(env("RB_OPTIONS"))
    base = rb_command() + ["check"] + options
    print("rb_action: " + " ".join(shlex.quote(c) for c in base + ["--format", "sarif"] + paths), flush=True)
    try:
        sarif = subprocess.run(base + ["--format", "sarif"] + paths, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        github = subprocess.run(base + ["--format", "github"] + paths, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    except OSError as e:
        print(annotation("error", f"cannot run rb: {e}", title="rb check"))
        set_output("exit-code", 2)
        return 2
    echo_untrusted(sarif.stderr.decode("utf-8", "replace"))
    set_output("exit-code", sarif.returncode)
    try:
        log = json.loads(sarif.stdout.decode("utf-8"))
    except ValueError:
        why = sarif.stderr.decode("utf-8", "replace").strip() or f"rb check ended with status {sarif.returncode}"
        print(annotation("error", why, title="rb check"))
        append("GITHUB_STEP_SUMMARY", failure_summary("rb check", f"rb check wrote no SARIF log (exit status {sarif.returncode})", why))
        return 0
    with open(sarif_path, "wb") as f:
        f.write(sarif.stdout)
    # The annotations are rb check's own (--format github); GitHub shows 10 errors of a step.
    sys.stdout.write(github.stdout.decode("utf-8", "replace"))
    counts = {"error": 0, "warning": 0, "note": 0}
    files = set()
    for run in log.get("runs", []):
        for r in run.get("results", []):
            counts[r.get("level", "warning")] = counts.get(r.get("level", "warning"), 0) + 1
            for loc in r.get("locations", []):
                uri = loc.get("physicalLocation", {}).get("artifactLocation", {}).get("uri")
                if uri:
                    files.add(uri)
    set_output("sarif", sarif_path)
    set_output("errors", counts.get("error", 0))
    set_output("warnings", counts.get("warning", 0))
    mark = "✅" if sarif.returncode == 0 else "❌"
    append("GITHUB_STEP_SUMMARY",
           f"<h2>rb check</h2>\n\n<p>{mark} {counts.get('error', 0)} errors, {counts.get('warning', 0)} warnings, "
           f"{counts.get('note', 0)} notes in {len(files)} files; the SARIF log is {code(sarif_path)}.</p>\n\n")
    return 0


def main(argv):
    if len(argv) >= 2 and argv[1] == "test":
        return run_test()
    if len(argv) >= 2 and argv[1] == "check":
        return run_check()
    if len(argv) == 3 and argv[1] == "classroom":
        with open(argv[2], encoding="utf-8") as f:
            print(encode(classroom_result(json.load(f), env("RB_CLASSROOM_NAME"))))
        return 0
    sys.stderr.write("usage: rb_action.py test | check | classroom REPORT.json\n")
    return 64


if __name__ == "__main__":
    sys.exit(main(sys.argv))
