#!/usr/bin/env python3
"""Writes a class of N programs of the seed's size (Figure 1.7: a square of side 120 from
400,300, plus its perimeter) into FOLDER/class, with the teacher's solution and assignment in
FOLDER, for timing rb test. The mix: most programs correct (written several ways), some with
three sides, a wrong side, a crash into the screen's edge, a typo, or the wrong output.
Usage: gen.py FOLDER [N]"""
import os
import random
import sys

folder = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
os.makedirs(os.path.join(folder, "class"), exist_ok=True)
rnd = random.Random(1)

HEAD = ["rLocate 400,300", "rInvisible GREEN", "LineWidth {width}", "rPen DOWN"]
TAIL = ['print "perimeter " + {perimeter}']


def loop(sides, side):
    return [f"for n = 1 to {sides}", f"  rForward {side}", "  rTurn 90", "next"]


def unrolled(side):
    return [line for _ in range(4) for line in (f"rForward {side}", "rTurn 90")]


def program(kind):
    width = rnd.choice([1, 2, 4])
    body, perimeter = loop(4, 120), "4 * 120"
    if kind == "unrolled":
        body = unrolled(120)
    elif kind == "while":
        body = ["n = 0", "while n < 4", "  rForward 120", "  rTurn 90", "  n = n + 1", "wend"]
    elif kind == "three":
        body = loop(3, 120)
    elif kind == "side":
        body = loop(4, rnd.choice([100, 110, 130, 140]))
    elif kind == "crash":
        body = loop(4, 400)
    elif kind == "typo":
        body = [line.replace("rForward", "rForwad") for line in loop(4, 120)]
    elif kind == "output":
        perimeter = "3 * 120"
    lines = [f"// generated: {kind}"] + [h.format(width=width) for h in HEAD] + body
    return "\n".join(lines + [t.format(perimeter=perimeter) for t in TAIL]) + "\n"


KINDS = ["loop"] * 40 + ["unrolled"] * 15 + ["while"] * 15 + ["three"] * 8 + ["side"] * 8 + \
        ["crash"] * 5 + ["typo"] * 5 + ["output"] * 4
for i in range(count):
    with open(os.path.join(folder, "class", f"student{i:04d}.bas"), "w") as f:
        f.write(program(rnd.choice(KINDS)))
with open(os.path.join(folder, "solution.bas"), "w") as f:
    f.write("\n".join(HEAD + loop(4, 120) + TAIL).format(width=4, perimeter="4 * 120") + "\n")
with open(os.path.join(folder, "assignment.toml"), "w") as f:
    f.write("""title = "square"
solution = "solution.bas"
[run]
max-steps = 100000
[[check]]
kind = "check"
[[check]]
kind = "no-error"
[[check]]
kind = "solution-output"
[[check]]
kind = "visits"
waypoints = [[400, 300], [400, 180], [520, 180], [520, 300], [400, 300]]
tolerance = 3
[[check]]
kind = "solution-trail"
tolerance = 3
[[check]]
kind = "ends-in"
circle = [400, 300, 5]
[[check]]
kind = "solution-screen"
tolerance = 0.005
""")
