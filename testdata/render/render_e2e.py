#!/usr/bin/env python3
"""End-to-end tests of `rb render`: runs the built binary and checks exit codes and outputs.

Usage: render_e2e.py --rb PATH/TO/rb --source SOURCE_DIR --work WORK_DIR CASE

Each CASE is one CTest test (testdata/render/CMakeLists.txt); WORK_DIR is emptied first.
"""

import argparse
import json
import os
import resource
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
                   "--seed", "--timeout", "--animate", "--fps", "--duration", "--every", "--hold"]:
        expect(option in r.stdout, f"--help does not list {option}")


def gif_frames(path):
    """How many images a GIF file holds, and whether it loops (NETSCAPE2.0), by its blocks."""
    data = open(path, "rb").read()
    expect(data[:6] == b"GIF89a", f"{path} is not a GIF89a file")
    flags = data[10]
    pos = 13 + (3 * (2 << (flags & 7)) if flags & 0x80 else 0)
    images, loops = 0, False
    while data[pos] != 0x3B:
        block = data[pos]
        if block == 0x21:
            if data[pos + 1] == 0xFF and data[pos + 3:pos + 14] == b"NETSCAPE2.0":
                loops = True
            pos += 2
        else:
            expect(block == 0x2C, f"unexpected block {block:#x} in {path}")
            images += 1
            iflags = data[pos + 9]
            pos += 10 + (3 * (2 << (iflags & 7)) if iflags & 0x80 else 0) + 1
        while data[pos]:
            pos += 1 + data[pos]
        pos += 1
    return images, loops


def case_animate(env):
    """--animate writes a GIF, an SVG or an HTML page by OUT's extension, beside -o's picture."""
    gif, png = env.path("square.gif"), env.path("square.png")
    r = env.run(env.fig17, "--animate", gif, "-o", png)
    env.expect_exit(r, 0)
    expect(png_size(png) == (800, 600), "no picture beside the animation")
    images, loops = gif_frames(gif)
    # The 10 moments of the square, and the glides: 11 frames more along each side, 5 in each turn.
    expect(images == 10 + 4 * 11 + 4 * 5 and loops, f"{images} images, loops {loops}: expected the square's 74, looping")
    nog = env.path("square-steps.gif")
    env.expect_exit(env.run(env.fig17, "--animate", nog, "--no-glide"), 0)
    images, loops = gif_frames(nog)
    expect(images == 10 and loops, f"--no-glide: {images} images, loops {loops}: expected the 10 moments of the square")
    expect(os.path.getsize(gif) < 200 * 1024, f"the square's GIF is {os.path.getsize(gif)} bytes")
    svg = env.path("square.SVG")
    env.expect_exit(env.run(env.fig17, "--animate", svg, "--fps", "25"), 0)
    text = open(svg).read()
    expect(text.startswith("<?xml") and "@keyframes" in text and "<script" not in text, "not an animated SVG")
    if shutil.which("xmllint"):
        x = subprocess.run(["xmllint", "--noout", svg], capture_output=True, text=True)
        expect(x.returncode == 0, f"the SVG is not well-formed XML: {x.stderr}")
    html = env.path("square.htm")
    env.expect_exit(env.run(env.fig17, "--animate", html, "--every", "2"), 0)
    page = open(html).read()
    expect(page.startswith("<!DOCTYPE html>") and "rbPlayer" in page, "not the player page")
    expect('"name":"fig_1_7.bas"' in page, "the page does not name the program")
    expect("fig_1_7.bas" in page and "rForward 120" in page, "the page lacks the program's source")
    # --duration and --hold; the step limit stops the run and the replay ends there.
    env.expect_exit(env.run(env.fig17, "--animate", gif, "--duration", "3", "--fps", "5", "--hold", "0"), 0)
    forever = env.program("forever.bas", "rLocate 400, 300\nrInvisible BLACK\nrPen DOWN\nwhile 1\n  rForward 1\n"
                                         "  rTurn 1\nwend\n")
    r = env.run(forever, "--animate", gif, "--max-steps", "2000")
    env.expect_exit(r, 0)
    expect("stopped after 2000 steps" in r.stderr, f"no note of the step limit: {r.stderr}")
    expect(gif_frames(gif)[0] > 100, "the step-limited run's GIF is short")


