#!/usr/bin/env python3
"""Writes docs/builtins.md from rb's built-in table (rb check --list-builtins --format json).

Usage: gen_builtins_doc.py PATH/TO/rb [OUTPUT]      (OUTPUT defaults to standard output)
       gen_builtins_doc.py PATH/TO/rb --check FILE  (exit 1 when FILE is not up to date)
"""
import json
import subprocess
import sys

GROUPS = [
    ("constant", "Constants"),
    ("colour", "Colours"),
    ("math", "Math"),
    ("string", "Strings and conversion"),
    ("time", "Time"),
    ("robot", "The robot"),
    ("graphics", "Graphics"),
    ("input", "Keyboard, mouse and dialogs"),
    ("array", "Arrays"),
    ("system", "Clipboard, files and other programs"),
]


def render(table):
    out = ["# Built-in commands, functions and constants", "",
           "Generated from rb's built-in table by `scripts/gen_builtins_doc.py`; do not edit.",
           "Names ignore case. Commands take their arguments after a space (`rForward 120`),",
           "functions in parentheses (`rRange(45)`). In a signature `[...]` is optional,",
           "`name...` may repeat, and `&name` must be a variable that receives a result.", ""]
    seen = set()
    order = [g for g, _ in GROUPS] + sorted({b["group"] for b in table} - {g for g, _ in GROUPS})
    titles = dict(GROUPS)
    for group in order:
        rows = [b for b in table if b["group"] == group]
        if not rows:
            continue
        out += [f"## {titles.get(group, group.capitalize())}", ""]
        if rows[0]["kind"] == "constant" and all(b["kind"] == "constant" for b in rows):
            out += ["| name | value |", "|---|---|"]
            for b in rows:
                out.append(f"| `{b['name']}` | {b['help']} |")
        else:
            out += ["| usage | kind | what it does |", "|---|---|---|"]
            for b in rows:
                usage = b["usage"].replace("|", "\\|")
                text = b["help"].replace("|", "\\|")
                out.append(f"| `{usage}` | {b['kind']} | {text} |")
        out.append("")
        seen.add(group)
    return "\n".join(out)


def main():
    rb = sys.argv[1]
    table = json.loads(subprocess.run([rb, "check", "--list-builtins", "--format", "json"],
                                      check=True, capture_output=True, text=True).stdout)
    text = render(table)
    if len(sys.argv) > 3 and sys.argv[2] == "--check":
        with open(sys.argv[3], encoding="utf-8") as f:
            if f.read() != text:
                print(f"{sys.argv[3]} is out of date: run scripts/gen_builtins_doc.py {rb} {sys.argv[3]}")
                return 1
        return 0
    if len(sys.argv) > 2:
        with open(sys.argv[2], "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
