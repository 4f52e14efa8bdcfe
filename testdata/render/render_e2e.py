#!/usr/bin/env python3
"""End-to-end tests of `rb render`: runs the built binary and checks exit codes and outputs.

Usage: render_e2e.py --rb PATH/TO/rb --source SOURCE_DIR --work WORK_DIR CASE

Each CASE is one CTest test (testdata/render/CMakeLists.txt); WORK_DIR is emptied first.
"""

import argparse
import os
import shutil
import struct
import subprocess
import sys

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


class Failure(Exception):
    pass


def expect(cond, message):
    if not cond:
        raise Failure(message)


def png_size(path):
    """Width and height from a PNG file's IHDR chunk."""
    with open(path, "rb") as f:
        head = f.read(24)
    expect(head[:8] == PNG_SIGNATURE, f"{path} is not a PNG file")
    expect(head[12:16] == b"IHDR", f"{path} has no IHDR chunk first")
    return struct.unpack(">II", head[16:24])


class Env:
    def __init__(self, rb, source, work):
        self.rb, self.source, self.work = rb, source, work
        self.fig17 = os.path.join(source, "examples", "fig_1_7.bas")

    def path(self, name):
        return os.path.join(self.work, name)

    def program(self, name, text):
        p = self.path(name)
        with open(p, "w") as f:
            f.write(text)
        return p

    def run(self, *args):
        r = subprocess.run([self.rb, "render", *args], capture_output=True, text=True, timeout=60)
        return r

    def expect_exit(self, r, code):
        expect(r.returncode == code,
               f"exit {r.returncode}, expected {code}\nstdout:\n{r.stdout}\nstderr:\n{r.stderr}")


def case_png(env):
    out = env.path("fig_1_7.png")
    r = env.run(env.fig17, "-o", out)
    env.expect_exit(r, 0)
    expect(png_size(out) == (800, 600), f"size {png_size(out)}")


def case_scale(env):
    out = env.path("fig_1_7_x2.png")
    env.expect_exit(env.run(env.fig17, "-o", out, "--scale", "2"), 0)
    expect(png_size(out) == (1600, 1200), f"size {png_size(out)}")
    svg = env.path("fig_1_7_x2.svg")
    env.expect_exit(env.run(env.fig17, "-o", svg, "--scale", "2"), 0)
    expect('width="1600" height="1200"' in open(svg).read(), "SVG not scaled")
    env.expect_exit(env.run(env.fig17, "-o", out, "--scale", "0"), 64)


def case_svg(env):
    out = env.path("fig_1_7.svg")
    env.expect_exit(env.run(env.fig17, "-o", out, "--seed", "3"), 0)
    text = open(out).read()
    expect(text.startswith('<?xml version="1.0"'), "not an XML document")
    expect('<polyline points="400,300 400,180 520,180 520,300 400,300"' in text, "no square trail")
    expect(text.endswith("</svg>\n"), "unterminated SVG")
    # The same program and seed give the same bytes.
    again = env.path("fig_1_7_again.SVG")
    env.expect_exit(env.run(env.fig17, "-o", again, "--seed", "3"), 0)
    expect(open(again).read() == text, "two runs gave different SVG")


def case_ascii(env):
    r = env.run(env.fig17, "--ascii")
    env.expect_exit(r, 0)
    lines = r.stdout.split("\n")
    expect(len(lines) == 38 and lines[-1] == "", f"{len(lines) - 1} lines, expected 37")
    expect(all(len(l) == 100 for l in lines[:-1]), "lines are not 100 characters")
    expect("^" in r.stdout, "no robot glyph")
    r = env.run(env.fig17, "--ascii", "--cells", "braille", "--cols", "40", "--rows", "12")
    env.expect_exit(r, 0)
    expect(len(r.stdout.split("\n")) == 13, "braille view has the wrong number of rows")
    expect("\u2191" in r.stdout, "no robot arrow")
    expect("\x1b" not in r.stdout, "colour escapes in plain output")
    env.expect_exit(env.run(env.fig17, "--ascii", "--cells", "nope"), 64)


