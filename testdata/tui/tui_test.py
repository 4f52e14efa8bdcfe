#!/usr/bin/env python3
"""End-to-end tests of `rb run --tui` in tmux: start the live view in a detached tmux session,
type keys and click with send-keys, read the screen with capture-pane.

Usage: tui_test.py --rb PATH/TO/rb TEST      (TEST: one of the names in TESTS below)
Exit status 0 on success, 1 on failure, 77 (CTest's skip code) when tmux is missing.

Each test polls the screen with a timeout instead of sleeping for fixed times, and runs its own
tmux server (on a socket in its own temporary folder), so tests can run in parallel.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
COLS, ROWS = 100, 30
# Generous: CI machines are slow and busy. Tests poll the screen, so a fast machine does not wait.
TIMEOUT = 30.0


class Failure(Exception):
    pass


class Session:
    """One `rb run --tui` in its own tmux server."""

    def __init__(self, rb, program, env=None, cols=COLS, rows=ROWS, args="", tui=True):
        self.dir = tempfile.mkdtemp(prefix="rbtui-")
        self.socket = os.path.join(self.dir, "tmux")  # removed with the folder
        self.code_file = os.path.join(self.dir, "code")
        self.err_file = os.path.join(self.dir, "stderr")
        settings = {"TERM": "xterm-256color", "LC_ALL": "C"}  # C locale: the ASCII cell mode
        settings.update(env or {})
        envs = " ".join(f"{k}={v}" for k, v in settings.items())
        # After rb exits the pane stays (sleep): the normal screen shows what rb printed there.
        mode = "--tui" if tui else ""
        command = (f"cd {HERE} && env {envs} {rb} run {mode} {args} {program} 2>{self.err_file}; "
                   f"echo $? >{self.code_file}.tmp; mv {self.code_file}.tmp {self.code_file}; "
                   f"sleep 600")
        self.tmux("new-session", "-d", "-s", "main", "-x", str(cols), "-y", str(rows), command)

    def tmux(self, *args):
        return subprocess.run(["tmux", "-S", self.socket, "-f", "/dev/null", *args],
                              capture_output=True, text=True, check=False)

    def screen(self):
        return self.tmux("capture-pane", "-p", "-t", "main").stdout

    def keys(self, *keys):
        self.tmux("send-keys", "-t", "main", *keys)

    def raw(self, text):
        """Bytes as the terminal would send them (mouse reports)."""
        self.tmux("send-keys", "-t", "main", "-l", text)

    def click(self, col, row, button=0):
        """An SGR mouse press and release at a 0-based cell (button 0 left, 2 right)."""
        self.raw(f"\x1b[<{button};{col + 1};{row + 1}M")
        self.raw(f"\x1b[<{button};{col + 1};{row + 1}m")

    def wait_for(self, what, predicate, timeout=TIMEOUT):
        deadline = time.monotonic() + timeout
        text = ""
        while time.monotonic() < deadline:
            text = self.screen()
            if predicate(text):
                return text
            if os.path.exists(self.code_file):
                break
            time.sleep(0.05)
        raise Failure(f"timed out waiting for {what}; the screen was:\n{text}\nstderr:\n{self.stderr()}")

    def settled(self, timeout=TIMEOUT):
        """The screen once two captures 0.1 s apart agree: curses may be mid-way through a frame
        when tmux captures it (the state row already new, the pose rows below still old)."""
        deadline = time.monotonic() + timeout
        last = self.screen()
        while time.monotonic() < deadline:
            time.sleep(0.1)
            now = self.screen()
            if now == last:
                return now
            last = now
        return last

    def wait_text(self, text, timeout=TIMEOUT):
        return self.wait_for(repr(text), lambda s: text in s, timeout)

    def exit_code(self, timeout=TIMEOUT):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if os.path.exists(self.code_file):
                with open(self.code_file) as f:
                    return int(f.read().strip())
            time.sleep(0.05)
        raise Failure(f"rb did not exit; the screen was:\n{self.screen()}")

    def stderr(self):
        try:
            with open(self.err_file, encoding="latin-1") as f:
                return f.read()
        except OSError:
            return ""

    def close(self):
        self.tmux("kill-server")
        shutil.rmtree(self.dir, ignore_errors=True)


def status(screen, label):
    """A value of the status panel ("x", "state", ...)."""
    m = re.search(r"[|+] " + re.escape(label) + r" +(\S[^|]*?)\s*$", screen, re.M)
    return m.group(1) if m else None


def output_pane(screen):
    """The output pane's text: the lines under its "-- output" rule, left of the side panels
    (the source pane may show the program's own text, such as its // expect: comments)."""
    lines = screen.split("\n")
    top = next((i for i, l in enumerate(lines) if l.startswith("-- output")), None)
    if top is None:
        return ""
    width = len(lines[top].rstrip(" |+").split(" |")[0])
    return "\n".join(l[:width] for l in lines[top + 1:])


def arena_lines(screen):
    """The arena's rows: the lines between the box's top and bottom edges, inside the box."""
    lines = screen.split("\n")
    top = next(i for i, l in enumerate(lines) if l.startswith("+ arena"))
    width = lines[top].index("+", 1)
    out = []
    for l in lines[top + 1:]:
        if l.startswith("+"):
            break
        out.append(l[1:width])
    return out


def check(condition, message):
    if not condition:
        raise Failure(message)


# ---- the tests

def test_square(rb):
    """The seed's square: the arena shows the robot and its pen trail; pause, step, resume, end."""
    s = Session(rb, "square.bas")
    try:
        s.wait_for("the robot to move", lambda t: status(t, "y") not in (None, "300.0"))
        s.keys("F2")
        s.wait_for("the pause", lambda t: status(t, "state") == "paused")
        paused = s.settled()
        check("PAUSED" in paused, "no PAUSED banner:\n" + paused)
        pose = (status(paused, "x"), status(paused, "y"), status(paused, "heading"))
        time.sleep(0.3)
        still = s.settled()
        check((status(still, "x"), status(still, "y"), status(still, "heading")) == pose,
              "the robot moved while paused:\n" + still)
        # F8 runs one pixel or degree of robot motion (or to the next statement).
        moved = None
        for _ in range(4):
            s.keys("F8")
            t = s.settled()
            if (status(t, "x"), status(t, "y"), status(t, "heading")) != pose:
                moved = t
                break
        check(moved is not None, "F8 did not step the robot:\n" + s.screen())
        check(status(moved, "state") == "paused", "not paused after a step:\n" + moved)
        s.keys("F2")
        done = s.wait_for("the end", lambda t: status(t, "state") == "finished" and "square done" in output_pane(t))
        check("square done" in output_pane(done), "the output pane lacks the program's output:\n" + done)
        arena = arena_lines(done)
        drawn = sum(1 for row in arena for c in row if c not in " ")
        check(drawn > 25, f"the square's trail is missing ({drawn} drawn cells):\n" + done)
        check(any("^" in row for row in arena), "no robot glyph (^) in the arena:\n" + done)
        check(status(done, "pen") == "down", "the status panel does not show the pen:\n" + done)
        s.keys("x")
        code = s.exit_code()
        check(code == 0, f"exit status {code}, stderr: {s.stderr()}")
    finally:
        s.close()


def test_keyboard(rb):
    """Keys go to a program that reads the keyboard; rb keeps its F-keys."""
    s = Session(rb, "remote.bas")
    try:
        s.wait_for("waitKey", lambda t: status(t, "state") == "waiting for a key")
        s.keys("w", "w", "d", "w")
        t = s.wait_for("the robot at 420,260",
                       lambda t: status(t, "x") == "420.0" and status(t, "y") == "260.0")
        check(status(t, "heading") == "90.0", "heading after d:\n" + t)
        s.keys("q")
        # The state row can be drawn before the output pane in the same frame: wait for both.
        t = s.wait_for("the end", lambda t: status(t, "state") == "finished" and "bye at 420,260" in output_pane(t))
        check("bye at 420,260" in output_pane(t), "output pane:\n" + t)
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_mouse(rb):
    """Clicks map terminal cells to screen pixels; a click on a button presses it."""
    s = Session(rb, "clicks.bas")
    try:
        s.wait_for("the program", lambda t: status(t, "state") == "running")
        # Measured on a settled screen: a capture mid-way through a frame can show the arena's
        # rows short, which maps the click to the wrong cell under load.
        t = s.settled()
        check("Stop" in "\n".join(arena_lines(t)), "the Stop button is not drawn:\n" + t)
        # The arena's cells start at column 1, row 2; the click lands in arena cell (15, 5),
        # which shows the pixels from 15/cols to 16/cols of the width (and so for the height).
        rows = arena_lines(t)
        cols, nrows = len(rows[0]), len(rows)
        s.click(1 + 15, 2 + 5)
        t = s.wait_for("the click", lambda t: "left " in output_pane(t))
        m = re.search(r"left (\d+),(\d+)", output_pane(t))
        x, y = int(m.group(1)), int(m.group(2))
        check(15 * 800 // cols <= x < 16 * 800 // cols + 1 and 5 * 600 // nrows <= y < 6 * 600 // nrows + 1,
              f"click on cell 15,5 of a {cols} x {nrows} arena mapped to {x},{y}")
        # The button is drawn on the cells that show its pixels; a click there presses it.
        stop = next(i for i, l in enumerate(t.split("\n")) if "Stop" in l[:62])
        col = t.split("\n")[stop].index("Stop") + 1
        s.click(col, stop)
        # The state row can be drawn before the output pane in the same frame: wait for both.
        t = s.wait_for("the end", lambda t: status(t, "state") == "finished" and "end by 0 Stop" in output_pane(t))
        check("end by 0 Stop" in output_pane(t), "the button press did not end the program:\n" + t)
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_error(rb):
    """A runtime error shows in the view, wrapped at its words, with its line marked ('!') in the
    source pane, then on standard error in rb run's format (exit 70)."""
    s = Session(rb, "crash.bas")
    try:
        t = s.wait_for("the error", lambda t: status(t, "state") == "error")
        t = s.settled()
        words = " ".join(" ".join(line.split()) for line in output_pane(t).split("\n") if line.strip())
        check("crash.bas:5:1: error: robot crashed into an obstacle: colour Red at (400, 120) [rb-robot-crash]" in words,
              "the view lacks the error, or cuts its words:\n" + t)
        check(re.search(r"(?:^|\|)!\s*5 rForward 300", t, re.M), "the error's line is not marked:\n" + t)
        s.keys("Enter")
        code = s.exit_code()
        check(code == 70, f"exit status {code}")
        err = s.stderr()
        check("crash.bas:5:1: error: robot crashed into an obstacle" in err, "stderr: " + err)
    finally:
        s.close()


def test_pause_move(rb):
    """Paused inside a robot motion, the variables pane shows the variables as they are: the
    loop's counter of the side being drawn, not that of the side before."""
    s = Session(rb, "square.bas")
    try:
        t = s.wait_for("the second turn", lambda t: status(t, "heading") == "180.0")
        corner = (status(t, "x"), status(t, "y"))
        s.wait_for("the third side", lambda t: status(t, "heading") == "180.0"
                   and (status(t, "x"), status(t, "y")) != corner)
        s.keys("F2")
        s.wait_for("the pause", lambda t: status(t, "state") == "paused")
        t = s.settled()
        check(variable(t, "n") == "3", "paused on the third side, the variables pane shows:\n" + t)
        s.keys("F10")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_quit(rb):
    """F10 ends a running program at once (exit 0); so does q before the program reads keys,
    and F10 while the program waits for a key (the wait ends, then the run). Ctrl-C exits 130,
    as a shell reports a program ended by SIGINT."""
    for key, want in (("F10", 0), ("q", 0), ("C-c", 130)):
        s = Session(rb, "square.bas")
        try:
            s.wait_for("the run", lambda t: status(t, "state") == "running")
            s.keys(key)
            code = s.exit_code()
            check(code == want, f"exit status {code} after {key}, expected {want}")
            check(s.stderr() == "", f"stderr after {key}: {s.stderr()}")
        finally:
            s.close()
    s = Session(rb, "remote.bas")
    try:
        s.wait_for("waitKey", lambda t: status(t, "state") == "waiting for a key")
        s.keys("F10")
        check(s.exit_code() == 0, "exit status after F10 in waitKey")
        check(s.stderr() == "", f"stderr after F10 in waitKey: {s.stderr()}")
    finally:
        s.close()


def test_resize(rb):
    """Resizing the terminal lays the view out again."""
    s = Session(rb, "remote.bas")
    try:
        t = s.wait_for("the view", lambda t: status(t, "state") == "waiting for a key")
        before = len(t.split("\n")[1].rstrip())
        s.tmux("resize-window", "-t", "main", "-x", "80", "-y", "24")
        t = s.wait_for("a narrower arena", lambda t: t.split("\n")[1].startswith("+ arena")
                       and len(t.split("\n")[1].rstrip()) < before)
        # At 80 columns the status panel is narrow and may cut the value: "waiting..." is enough.
        check(status(t, "state").startswith("waiting"), "state after resize:\n" + t)
        s.keys("F10")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_unicode(rb):
    """In a UTF-8 locale the view may use half blocks or braille; it still shows the robot."""
    s = Session(rb, "square.bas", env={"LC_ALL": "C.UTF-8"})
    try:
        t = s.wait_for("the end", lambda t: "finished" in t.split("\n")[0])
        check(status(t.replace("\u2502", "|"), "pen") == "down", "status:\n" + t)
        s.keys("F6")  # another cell mode
        s.keys("x")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def running_line(screen):
    """The number of the source pane's highlighted line (the statement about to run)."""
    m = re.search(r"(?:^|\|)>\s*(\d+) ", screen, re.M)
    return int(m.group(1)) if m else None


def variable(screen, name):
    """A value in the variables pane."""
    m = re.search(r"\|" + re.escape(name) + r" +(\S.*?)\s*\|", screen)
    return m.group(1) if m else None


def test_motion(rb):
    """At rSpeed 0 the view still shows the robot moving: the pose changes between two looks."""
    s = Session(rb, "motion.bas")
    try:
        first = s.wait_for("the robot to move",
                           lambda t: status(t, "state") == "running"
                           and status(t, "y") not in (None, "300.0"))
        pose = (status(first, "x"), status(first, "y"), status(first, "heading"))
        later = s.wait_for("the robot to move on",
                           lambda t: (status(t, "x"), status(t, "y"), status(t, "heading")) != pose
                           and status(t, "state") == "running")
        check(status(later, "y") is not None, later)
        s.wait_for("the end", lambda t: status(t, "state") == "finished")
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_paused(rb):
    """--paused stops before the first statement; nothing runs until F2."""
    s = Session(rb, "square.bas", args="--paused")
    try:
        t = s.wait_for("the pause", lambda t: status(t, "state") == "paused"
                       and running_line(t) == 3)
        check(status(t, "robot") == "not placed", "the robot moved before the first statement:\n" + t)
        time.sleep(0.5)
        t = s.settled()
        check(running_line(t) == 3 and status(t, "state") == "paused", "ran while paused:\n" + t)
        s.keys("F2")
        s.wait_for("the end", lambda t: status(t, "state") == "finished")
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_step(rb):
    """F3 steps one statement (into a gosub), F7 steps over it; the highlighted line follows."""
    s = Session(rb, "debug.bas", args="--paused")
    try:
        s.wait_for("the pause at line 2", lambda t: running_line(t) == 2)
        for key, line in (("F3", 3), ("F3", 4), ("F3", 5), ("F3", 6), ("F3", 13), ("F3", 14),
                          ("F3", 7), ("F3", 8), ("F3", 6), ("F7", 7)):
            s.keys(key)
            t = s.wait_for(f"{key} to line {line}", lambda t, line=line:
                           running_line(t) == line and status(t, "state") == "paused")
        t = s.wait_for("the variables pane", lambda t: variable(t, "total") == "3")
        check(variable(t, "total") == "3", "the variables pane after two gosubs:\n" + t)
        s.keys("F10")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_break(rb):
    """--break stops at its line each time the run comes to it; F9 clears it; the variables pane
    shows the values at each stop; after the end the output is printed on the normal screen."""
    s = Session(rb, "debug.bas", args="--break 7")
    try:
        t = s.wait_for("the breakpoint", lambda t: running_line(t) == 7
                       and status(t, "state") == "paused")
        t = s.wait_for("total 1", lambda t: variable(t, "total") == "1")
        # (Waited for, not checked at once: tmux may capture a frame half drawn.)
        s.wait_for("the title saying why", lambda t: "paused at breakpoint, line 7" in t.split("\n")[0])
        check(variable(t, "name") == '"rb"', "a string in the variables pane:\n" + t)
        check(variable(t, "n") == "1", "the loop counter:\n" + t)
        s.keys("F2")
        t = s.wait_for("the second stop", lambda t: running_line(t) == 7
                       and variable(t, "total") == "3" and status(t, "state") == "paused")
        s.keys("F3")  # a step from the breakpoint: paused, but not at a breakpoint any more
        s.wait_for("the step, the title without the breakpoint",
                   lambda t: running_line(t) == 8 and status(t, "state") == "paused"
                   and "breakpoint" not in t.split("\n")[0])
        s.keys("F2")
        t = s.wait_for("the third stop", lambda t: running_line(t) == 7
                       and variable(t, "total") == "6" and status(t, "state") == "paused")
        s.keys("F9")  # clears the breakpoint on the shown line: the run goes on to its end
        s.wait_for("the title's notice", lambda t: "breakpoint cleared on line 7" in t.split("\n")[0])
        s.keys("F2")
        # The state row can be drawn before the output pane in the same frame: wait for both.
        t = s.wait_for("the end", lambda t: status(t, "state") == "finished" and "total 6" in output_pane(t))
        check("total 6" in output_pane(t), "the output pane:\n" + t)
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
        after = s.wait_text("total 6")
        check("rb run debug.bas" not in after, "the view is still shown after the exit:\n" + after)
    finally:
        s.close()


def test_break_moved(rb):
    """A breakpoint on a line without a statement (a comment, a blank line before a label) moves
    to the next line that has one, said on stderr and in the title; one with no statement after
    it is refused with the reason (exit 64), as is a line past the end."""
    s = Session(rb, "debug.bas", args="--break 1 --break 11")
    try:
        s.wait_for("the stop on line 2, said in the title",
                   lambda t: running_line(t) == 2 and status(t, "state") == "paused"
                   and "paused at breakpoint, line 2" in t.split("\n")[0]
                   and "2 breakpoints moved" in t.split("\n")[0])
        s.keys("F2")
        s.wait_for("the stop in the gosub", lambda t: running_line(t) == 13
                   and "paused at breakpoint, line 13" in t.split("\n")[0])
        s.keys("F10")
        check(s.exit_code() == 0, "exit status")
        err = s.stderr()
        check("--break 1: line 1 holds no statement: the breakpoint is on line 2, the next that does" in err,
              "stderr: " + err)
        check("--break 11: line 11 holds no statement: the breakpoint is on line 13" in err, "stderr: " + err)
    finally:
        s.close()
    for line, message in (("15", "--break 15: no statement on or after line 15: nothing there can stop the run"),
                          ("16", "--break 16: no such line in the program")):
        s = Session(rb, "debug.bas", args=f"--break {line}")
        try:
            code = s.exit_code()
            check(code == 64, f"exit status {code} for --break {line}")
            check(message in s.stderr(), "stderr: " + s.stderr())
        finally:
            s.close()


def test_restart(rb):
    """F12 runs the program again from the start, keeping the breakpoints and the view (the
    speed here); at the end it restarts too. After the view closes only the last run's output
    is printed."""
    s = Session(rb, "debug.bas", args="--break 7")
    try:
        t = s.wait_for("the breakpoint", lambda t: running_line(t) == 7 and variable(t, "total") == "1")
        s.keys("F2")
        s.wait_for("the second stop", lambda t: running_line(t) == 7 and variable(t, "total") == "3")
        s.keys("F5")  # x2: kept by the restart
        s.wait_for("speed x2", lambda t: status(t, "speed") == "x2")
        s.keys("F12")
        s.wait_for("the restarted run at its first stop, at x2, said in the title",
                   lambda t: running_line(t) == 7 and variable(t, "total") == "1"
                   and status(t, "state") == "paused" and status(t, "speed") == "x2"
                   and "restarted" in t.split("\n")[0])
        s.keys("F9")  # clear the breakpoint: the next run goes through
        s.keys("F2")
        s.wait_for("the end", lambda t: status(t, "state") == "finished"
                   and keys_line(t).startswith("F12 restart"))
        s.keys("F12")  # from the final screen
        s.wait_for("the second end", lambda t: status(t, "state") == "finished"
                   and "restarted" in t.split("\n")[0])
        t = s.settled()
        check(running_line(t) is None, "a breakpoint cleared before the restart stopped it:\n" + t)
        s.keys("x")
        check(s.exit_code() == 0, "exit status")
        after = s.wait_text("total 6")
        check(after.count("total 6") == 1, "more than the last run's output:\n" + after)
    finally:
        s.close()


WATCHED = """// --watch: tui_test.py edits this copy while it runs.
total = 0
name = "rb"
dim marks[4]
for n = 1 to 3
  gosub AddOne
  marks[n] = total
next
print "total ", total
end

AddOne:
  total = total + n
  return
"""


def test_watch(rb):
    """--watch runs the program again when it is saved: a breakpoint stays on its line, or moves
    to the next statement when its line became a comment; a save with a syntax error shows the
    error and waits; the fix saved runs again."""
    folder = tempfile.mkdtemp(prefix="rbtui-watch-")
    prog = os.path.join(folder, "watched.bas")

    def save(text):
        # As editors do: a new file renamed over the old one.
        with open(prog + ".tmp", "w") as f:
            f.write(text)
        os.replace(prog + ".tmp", prog)

    save(WATCHED)
    s = Session(rb, prog, args="--watch --break 7")
    try:
        s.wait_for("the breakpoint", lambda t: running_line(t) == 7 and variable(t, "total") == "1")
        save(WATCHED.replace('print "total ", total', 'print "sum ", total'))
        s.wait_for("the run of the saved program",
                   lambda t: "watched.bas was saved" in t.split("\n")[0] and running_line(t) == 7
                   and variable(t, "total") == "1")
        # Line 7 becomes a comment: its breakpoint moves to the next statement (next, line 8).
        save(WATCHED.replace("  marks[n] = total", "  // marks[n] = total"))
        s.wait_for("the breakpoint on line 8, said in the title",
                   lambda t: running_line(t) == 8 and status(t, "state") == "paused"
                   and "line 7 -> 8" in t.split("\n")[0])
        # A syntax error: the view shows it and waits.
        save(WATCHED.replace("for n = 1 to 3", "for n = 1 to"))
        s.wait_for("the load error", lambda t: "not loaded" in t.split("\n")[0]
                   and "watched.bas:5:" in output_pane(t) and keys_line(t).startswith("F12 load again"))
        # The breakpoint stays where it moved to.
        save(WATCHED.replace('print "total ", total', 'print "fixed ", total'))
        t = s.wait_for("the fixed program's stop", lambda t: running_line(t) == 8
                       and status(t, "state") == "paused" and "fixed" in t)
        s.keys("F9", "F2")
        s.wait_for("the end", lambda t: status(t, "state") == "finished" and "fixed 6" in output_pane(t))
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status " + s.stderr())
    finally:
        s.close()
    # A program with errors from the start opens the view too; quitting prints the errors as
    # rb run does (exit 65).
    save(WATCHED.replace("for n = 1 to 3", "for n = 1 to"))
    s = Session(rb, prog, args="--watch")
    try:
        s.wait_for("the load error", lambda t: "not loaded" in t.split("\n")[0])
        s.keys("F10")
        code = s.exit_code()
        check(code == 65, f"exit status {code}")
        check("watched.bas:5:" in s.stderr(), "stderr: " + s.stderr())
    finally:
        s.close()
        shutil.rmtree(folder, ignore_errors=True)


def watch_line(screen, expr):
    """A watch's value (or error) in the variables pane."""
    m = re.search(r"\|" + re.escape(expr) + r"(?: = |: )(.*?)\s*\|", screen)
    return m.group(1) if m else None


def test_watch_expr(rb):
    """F11 adds a watch expression: its value at every stop, errors in place; the same
    expression again removes it; a restart keeps them."""
    s = Session(rb, "debug.bas", args="--break 7", rows=40)  # room for watches and variables
    try:
        s.wait_for("the breakpoint", lambda t: running_line(t) == 7 and variable(t, "total") == "1")
        for expr in ("2 * total", "marks[n] + 1", "left(name, 1)", "nope + 1", "marks[9]"):
            s.keys("F11")
            s.wait_for("the watch line", lambda t: keys_line(t).startswith("watch: _"))
            s.raw(expr)
            s.keys("Enter")
            s.wait_for(f"the watch {expr}", lambda t, e=expr: watch_line(t, e) is not None)
        t = s.settled()
        check(watch_line(t, "2 * total") == "2", "total * 2:\n" + t)
        check(watch_line(t, "marks[n] + 1") == "1", "marks[n] + 1:\n" + t)
        check(watch_line(t, "left(name, 1)") == '"r"', "left(name, 1):\n" + t)
        # (An error wraps onto the lines under it in the narrow pane.)
        check((watch_line(t, "nope + 1") or "").startswith("the program has no variable"), "nope:\n" + t)
        check((watch_line(t, "marks[9]") or "").startswith("index 9 is out of range"), "marks[9]:\n" + t)
        s.keys("F2")
        s.wait_for("the second stop and the watches' new values",
                   lambda t: running_line(t) == 7 and variable(t, "total") == "3"
                   and watch_line(t, "2 * total") == "6" and watch_line(t, "marks[n] + 1") == "1")
        # Esc closes the line without adding anything.
        s.keys("F11")
        s.wait_for("the watch line", lambda t: keys_line(t).startswith("watch: _"))
        s.raw("n")
        s.keys("Escape")
        s.wait_for("the keys line back", lambda t: keys_line(t).startswith("F2 run"))
        t = s.settled()
        check(watch_line(t, "n") is None, "Esc added a watch:\n" + t)
        # A restart keeps the watches.
        s.keys("F12")
        t = s.wait_for("the restarted run's stop", lambda t: running_line(t) == 7
                       and variable(t, "total") == "1" and watch_line(t, "2 * total") == "2")
        # The same expression again removes it.
        s.keys("F11")
        s.wait_for("the watch line", lambda t: keys_line(t).startswith("watch: _"))
        s.raw("2 * total")
        s.keys("Enter")
        s.wait_for("the watch removed", lambda t: watch_line(t, "2 * total") is None
                   and "watch removed: 2 * total" in t.split("\n")[0])
        s.keys("F10")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def title(screen):
    return screen.split("\n")[0]


def test_back(rb):
    """Paused, Left and Right step back and forth through the run's recording: the line, the
    output as it was, the variables pane saying its values are the present's; Esc returns to
    the present and F2 runs on from there. After the end too: the robot's pose as it was, the
    output before it was printed, and a click on the position bar."""
    s = Session(rb, "debug.bas", args="--break 7")
    try:
        s.wait_for("the first stop", lambda t: running_line(t) == 7 and variable(t, "total") == "1")
        s.keys("F2")
        s.wait_for("the second stop", lambda t: running_line(t) == 7 and variable(t, "total") == "3")
        s.keys("Left")  # the gosub's return, the statement before
        s.wait_for("a step back, the state and the variables pane saying so",
                   lambda t: running_line(t) == 14 and "back in time" in title(t)
                   and (status(t, "state") or "").startswith("back at step")
                   and "variables now, not at step" in t)
        s.keys("Left", "Left")
        s.wait_for("two more back", lambda t: running_line(t) == 6)
        s.keys("Right")
        s.wait_for("one forward", lambda t: running_line(t) == 13)
        s.keys("Escape")
        t = s.wait_for("the present", lambda t: running_line(t) == 7
                       and "paused at breakpoint, line 7" in title(t))
        # F2 from an earlier step runs on from the present: the next stop is the third.
        s.keys("Left")
        s.wait_for("back again", lambda t: running_line(t) == 14)
        s.keys("F2")
        s.wait_for("the third stop", lambda t: running_line(t) == 7 and variable(t, "total") == "6"
                   and "back" not in title(t))
        s.keys("F9", "F2")
        s.wait_for("the end", lambda t: status(t, "state") == "finished" and "total 6" in output_pane(t))
        s.keys("Left")  # the `end` statement: the output was printed before it
        s.wait_for("the last statement", lambda t: running_line(t) == 10 and "total 6" in output_pane(t))
        s.keys("Left")  # the print: nothing printed yet
        s.wait_for("the print, before its output",
                   lambda t: running_line(t) == 9 and "total 6" not in output_pane(t))
        t = s.settled()
        # A click on the bar's first cell: the first statement.
        lines = t.split("\n")
        row = next(i for i, l in enumerate(lines) if l.startswith("-- output at"))
        s.click(lines[row].index("[") + 1, row)
        t = s.wait_for("the first step", lambda t: running_line(t) == 2 and "step 1 of" in title(t))
        s.keys("Escape")
        s.wait_for("the end again", lambda t: status(t, "state") == "finished")
        t = s.settled()
        check(running_line(t) is None, "the end marks a line:\n" + t)
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()
    s = Session(rb, "square.bas", args="--speed 16")
    try:
        t = s.wait_for("the end", lambda t: status(t, "state") == "finished")
        end = (status(t, "x"), status(t, "y"), status(t, "heading"))
        s.keys("Home", "Home", "Home")  # three tenths of the run back
        s.wait_for("an earlier pose, without sensors",
                   lambda t: "back in time" in title(t) and status(t, "bumper") == "-"
                   and (status(t, "x"), status(t, "y"), status(t, "heading")) != end)
        s.keys("End", "End", "End")
        s.wait_for("the present, the end's pose", lambda t: "back" not in title(t)
                   and (status(t, "x"), status(t, "y"), status(t, "heading")) == end)
        s.keys("x")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def keys_line(screen):
    lines = screen.rstrip("\n").split("\n")
    return lines[-1] if lines else ""


def test_finished(rb):
    """After the end the source pane marks no line as running and the keys line offers only
    what can still be done (no pause, step, breakpoint or speed)."""
    s = Session(rb, "debug.bas")
    try:
        t = s.wait_for("the end", lambda t: status(t, "state") == "finished")
        t = s.settled()
        check(running_line(t) is None, "a line is still marked running:\n" + t)
        keys = keys_line(t)
        check("F6 view" in keys and "F10 quit" in keys, "keys line: " + keys)
        for gone in ("F2", "F3", "F7", "F8", "F9", "F4/F5"):
            check(gone not in keys, f"the keys line still offers {gone}: " + keys)
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_speed(rb):
    """--speed sets the pace, F4 and F5 halve and double it."""
    s = Session(rb, "square.bas", args="--speed 4 --paused")
    try:
        s.wait_for("speed x4", lambda t: status(t, "speed") == "x4")
        s.keys("F5")
        s.wait_for("speed x8", lambda t: status(t, "speed") == "x8")
        s.keys("F4", "F4", "F4", "F4")
        s.wait_for("speed x1/2", lambda t: status(t, "speed") == "x1/2")
        s.keys("F10")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_text(rb):
    """Text the program draws shows as characters where its cells are readable."""
    s = Session(rb, "text.bas")
    try:
        t = s.wait_for("the end", lambda t: status(t, "state") == "finished")
        arena = "\n".join(arena_lines(t))
        check(re.search(r"H\s*E\s*L\s*L\s*O", arena) is not None,
              "the drawn text is not shown as characters:\n" + t)
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()


def test_output(rb):
    """The output pane shows the tab that ';' writes as spaces to the next 8-column stop (never
    '?'), wraps a long line instead of cutting it, and wraps a runtime error so that its hint
    stays readable."""
    def joined(t):
        # The pane is as wide as the arena's box; a wrapped line fills its rows to that width.
        lines = t.split("\n")
        width = lines[1].index("+", 1) + 1
        top = next(i for i, l in enumerate(lines) if l.startswith("-- output"))
        return "".join(l[:width].ljust(width) for l in lines[top + 1:])

    s = Session(rb, "output.bas", rows=40)
    try:
        s.wait_for("the error", lambda t: status(t, "state") == "error")
        t = s.settled()
        out = output_pane(t)
        check("with    8        sides" in out, "the tabs are not expanded:\n" + t)
        check("?" not in out.replace("did you mean 'total'?", ""), "a control character drawn as '?':\n" + t)
        check("wraps onto the rows after it: END" in joined(t), "the long line is cut:\n" + t)
        check("did you mean 'total'?" in joined(t), "the error's hint is cut:\n" + t)
        s.keys("Enter")
        check(s.exit_code() == 70, "exit status")
    finally:
        s.close()


def test_dumb(rb):
    """A terminal that cannot show the view: one line on stderr, exit 74, nothing drawn."""
    s = Session(rb, "square.bas", env={"TERM": "dumb"})
    try:
        code = s.exit_code()
        check(code == 74, f"exit status {code}")
        err = s.stderr()
        check(err.count("\n") == 1 and "dumb" in err and "without --tui" in err, "stderr: " + err)
        check("rb run square.bas" not in s.screen(), "the view was drawn:\n" + s.screen())
    finally:
        s.close()


def test_input_terminal(rb):
    """Headless `input` on a terminal: the terminal shows what was typed, so rb writes it no
    second time (from a pipe rb writes it: the conformance program input_echo)."""
    s = Session(rb, "input.bas", tui=False)
    try:
        s.wait_text("How many sides?")
        s.keys("6", "Enter")
        s.wait_text("Name?")
        s.keys("robot", "Enter")
        code = s.exit_code()
        check(code == 0, f"exit status {code}")
        lines = [l.rstrip() for l in s.screen().splitlines() if l.strip()]
        check(lines == ["How many sides? 6", "sides: 6", "Name? robot", "hello robot"],
              "the terminal shows:\n" + s.screen())
    finally:
        s.close()


def test_draw_hint(rb):
    """Headless on a terminal, a program that only draws is told where its picture is, once."""
    s = Session(rb, "drawing.bas", tui=False)
    try:
        code = s.exit_code()
        check(code == 0, f"exit status {code}")
        err = s.stderr()
        check(err.count("\n") == 1 and "rb run --tui drawing.bas" in err and "rb render drawing.bas -o" in err,
              "stderr: " + err)
    finally:
        s.close()


def test_real(rb):
    """With --real the status shows the link: the port, the commands sent, the last reply."""
    tmp = tempfile.mkdtemp(prefix="rbtui-robot-")
    link = os.path.join(tmp, "robot")
    robot = subprocess.Popen([rb, "robot", "--pty", "--link", link], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL)
    s = None
    try:
        robot.stdout.readline()  # the device: the emulator is ready
        s = Session(rb, "square.bas", args=f"--real --port {link}")
        t = s.wait_for("the link in the status", lambda t: status(t, "link") is not None
                       and status(t, "sent") not in (None, "0 commands"))
        check(link in status(t, "link"), "the port:\n" + t)
        t = s.wait_for("a reply", lambda t: (status(t, "reply") or "-").startswith("cmd "))
        s.wait_for("the end", lambda t: status(t, "state") == "finished")
        s.keys("Enter")
        code = s.exit_code()
        check(code == 0, f"exit status {code}: {s.stderr()}")
    finally:
        if s:
            s.close()
        robot.terminate()
        robot.wait(10)
        shutil.rmtree(tmp, ignore_errors=True)



def test_pixels(rb):
    """--cells pixels: the screen as a sixel image where the terminal shows them; elsewhere (tmux
    built without sixel) the best character mode, and the title says why."""
    s = Session(rb, "square.bas", args="--cells pixels", env={"LC_ALL": "C.UTF-8"})
    try:
        t = s.wait_for("the view", lambda t: "rb run square.bas" in t)
        title = t.split("\n")[0]
        check("view pixels" in title or "(no pixels: the terminal shows no sixel images)" in title,
              "title: " + title)
        s.wait_for("the end", lambda t: "finished" in t.split("\n")[0])
        s.keys("Enter")
        check(s.exit_code() == 0, "exit status")
    finally:
        s.close()



def test_sixel(rb):
    """--cells pixels on a terminal that reports sixel graphics: rb sends the screen as a sixel
    image. The terminal here is a pseudo-terminal this test answers for (tmux is not needed):
    it says it is a VT340-class terminal with sixels (CSI ? 63;4 c) and reads what rb draws."""
    import fcntl
    import pty
    import select
    import struct
    import termios
    pid, fd = pty.fork()
    if pid == 0:
        os.chdir(HERE)
        env = dict(os.environ, TERM="xterm-256color", LC_ALL="C.UTF-8")
        os.execve(rb, [rb, "run", "--tui", "--cells", "pixels", "square.bas"], env)
    fcntl.ioctl(fd, termios.TIOCSWINSZ, struct.pack("HHHH", 30, 100, 600, 1000))
    got = b""
    answered = False
    deadline = time.monotonic() + TIMEOUT
    try:
        while time.monotonic() < deadline:
            ready, _, _ = select.select([fd], [], [], 0.2)
            if not ready:
                continue
            try:
                chunk = os.read(fd, 65536)
            except OSError:
                break
            got += chunk
            if not answered and b"\x1b[c" in got:
                os.write(fd, b"\x1b[?63;4c")  # a terminal with sixel graphics
                answered = True
            if re.search(rb"\x1bPq?[0-9;]*q?\"1;1;\d+;\d+", got):
                break
        check(answered, "rb did not ask the terminal what it can do")
        check(re.search(rb"\x1bP[0-9;]*q\"1;1;\d+;\d+", got) is not None,
              f"no sixel image in rb's output ({len(got)} bytes)")
        check(b"view pixels" in got, "the title does not say pixels")
        os.write(fd, b"\x1b[21~")  # F10
        end = time.monotonic() + TIMEOUT
        while time.monotonic() < end:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                check(os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0, f"exit status {status}")
                return
            try:
                if select.select([fd], [], [], 0.2)[0]:
                    os.read(fd, 65536)
            except OSError:
                pass
        raise Failure("rb did not exit after F10")
    finally:
        try:
            os.kill(pid, 9)
            os.waitpid(pid, 0)
        except OSError:
            pass
        os.close(fd)


TESTS = {
    "square": test_square,
    "keyboard": test_keyboard,
    "mouse": test_mouse,
    "error": test_error,
    "pause_move": test_pause_move,
    "quit": test_quit,
    "resize": test_resize,
    "unicode": test_unicode,
    "motion": test_motion,
    "paused": test_paused,
    "step": test_step,
    "break": test_break,
    "speed": test_speed,
    "text": test_text,
    "dumb": test_dumb,
    "output": test_output,
    "finished": test_finished,
    "break_moved": test_break_moved,
    "restart": test_restart,
    "watch": test_watch,
    "watch_expr": test_watch_expr,
    "back": test_back,
    "real": test_real,
    "pixels": test_pixels,
    "input_terminal": test_input_terminal,
    "draw_hint": test_draw_hint,
    "sixel": test_sixel,
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("test", choices=sorted(TESTS))
    args = ap.parse_args()
    if not shutil.which("tmux"):
        print("SKIP: tmux is not installed (scripts/setup.sh installs it)")
        return 77
    try:
        TESTS[args.test](os.path.abspath(args.rb))
    except Failure as e:
        print(f"FAIL tui {args.test}: {e}")
        return 1
    print(f"PASS tui {args.test}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
