#!/usr/bin/env python3
"""Diagnostics as users and machines see them.

    diag_test.py --rb RB [--update] transcript FILE.t...
    diag_test.py --rb RB structure FILE.bas...
    diag_test.py --rb RB rules SOURCE_DIR

transcript: each FILE.t is a list of commands and their full output, as a terminal shows it:

    $ rb check --color=never arity.bas
    arity.bas:3:12: error: ...
    ...
    [exit 65]

Every command runs in this folder (`rb` is the binary under test) with standard error merged
into standard output after it; the text after the `$` line up to `[exit N]` must match
exactly. With --update the .t files are rewritten from what rb prints now: review the change
with `git diff` before committing it.

structure: runs `rb check --format json`, `--format sarif` and `--format github` on each
program and checks what their consumers need: gcc's JSON shape (kind, message, option,
locations with caret/start/finish, children, fixits), SARIF 2.1.0 as GitHub code scanning reads
it (version, $schema, runs[].tool.driver.name and rules, results with ruleId, ruleIndex, level,
message.text and physicalLocation with artifactLocation.uri and a region), and one
`::error file=...,line=...,col=...,title=...::message` line per diagnostic.
"""
import argparse
import difflib
import json
import os
import re
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run(rb, command):
    argv = shlex.split(command)
    if argv[0] == "rb":
        argv[0] = rb
    env = dict(os.environ)
    env.pop("NO_COLOR", None)
    r = subprocess.run(argv, cwd=HERE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=60, env=env)
    out = r.stdout.decode("utf-8", "replace") + r.stderr.decode("utf-8", "replace")
    if out and not out.endswith("\n"):
        out += "\n"
    return out + f"[exit {r.returncode}]\n"


def transcript(rb, path, update):
    text = open(path, encoding="utf-8").read()
    blocks = re.split(r"^(?=\$ )", text, flags=re.M)
    header = blocks[0] if not blocks[0].startswith("$ ") else ""
    actual = header
    for block in blocks:
        if not block.startswith("$ "):
            continue
        command = block.splitlines()[0][2:]
        actual += "$ " + command + "\n" + run(rb, command)
        # keep blank separator lines between commands
        if block.endswith("\n\n"):
            actual += "\n"
    if update:
        with open(path, "w", encoding="utf-8") as f:
            f.write(actual)
        print(f"wrote {path}")
        return True
    if actual != text:
        print(f"{path}: rb's output differs:")
        sys.stdout.writelines(difflib.unified_diff(text.splitlines(True), actual.splitlines(True),
                                                   "expected", "actual"))
        return False
    return True


def check_position(p, where, problems):
    for key in ("file", "line", "column"):
        if key not in p:
            problems.append(f"{where}: no {key}")
    if p.get("line", 1) < 1 or p.get("column", 1) < 1:
        problems.append(f"{where}: line and column are 1-based")


def check_gcc_json(doc, problems):
    if not isinstance(doc, list):
        problems.append("json: not an array")
        return 0
    stopped = STOPPED.match(doc[-1].get("message", "")) if doc else None
    if stopped:  # --max-errors' note: the last item, a note without a location or a rule
        if doc[-1].get("kind") != "note" or doc[-1].get("locations"):
            problems.append("json: the --max-errors note is not a note without a location")
        doc = doc[:-1]
    for i, d in enumerate(doc):
        where = f"json[{i}]"
        for key in ("kind", "message", "locations", "children"):
            if key not in d:
                problems.append(f"{where}: no {key}")
        if d.get("kind") not in ("error", "warning", "note"):
            problems.append(f"{where}: kind {d.get('kind')!r}")
        if not str(d.get("option", "")).startswith("rb-"):
            problems.append(f"{where}: no rule code in option")
        for j, loc in enumerate(d.get("locations", [])):
            if "caret" not in loc:
                problems.append(f"{where}.locations[{j}]: no caret")
                continue
            if "line" in loc["caret"]:
                check_position(loc["caret"], f"{where}.locations[{j}].caret", problems)
            if ("start" in loc) != ("finish" in loc):
                problems.append(f"{where}.locations[{j}]: start without finish")
            if "finish" in loc and loc["finish"]["column"] < loc["start"]["column"]:
                problems.append(f"{where}.locations[{j}]: finish before start")
        for c in d.get("children", []):
            if c.get("kind") != "note":
                problems.append(f"{where}: a child that is not a note")
        for f in d.get("fixits", []):
            for key in ("start", "next", "string"):
                if key not in f:
                    problems.append(f"{where}: fixit without {key}")
    return len(doc)


