#!/usr/bin/env python3
"""rb's machine formats read by the tools they are for, none written here.

    consumers.py --rb RB gcc-columns
        gcc is the reference for its own JSON format: for lines whose units differ (tabs, accents,
        combining marks, CJK text, emoji), a C file and a RobotBASIC file with the same bytes
        before an unknown name `zork` are checked by gcc (-fdiagnostics-format=json) and by rb
        (--format json); the caret's column, display-column and byte-column must be the same.

    consumers.py --rb RB --tools DIR sarif-multitool PROGRAM...
        Microsoft's SARIF Multitool (npm @microsoft/sarif-multitool, installed in DIR by
        scripts/setup.sh --test) validates rb check --format sarif of each program (and of the
        first under a name with a space, '#', '%', '?' and accents) against the
        SARIF 2.1.0 schema and its rules, with GitHub code scanning's rules (--rule-kind Sarif;Gh):
        any result it reports fails the test.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

PREFIXES = [
    "",
    "\t",
    "\t\t",
    "/*ab*/\t",
    "/* \u00e9t\u00e9 */ ",                 # accents: two bytes, one column
    "/* e\u0301 */ ",                        # e and a combining accent: no column for the accent
    "/* \u4e2d\u6587\u5b57 */ ",             # CJK: three bytes, two columns each
    "/* \U0001F600 */ ",                     # an emoji: four bytes, two columns
    "\t/* \uac00\t\U0001F916x */ ",          # Hangul, a tab after a wide character, an emoji
]


def caret(doc):
    for d in doc:
        for loc in d.get("locations", []):
            c = loc.get("caret", {})
            if c.get("line") == 1:
                return {k: c.get(k) for k in ("column", "display-column", "byte-column")}
    return None


def gcc_columns(rb):
    gcc = shutil.which("gcc")
    if not gcc:
        print("gcc is not installed (scripts/setup.sh installs it)")
        return False
    ok = True
    with tempfile.TemporaryDirectory() as work:
        for i, prefix in enumerate(PREFIXES):
            c = os.path.join(work, f"p{i}.c")
            bas = os.path.join(work, f"p{i}.bas")
            with open(c, "w", encoding="utf-8") as f:
                f.write(prefix + "zork;\n")
            with open(bas, "w", encoding="utf-8") as f:
                f.write(prefix + "zork\n")
            g = subprocess.run([gcc, "-fsyntax-only", "-fdiagnostics-format=json", c],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
            r = subprocess.run([rb, "check", "--format", "json", bas], stdout=subprocess.PIPE)
            want = caret(json.loads(g.stderr or g.stdout))
            got = caret(json.loads(r.stdout))
            if want is None or got != want:
                print(f"prefix {prefix!r}: gcc {want}, rb {got}")
                ok = False
            else:
                print(f"prefix {prefix!r}: {got}")
    print(f"{len(PREFIXES)} lines, {'same as gcc' if ok else 'differences'}")
    return ok


def sarif_multitool(rb, tools, programs):
    tool = os.path.join(tools, "node_modules", "@microsoft", "sarif-multitool-linux", "Sarif.Multitool")
    if not os.access(tool, os.X_OK):
        print(f"{tool} is missing: run scripts/setup.sh --test (npm ci in tools/)")
        return False
    problems = 0
    with tempfile.TemporaryDirectory() as work:
        # The first program once more under a name a URI cannot carry as it is: a space, '#',
        # '%', '?' and a non-ASCII letter (its artifact uri must be percent-encoded).
        odd = os.path.join(work, "odd name #1 %? \u00e9t\u00e9.bas")
        shutil.copyfile(programs[0], odd)
        for prog in list(programs) + [odd]:
            log = os.path.join(work, os.path.basename(prog) + ".sarif")
            out = os.path.join(work, os.path.basename(prog) + ".validation.sarif")
            r = subprocess.run([rb, "check", "--format", "sarif", os.path.basename(prog)],
                               cwd=os.path.dirname(os.path.abspath(prog)), stdout=subprocess.PIPE)
            with open(log, "wb") as f:
                f.write(r.stdout)
            results = json.loads(r.stdout)["runs"][0]["results"]
            v = subprocess.run([tool, "validate", "--rule-kind", "Sarif;Gh", "--output", out, log],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
            if not os.path.exists(out):
                print(f"{prog}: the Multitool wrote no validation log:\n{v.stdout.decode(errors='replace')}")
                problems += 1
                continue
            found = json.load(open(out, encoding="utf-8"))["runs"][0].get("results", [])
            for res in found:
                args = res.get("message", {}).get("arguments", [])
                print(f"{prog}: {res.get('ruleId')} {res.get('level', 'warning')}: {args}")
            problems += len(found)
            print(f"{prog}: {len(results)} results, {len(found)} findings")
    print(f"{len(programs) + 1} logs, {problems} findings")
    return problems == 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rb", required=True)
    ap.add_argument("--tools")
    ap.add_argument("mode", choices=["gcc-columns", "sarif-multitool"])
    ap.add_argument("programs", nargs="*")
    a = ap.parse_args()
    rb = os.path.abspath(a.rb)
    if a.mode == "gcc-columns":
        return 0 if gcc_columns(rb) else 1
    return 0 if sarif_multitool(rb, a.tools, a.programs) else 1


if __name__ == "__main__":
    sys.exit(main())
