#!/usr/bin/env python3
"""Runs the programs of examples/ written beyond the seed's figures (examples/README.md, "Beyond
the book"): each must be quiet under `rb check --portable --werror` and run under `rb run` with
rb's default limits to the end it prints (seed 1; scripted keys and button presses where the
program asks for them).

Usage: examples_test.py PATH/TO/rb
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "..", "examples")

# program -> (extra rb run arguments, expected standard output)
RUNS = {
    "keys.bas": (["--keys", "wwwwwwwwwwwwwwwpddddddwwwwsq"],
                 "w forward, s back, a left, d right, p pen, q quit\n"
                 "Bump! A wall ahead.\nBump! A wall ahead.\n"
                 "The robot is at 460, 21, heading 90\n"),
    "buttons.bas": (["--events", os.path.join(HERE, "buttons.events")],
                    "Square of 120 pixels\nTriangle of 200 pixels\n"
                    "The size must be a number from 20 to 250.\nSquare of 60 pixels\nDrawn: 3 shapes\n"),
    "sensors.bas": ([], None),
    "bumper_roamer.bas": ([], "30 bumps, 4724 pixels driven\n"),
    "line_follower.bas": ([], "Back at the start after 840 steps\n"),
    "maze.bas": ([], "Out of the maze in 30 moves\n"),
}
SENSORS = [
    "bumpers 0, infrared 0, floor 2 (2: the middle sensor)",
    "the red box is 161 pixels ahead",
    "0\t160\tred",
    "90\t180\tblue",
    "near the box: infrared 4, range 20, bumpers 0",
]


def main():
    rb = os.path.abspath(sys.argv[1])
    problems = []
    for name, (args, want) in RUNS.items():
        c = subprocess.run([rb, "check", "--portable", "--werror", name], capture_output=True, text=True,
                           cwd=EXAMPLES, timeout=60)
        if c.returncode != 0:
            problems.append(f"rb check --portable --werror {name}: exit {c.returncode}\n{c.stdout}{c.stderr}")
        r = subprocess.run([rb, "run", "--seed", "1"] + args + [name], capture_output=True, text=True,
                           cwd=EXAMPLES, timeout=120, stdin=subprocess.DEVNULL)
        if want is None:  # sensors.bas: its telling lines
            ok = r.returncode == 0 and all(line in r.stdout.splitlines() for line in SENSORS)
        else:
            ok = r.returncode == 0 and r.stdout == want
        if not ok:
            problems.append(f"rb run {name}: exit {r.returncode}, output {r.stdout!r}, stderr {r.stderr[:400]!r}")
    for p in problems:
        print("FAIL " + p)
    print(f"{2 * len(RUNS) - len(problems)} checks passed, {len(problems)} failed")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