# What every format says when --max-errors stops it.
STOPPED = re.compile(r"stopped after \d+ errors \(--max-errors; --max-errors 0 shows them all\)$")


def check_sarif(doc, problems):
    if doc.get("version") != "2.1.0":
        problems.append("sarif: version is not 2.1.0")
    if "sarif" not in doc.get("$schema", ""):
        problems.append("sarif: no $schema")
    runs = doc.get("runs")
    if not isinstance(runs, list) or len(runs) != 1:
        problems.append("sarif: runs is not one run")
        return 0
    if runs[0].get("columnKind") != "utf16CodeUnits":
        problems.append("sarif: run.columnKind is not utf16CodeUnits")
    driver = runs[0].get("tool", {}).get("driver", {})
    if driver.get("name") != "rb":
        problems.append("sarif: tool.driver.name is not rb")
    rules = driver.get("rules")
    if not isinstance(rules, list):
        problems.append("sarif: no tool.driver.rules")
        rules = []
    ids = [r.get("id") for r in rules]
    for r in rules:
        for key in ("shortDescription", "fullDescription"):
            if not r.get(key, {}).get("text"):
                problems.append(f"sarif: rule {r.get('id')} has no {key}.text")
        if r.get("defaultConfiguration", {}).get("level") not in ("error", "warning", "note"):
            problems.append(f"sarif: rule {r.get('id')} has no defaultConfiguration.level")
        if not str(r.get("helpUri", "")).startswith("https://"):
            problems.append(f"sarif: rule {r.get('id')} has no helpUri")
    for inv in runs[0].get("invocations", []):
        if not isinstance(inv.get("executionSuccessful"), bool):
            problems.append("sarif: an invocation without executionSuccessful")
        for n in inv.get("toolExecutionNotifications", []):
            if not STOPPED.match(n.get("message", {}).get("text", "")):
                problems.append(f"sarif: unexpected notification {n!r}")
    results = runs[0].get("results")
    if not isinstance(results, list):
        problems.append("sarif: no results")
        return 0
    for i, res in enumerate(results):
        where = f"sarif.results[{i}]"
        if res.get("ruleId") not in ids:
            problems.append(f"{where}: ruleId {res.get('ruleId')!r} is not among the rules")
        elif ids[res.get("ruleIndex", -1)] != res["ruleId"]:
            problems.append(f"{where}: ruleIndex does not point at its rule")
        if res.get("level") not in ("error", "warning", "note"):
            problems.append(f"{where}: level {res.get('level')!r}")
        if not res.get("message", {}).get("text"):
            problems.append(f"{where}: no message.text")
        locs = res.get("locations", [])
        if not locs:
            problems.append(f"{where}: no locations")
        for loc in locs:
            phys = loc.get("physicalLocation", {})
            if not phys.get("artifactLocation", {}).get("uri"):
                problems.append(f"{where}: no artifactLocation.uri")
            region = phys.get("region")
            if region is not None and "startColumn" not in region:
                # a whole-file finding: its lines
                if not isinstance(region.get("startLine"), int) or region.get("endLine", 0) < region["startLine"]:
                    problems.append(f"{where}: a whole-file region without startLine/endLine")
            elif region is not None:
                for key in ("startLine", "startColumn", "endLine", "endColumn"):
                    if not isinstance(region.get(key), int) or region[key] < 1:
                        problems.append(f"{where}: region.{key} missing or not 1-based")
                if region.get("endColumn", 2) <= region.get("startColumn", 1):
                    problems.append(f"{where}: endColumn is not after startColumn (it is exclusive)")
    return len(results)


