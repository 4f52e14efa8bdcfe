#!/usr/bin/env python3
"""Writes RobotBASIC programs of about 300 lines each (a realistic mix: subroutines, loops, ifs,
robot and graphics commands, string and math calls), for timing rb check.

Usage: gen.py FOLDER [N]            N programs (default 1000) into FOLDER, prog0000.bas ...
       gen.py --one LINES FILE      one file of at least LINES lines (whole 300-line programs one
                                    after another, their labels made unique, no indentation: rb reads
                                    files up to 16 MiB), FILE.bas and the same program
                                    in Lua 5.4 as FILE.lua (same statements, line for line), for
                                    comparing rb check with Lua's loadfile."""
import os
import random
import sys

rnd = random.Random(1)


def block(k):
    """One block as (RobotBASIC lines, Lua lines); both draw the same random numbers."""
    v = f"v{k}"
    kind = rnd.randrange(6)
    if kind == 0:
        n, a, b, c = rnd.randint(2, 50), rnd.randint(1, 9), rnd.randint(100, 999), rnd.randint(1, 99)
        return ([f"for {v} = 1 to {n}", f"  total = total + {v} * {a}",
                 f"  if total > {b} then total = total - {c}", "next"],
                [f"for {v} = 1, {n} do", f"  total = total + {v} * {a}",
                 f"  if total > {b} then total = total - {c} end", "end"])
    if kind == 1:
        n = rnd.randint(10, 99)
        return ([f"while rBumper() = 0 and count < {n}", "  rForward 1", "  count = count + 1", "wend"],
                [f"while rBumper() == 0 and count < {n} do", "  rForward(1)", "  count = count + 1", "end"])
    if kind == 2:
        m, t = rnd.choice([3, 4, 24]), rnd.randint(-180, 180)
        return ([f"if rFeel() & {m}", f"  rTurn {t}", "elseif rRange() < 20", "  rTurn 90", "else",
                 "  rForward 2", "endif"],
                [f"if rFeel() & {m} ~= 0 then", f"  rTurn({t})", "elseif rRange() < 20 then",
                 "  rTurn(90)", "else", "  rForward(2)", "end"])
    if kind == 3:
        n, d = rnd.randint(1, 99), rnd.randint(0, 360)
        return ([f'name = "robot" + {n}', "print left(name, 3), length(name)",
                 f"x = round(sin(dtor({d})) * 100)"],
                [f'name = "robot" .. {n}', "print(string.sub(name, 1, 3), #name)",
                 f"x = math.floor(math.sin(math.rad({d})) * 100 + 0.5)"])
    if kind == 4:
        x1, y1, x2, y2 = rnd.randint(0, 400), rnd.randint(0, 300), rnd.randint(400, 799), rnd.randint(300, 599)
        w, h = rnd.randint(20, 90), rnd.randint(20, 90)
        return ([f"rectangle {x1}, {y1}, {x2}, {y2}, red", f"circle 10, 10, {w}, {h}, blue, blue",
                 "lineWidth 2"],
                [f"rectangle({x1}, {y1}, {x2}, {y2}, red)", f"circle(10, 10, {w}, {h}, blue, blue)",
                 "lineWidth(2)"])
    return (["repeat", "  count = count - 1", "until count <= 0"],
            ["repeat", "  count = count - 1", "until count <= 0"])


def program(prefix="", indent="  "):
    """One program of 300 lines as (RobotBASIC lines, Lua lines). Labels and subs are named
    `prefix + WorkN` so that programs can share one file."""
    bas = ["// generated for the rb check benchmark", "total = 0", "count = 0", f"{prefix}Main:",
           "  rLocate 400, 300", f"  gosub {prefix}Work0", "end", ""]
    lua = ["-- generated for the rb check benchmark", "total = 0", "count = 0", f"-- {prefix}Main:",
           "  rLocate(400, 300)", f"  {prefix}Work0()", "-- end", ""]
    label = 0
    while True:
        sub_b, sub_l = [f"{prefix}Work{label}:"], [f"function {prefix}Work{label}()"]
        for k in range(rnd.randint(3, 8)):
            b, l = block(k)
            sub_b += [indent + s if indent else s.lstrip() for s in b]
            sub_l += [indent + s if indent else s.lstrip() for s in l]
        if label > 0:
            if rnd.random() < 0.3:
                sub_b.append(f"  gosub {prefix}Work{label - 1}")
                sub_l.append(f"  {prefix}Work{label - 1}()")
            else:
                sub_b.append("  total = total + 1")
                sub_l.append("  total = total + 1")
        sub_b += ["return", ""]
        sub_l += ["end", ""]
        if len(bas) + len(sub_b) > 300:
            break
        bas += sub_b
        lua += sub_l
        label += 1
    bas += ["// padding"] * (300 - len(bas))
    lua += ["-- padding"] * (300 - len(lua))
    return bas, lua


if len(sys.argv) == 4 and sys.argv[1] == "--one":
    lines, stem = int(sys.argv[2]), sys.argv[3]
    with open(stem + ".bas", "w") as fb, open(stem + ".lua", "w") as fl:
        for n in range((lines + 299) // 300):
            bas, lua = program(f"P{n}_", indent="")
            fb.write("\n".join(bas) + "\n")
            fl.write("\n".join(lua) + "\n")
    sys.exit(0)

folder = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
os.makedirs(folder, exist_ok=True)
for n in range(count):
    bas, _ = program()
    with open(os.path.join(folder, f"prog{n:04d}.bas"), "w") as f:
        f.write("\n".join(bas) + "\n")
