#!/usr/bin/env python3
"""Writes a class of N programs of L lines each into FOLDER (student00000.bas, ...), for timing
rb's similarity (bench/grade/similarity.sh). Programs share most of their lines, as a class's do:

  - 40% of every program is the assignment's starting code (one template for the class), each
    copy with its own edits;
  - 30% comes from two of 20 "libraries" (code from a textbook or the course's examples that
    some students took: each library is in about a tenth of the class), edited too;
  - 30% is the student's own;
  - one program in ten is a copy of an earlier student's, edited.

Edits: 5% of the shared lines are deleted, replaced by a line of the student's own or have one
inserted before them, and the program's blocks (of about 500 lines) come in an order of its own.
Names and numbers are not changed: rb's similarity reads every name as "a name" and every number
as "a number" (grade/similarity.h), so renaming would change nothing it sees.

The lines are RobotBASIC statements of the kinds the course's programs use (assignments, ifs,
loops, subroutines, robot and graphics commands, prints, arrays, comments), made from a seeded
generator: the same arguments give the same class.
Usage: similar_gen.py FOLDER [N=2000] [L=10000] [seed=1]"""
import os
import random
import sys

folder = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 2000
lines = int(sys.argv[3]) if len(sys.argv) > 3 else 10000
rnd = random.Random(int(sys.argv[4]) if len(sys.argv) > 4 else 1)
os.makedirs(folder, exist_ok=True)

NAMES = ["x", "y", "n", "i", "j", "k", "side", "total", "speed", "angle", "dist", "count", "steps",
         "left", "right", "best", "score", "hits", "turns", "size", "a", "b", "c", "t", "v"]
ARRAYS = ["grid", "path", "seen", "xs", "ys"]
WORDS = ["left", "right", "wall", "done", "turn", "steps", "found", "goal", "lap", "hit"]
LABELS = ["DrawWalls", "DrawRoof", "Scan", "TurnAround", "FollowWall", "Report", "Spiral",
          "Square", "Home", "Seek"]


def name():
    return rnd.choice(NAMES)


def num():
    return str(rnd.choice([1, 2, 3, 4, 5, 10, 20, 45, 90, 100, 120, 180, 360]))


FUNCTIONS = [("random", 1), ("abs", 1), ("sqrt", 1), ("sin", 1), ("cos", 1), ("int", 1), ("max", 2),
             ("min", 2), ("rFeel", 0), ("rBumper", 0), ("rRange", 0), ("rLook", 0), ("rCompass", 0),
             ("rGPSX", 0), ("rGPSY", 0), ("length", 1), ("Distance", 2), ("Scale", 2)]
OPERATORS = ["+", "-", "*", "/", "mod", "+", "-", "*"]
COMPARE = ["<", ">", "=", "<=", ">=", "<>"]


def atom():
    r = rnd.random()
    if r < 0.45:
        return name()
    if r < 0.75:
        return num()
    if r < 0.9:
        f, arity = rnd.choice(FUNCTIONS)
        return f + "(" + ", ".join(atom() if rnd.random() < 0.8 else expr() for _ in range(arity)) + ")"
    return f"{rnd.choice(ARRAYS)}[{expr(0)}]"


def expr(depth=1):
    """An expression of a shape of its own: names, numbers, calls, array items and operators."""
    if depth == 0 or rnd.random() < 0.45:
        return atom()
    e = f"{expr(depth - 1)} {rnd.choice(OPERATORS)} {expr(depth - 1)}"
    return f"({e})" if rnd.random() < 0.2 else e


def cond():
    c = f"{expr(0)} {rnd.choice(COMPARE)} {expr()}"
    return c if rnd.random() < 0.8 else f"{c} {rnd.choice(['and', 'or'])} {name()} {rnd.choice(COMPARE)} {num()}"