def case_flip(env):
    """With flip on, the picture is the screen at the last flip, as a live view shows it."""
    prog = env.program("flip.bas", "flip on\nrectangle 0, 0, 800, 600, BLACK, BLACK\nflip\n"
                                   "clearScr\n")
    r = env.run(prog, "--ascii", "--cols", "20", "--rows", "5")
    env.expect_exit(r, 0)
    expect(r.stdout == ("#" * 20 + "\n") * 5, "not the flipped (black) screen:\n" + r.stdout)
    svg = env.path("flip.svg")
    env.expect_exit(env.run(prog, "-o", svg), 0)
    with open(svg) as f:
        text = f.read()
    expect("the last flip" in text and "data:image/png" in text, "SVG lacks the flipped screen")
    plain = env.program("noflip.bas", "rectangle 0, 0, 800, 600, BLACK, BLACK\nclearScr\n")
    r = env.run(plain, "--ascii", "--cols", "20", "--rows", "5")
    expect("#" not in r.stdout, "without flip the cleared screen shows:\n" + r.stdout)


def case_bad_extension(env):
    out = env.path("picture.gif")
    r = env.run(env.fig17, "-o", out)
    env.expect_exit(r, 64)
    expect(not os.path.exists(out), "wrote a file despite the bad extension")
    expect(".png or .svg" in r.stderr, f"unhelpful message: {r.stderr}")
    env.expect_exit(env.run(env.fig17), 64)  # neither -o nor --ascii


def case_missing_file(env):
    out = env.path("missing.png")
    r = env.run(env.path("no_such_program.bas"), "-o", out)
    env.expect_exit(r, 66)
    expect(not os.path.exists(out), "wrote a picture of nothing")


def case_load_error(env):
    prog = env.program("broken.bas", "rLocate 100, 100\nwend\n")
    out = env.path("broken.png")
    env.expect_exit(env.run(prog, "-o", out), 65)
    expect(not os.path.exists(out), "wrote a picture though nothing ran")


def case_runtime_error(env):
    # The robot drives into the wall: the picture of the crash is still written.
    prog = env.program("crash.bas", "rectangle 300, 0, 310, 599, RED, RED\nrLocate 100, 300, 90\n"
                                     "rForward 500\nprint \"never\"\n")
    out = env.path("crash.png")
    r = env.run(prog, "-o", out)
    env.expect_exit(r, 70)
    expect("crashed" in r.stderr, f"no runtime error on stderr: {r.stderr}")
    expect(png_size(out) == (800, 600), "no crash picture")


def case_max_steps(env):
    prog = env.program("forever.bas", "rLocate 400, 300\nwhile 1\n  rTurn 1\nwend\n")
    out = env.path("forever.svg")
    r = env.run(prog, "-o", out, "--max-steps", "500")
    env.expect_exit(r, 0)
    expect("rb render: stopped after 500 steps (--max-steps)" in r.stderr, f"no note: {r.stderr}")
    expect("error:" not in r.stderr, f"the step limit is not an error for render: {r.stderr}")
    expect("<circle" in open(out).read(), "no robot in the picture")


def case_unwritable(env):
    out = os.path.join(env.work, "no_such_dir", "x.png")
    r = env.run(env.fig17, "-o", out)
    env.expect_exit(r, 74)
    expect(out in r.stderr, f"the message does not name the file: {r.stderr}")


def case_help(env):
    r = subprocess.run([env.rb, "render", "--help"], capture_output=True, text=True, timeout=60)
    env.expect_exit(r, 0)
    for option in ["--output", "--scale", "--ascii", "--cols", "--rows", "--cells", "--max-steps",
                   "--seed", "--timeout"]:
        expect(option in r.stdout, f"--help does not list {option}")


CASES = {name[len("case_"):]: fn for name, fn in globals().items() if name.startswith("case_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("case", choices=sorted(CASES))
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    try:
        CASES[a.case](Env(a.rb, a.source, a.work))
    except Failure as e:
        print(f"FAIL {a.case}: {e}")
        return 1
    print(f"ok {a.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