def case_animate_error(env):
    """A run that ends in a runtime error: the replay is written, the error on stderr, exit 70."""
    prog = env.program("crash.bas", "rLocate 400, 60\nrPen DOWN\nfor i = 1 to 20\n  rForward 10\nnext\n")
    for ext in ["gif", "svg", "html"]:
        out = env.path("crash." + ext)
        r = env.run(prog, "--animate", out)
        env.expect_exit(r, 70)
        expect("error:" in r.stderr and "crash.bas:4" in r.stderr, f"the error is not on stderr: {r.stderr}")
        expect(os.path.getsize(out) > 1000, f"no {ext} replay after the error")
    page = open(env.path("crash.html")).read()
    expect('"status":"runtime error"' in page, "the page does not say how the run ended")
    # 3 statements, the for, 4 moves and nexts, the fifth move: the player counts 12, not the
    # statements up to the loop's last jump (issue 37: "a crash into the wall reports 0 steps").
    expect('"totalSteps":12' in page, "the player does not count the statements up to the crash")
    wall = env.program("wall.bas", "rLocate 400, 60\nrPen DOWN\nrForward 100\n")
    out = env.path("wall.html")
    env.expect_exit(env.run(wall, "--animate", out), 70)
    expect('"totalSteps":3' in open(out).read(), "a crash with no jump before it: the player does not count 3 statements")


def case_animate_usage(env):
    """Bad --animate command lines: clear messages naming the option, exit 64 (74 when OUT
    cannot be written), before anything runs."""
    def bad(args, code, *words):
        r = env.run(env.fig17, *args)
        env.expect_exit(r, code)
        for w in words:
            expect(w in r.stderr, f"{' '.join(args)}: the message lacks {w!r}: {r.stderr}")
    gif = env.path("x.gif")
    bad(["--animate", env.path("x.mp4")], 64, "--animate", "x.mp4", ".gif, .svg or .html")
    bad(["--animate", env.path("x")], 64, "--animate", ".gif, .svg or .html")
    missing = os.path.join(env.work, "no_such_dir", "x.gif")
    bad(["--animate", missing], 74, "--animate", missing, "no such folder")
    bad(["--animate", env.work], 64, "--animate")
    for fps in ["0", "-3", "1000", "abc", "nan"]:
        bad(["--animate", gif, "--fps", fps], 64, "--fps", "0.1 to 100")
    bad(["--fps", "5", "-o", env.path("x.png")], 64, "--fps", "--animate")
    bad(["--animate", gif, "--every", "2", "--duration", "3"], 64, "--every", "--duration")
    bad(["--animate", gif, "--every", "0"], 64, "--every")
    bad(["--animate", gif, "--duration", "0"], 64, "--duration")
    bad(["--animate", gif, "--hold", "-1"], 64, "--hold")
    bad([], 64, "-o OUT", "--animate OUT")
    expect(not os.path.exists(gif), "a bad command line wrote the animation")


def case_animate_long(env):
    """10,000,000 statements: the recording keeps a sample within its budget, the frames are
    sampled, memory stays bounded and nothing crashes."""
    prog = env.program("long.bas",
                       "rLocate 400, 300\nrInvisible RED\nrPen DOWN\nfor i = 1 to 3333332\n"
                       "  if i % 200 = 0 then rForward 1\n  if i % 20000 = 0 then rTurn 91\nnext\n")
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    for ext in ["gif", "html"]:
        out = env.path("long." + ext)
        r = env.run(prog, "--animate", out)
        env.expect_exit(r, 0)
        expect(os.path.getsize(out) < 20 << 20, f"the {ext} replay is {os.path.getsize(out)} bytes")
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # KiB, of the largest child
    expect(peak < 400 * 1024, f"rb render --animate used {peak // 1024} MiB (before: {before // 1024})")
    images, _ = gif_frames(env.path("long.gif"))
    expect(100 < images <= 2000, f"{images} images in the GIF")
    page = open(env.path("long.html")).read()
    meta = json.loads(page[page.index('id="rb-meta">') + 13:page.index("</script>", page.index('id="rb-meta">'))])
    expect(meta["totalSteps"] == 10000000, f"{meta['totalSteps']} statements recorded")
    expect(meta["stride"] > 1 and meta["steps"] < 1000000, f"{meta['steps']} steps kept, stride {meta['stride']}")


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