# Statement makers: each returns one line (blocks are made of such lines, and loops of two).
SIMPLE = [
    lambda: f"{name()} = {expr()}",
    lambda: f"{name()} = {expr()}",
    lambda: f"{name()} += {expr(0)}",
    lambda: f"if {cond()} then {name()} = {expr(0)}",
    lambda: f"if {cond()} then gosub {rnd.choice(LABELS)}",
    lambda: f"rForward {expr(0)}",
    lambda: f"rTurn {expr(0)}",
    lambda: f"rLocate {expr(0)}, {expr(0)}",
    lambda: f"rPen {rnd.choice(['UP', 'DOWN'])}",
    lambda: f'print "{rnd.choice(WORDS)} "; {expr(0)}',
    lambda: f"print {expr(0)}, {expr()}",
    lambda: f"{rnd.choice(ARRAYS)}[{expr(0)}] = {expr()}",
    lambda: f"LineWidth {expr(0)}",
    lambda: f"Line {expr(0)}, {expr(0)}, {expr(0)}, {expr(0)}",
    lambda: f"Circle {expr(0)}, {expr(0)}, {num()}, {num()}",
    lambda: f"Rectangle {expr(0)}, {expr(0)}, {num()}, {num()}, {rnd.choice(['RED', 'BLUE', 'GREEN'])}",
    lambda: f'xyText {expr(0)}, {expr(0)}, "{rnd.choice(WORDS)}"',
    lambda: f"if rBumper() & {rnd.choice([1, 2, 4, 8])} then rTurn {expr(0)}",
    lambda: f"gosub {rnd.choice(LABELS)}",
    lambda: f"call {rnd.choice(LABELS)}({expr(0)}, {name()})",
    lambda: f"// {' '.join(rnd.choice(WORDS) for _ in range(4))}",
]


def block(n):
    """n lines of code: simple statements, with loops and subroutines around some of them."""
    out = []
    while len(out) < n:
        r = rnd.random()
        if r < 0.08 and n - len(out) > 4:
            out.append(f"for {name()} = {expr(0)} to {expr(0)}" + (f" step {num()}" if rnd.random() < 0.3 else ""))
            out.extend("  " + rnd.choice(SIMPLE)() for _ in range(rnd.randint(1, 3)))
            out.append("next")
        elif r < 0.12 and n - len(out) > 4:
            out.append(f"while {cond()}")
            out.extend("  " + rnd.choice(SIMPLE)() for _ in range(rnd.randint(1, 3)))
            out.append("wend")
        elif r < 0.15 and n - len(out) > 5:
            out.append(f"{rnd.choice(LABELS)}{rnd.randint(1, 99)}:")
            out.extend("  " + rnd.choice(SIMPLE)() for _ in range(rnd.randint(2, 4)))
            out.append("return")
        else:
            out.append(rnd.choice(SIMPLE)())
    return out[:n]


def edited(src):
    """The lines with 5% of them deleted, replaced or given a line before them."""
    out = []
    for line in src:
        r = rnd.random()
        if r < 0.0167:
            continue
        if r < 0.0333:
            out.append(rnd.choice(SIMPLE)())
            continue
        if r < 0.05:
            out.append(rnd.choice(SIMPLE)())
        out.append(line)
    return out


def chunks(src, size=500):
    return [src[i:i + size] for i in range(0, len(src), size)]


template_n = lines * 4 // 10
library_n = lines * 15 // 100
own_n = lines - template_n - 2 * library_n
template = block(template_n)
libraries = [block(library_n) for _ in range(20)]

written = []  # each program's blocks, for the copiers
for i in range(count):
    if written and rnd.random() < 0.1:
        blocks = [edited(b) for b in rnd.choice(written)]
    else:
        two = rnd.sample(range(len(libraries)), 2)
        blocks = chunks(edited(template)) + chunks(edited(libraries[two[0]])) + \
            chunks(edited(libraries[two[1]])) + chunks(block(own_n))
    rnd.shuffle(blocks)
    if len(written) < 200:  # copiers copy from the first 200 (the memory stays small)
        written.append(blocks)
    with open(os.path.join(folder, f"student{i:05d}.bas"), "w") as f:
        f.write(f"// student {i}\n")
        for b in blocks:
            f.write("\n".join(b))
            f.write("\n")
