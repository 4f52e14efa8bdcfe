#!/usr/bin/env python3
"""Writes N RobotBASIC programs of about 300 lines each (a realistic mix: subroutines, loops,
ifs, robot and graphics commands, string and math calls) into a folder, for timing rb check.
Usage: gen.py FOLDER [N]"""
import os
import random
import sys

folder = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
os.makedirs(folder, exist_ok=True)
rnd = random.Random(1)


def block(k):
    v = f"v{k}"
    kinds = [
        [f"for {v} = 1 to {rnd.randint(2, 50)}", f"  total = total + {v} * {rnd.randint(1, 9)}",
         f"  if total > {rnd.randint(100, 999)} then total = total - {rnd.randint(1, 99)}", "next"],
        [f"while rBumper() = 0 and count < {rnd.randint(10, 99)}", "  rForward 1", "  count = count + 1", "wend"],
        [f"if rFeel() & {rnd.choice([3, 4, 24])}", f"  rTurn {rnd.randint(-180, 180)}",
         "elseif rRange() < 20", "  rTurn 90", "else", "  rForward 2", "endif"],
        [f'name = "robot" + {rnd.randint(1, 99)}', "print left(name, 3), length(name)",
         f"x = round(sin(dtor({rnd.randint(0, 360)})) * 100)"],
        [f"rectangle {rnd.randint(0, 400)}, {rnd.randint(0, 300)}, {rnd.randint(400, 799)}, {rnd.randint(300, 599)}, red",
         f"circle 10, 10, {rnd.randint(20, 90)}, {rnd.randint(20, 90)}, blue, blue", "lineWidth 2"],
        ["repeat", "  count = count - 1", "until count <= 0"],
    ]
    return rnd.choice(kinds)


for n in range(count):
    lines = ["// generated for the rb check benchmark", "total = 0", "count = 0", "Main:",
             "  rLocate 400, 300", "  gosub Work0", "end", ""]
    label = 0
    while True:
        sub = [f"Work{label}:"]
        for k in range(rnd.randint(3, 8)):
            sub += ["  " + s for s in block(k)]
        if label > 0:
            sub.append(f"  gosub Work{label - 1}" if rnd.random() < 0.3 else "  total = total + 1")
        sub += ["return", ""]
        if len(lines) + len(sub) > 300:
            break
        lines += sub
        label += 1
    lines += ["// padding"] * (300 - len(lines))
    with open(os.path.join(folder, f"prog{n:04d}.bas"), "w") as f:
        f.write("\n".join(lines) + "\n")
