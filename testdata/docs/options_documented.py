#!/usr/bin/env python3
"""Every option `rb CMD --help` lists is described in man/rb-CMD.1 (and, for rb test, in
docs/teaching.md too). Usage: options_documented.py PATH/TO/rb SOURCE_DIR CMD"""
import re
import subprocess
import sys

rb, src, cmd = sys.argv[1:4]
helptext = subprocess.run([rb, cmd, "--help"], capture_output=True, text=True).stdout
options = sorted(set(re.findall(r"(--[a-z][a-z-]*)", helptext)) - {"--help"})
if not options:
    sys.exit(f"rb {cmd} --help lists no options")
with open(f"{src}/man/rb-{cmd}.1") as f:
    man = f.read().replace("\\-", "-")
missing = [o for o in options if o not in man]
if cmd == "test":
    with open(f"{src}/docs/teaching.md") as f:
        docs = f.read()
    missing += [f"{o} (docs/teaching.md)" for o in options if o not in docs and o not in ("--seed", "--jobs")]
if missing:
    sys.exit(f"rb {cmd}: options not described: {', '.join(missing)}")
print(f"rb {cmd}: all {len(options)} options described")