def structure(rb, files):
    problems = []
    for path in files:
        name = os.path.relpath(os.path.abspath(path), HERE)
        text = run(rb, f"rb check --format json {shlex.quote(name)}")
        body, _, code = text.rpartition("[exit ")
        doc = json.loads(body)
        n_json = check_gcc_json(doc, problems)
        json_stopped = bool(doc) and bool(STOPPED.match(doc[-1].get("message", "")))
        text = run(rb, f"rb check --format sarif {shlex.quote(name)}")
        body, _, _ = text.rpartition("[exit ")
        sarif = json.loads(body)
        n_sarif = check_sarif(sarif, problems)
        sarif_stopped = any(inv.get("toolExecutionNotifications") for inv in sarif["runs"][0].get("invocations", []))
        if json_stopped != sarif_stopped:
            problems.append(f"{name}: --max-errors stopped the JSON ({json_stopped}) and SARIF ({sarif_stopped}) differently")
        text = run(rb, f"rb check --format github {shlex.quote(name)}")
        lines = text.splitlines()[:-1]
        if lines and lines[-1].startswith("::notice title=rb check::") and STOPPED.match(lines[-1].split("::")[-1]):
            lines = lines[:-1]  # --max-errors' notice
        for line in lines:
            if not re.fullmatch(r"::(error|warning|notice) file=[^,:]+(,line=\d+,col=\d+(,endColumn=\d+)?)?"
                                r"(,title=rb-[a-z0-9-]+)?::.+", line):
                problems.append(f"github: malformed line {line!r}")
        if not (n_json == n_sarif == len(lines)):
            problems.append(f"{name}: {n_json} JSON diagnostics, {n_sarif} SARIF results, {len(lines)} GitHub lines")
        if n_json == 0:
            problems.append(f"{name}: no diagnostics at all (a structure test needs some)")
    for p in problems:
        print(p)
    print(f"{len(files)} programs, {len(problems)} problems")
    return not problems


def rules(source):
    """Every rule code the sources use is in the rule table (core/base/rules.cpp) and
    documented in docs/diagnostics.md, and every documented code is in the table."""
    table_src = open(os.path.join(source, "core", "base", "rules.cpp"), encoding="utf-8").read()
    table = set(re.findall(r'\{"(rb-[a-z0-9-]+)", Severity::', table_src))
    used = set()
    for folder in ("core", "cmd", "lsp", "grade"):
        for root, _, files in os.walk(os.path.join(source, folder)):
            for f in files:
                if f.endswith(".cpp") and not f.endswith("_test.cpp") and f != "rules.cpp":
                    text = open(os.path.join(root, f), encoding="utf-8").read()
                    used |= set(re.findall(r'"(rb-[a-z0-9]+(?:-[a-z0-9]+)+)"', text))
    docs = open(os.path.join(source, "docs", "diagnostics.md"), encoding="utf-8").read()
    documented = set(re.findall(r'<a id="(rb-[a-z0-9-]+)"></a>', docs))
    problems = [f"{c}: used in the sources but not in the rule table" for c in sorted(used - table)]
    problems += [f"{c}: in the rule table but not documented in docs/diagnostics.md" for c in sorted(table - documented)]
    problems += [f"{c}: documented but not in the rule table" for c in sorted(documented - table)]
    for p in problems:
        print(p)
    print(f"{len(table)} rules, {len(used)} used in the sources, {len(problems)} problems")
    return not problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rb", required=True)
    ap.add_argument("--update", action="store_true")
    ap.add_argument("mode", choices=["transcript", "structure", "rules"])
    ap.add_argument("files", nargs="+", help="transcripts, programs, or (rules) the source folder")
    a = ap.parse_args()
    rb = os.path.abspath(a.rb)
    if a.mode == "rules":
        return 0 if rules(a.files[0]) else 1
    if a.mode == "structure":
        return 0 if structure(rb, a.files) else 1
    ok = all([transcript(rb, f, a.update) for f in a.files])
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
