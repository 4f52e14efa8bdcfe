#!/usr/bin/env python3
"""End-to-end tests of rb's real-robot link against the robot emulator, without hardware.

Each case starts `rb robot --pty --link DIR/robot` in the background (in a fresh temporary
folder, so cases may run in parallel), runs rb against --port DIR/robot, and stops the emulator
again. Faults must stop the program with an error naming the port and the program line, with
the right exit status, on time.

Usage: link_tests.py --rb PATH/TO/rb --examples PATH/TO/examples CASE [CASE ...]
"""
import argparse
import csv
import io
import os
import select
import signal
import subprocess
import sys
import tempfile
import threading
import time
import tty

HERE = os.path.dirname(os.path.abspath(__file__))
RB = None
EXAMPLES = None


class Emulator:
    """`rb robot --pty` in the background, its log (--verbose) in a file."""

    def __init__(self, tmp, *options):
        self.link = os.path.join(tmp, "robot")
        self.log_path = os.path.join(tmp, "robot.log")
        self.log = open(self.log_path, "w")
        self.proc = subprocess.Popen([RB, "robot", "--pty", "--link", self.link, "--verbose", *options],
                                     stdout=subprocess.PIPE, stderr=self.log)
        ready, _, _ = select.select([self.proc.stdout], [], [], 10)
        if not ready:
            self.proc.kill()
            raise AssertionError("rb robot printed no device within 10 s")
        self.device = self.proc.stdout.readline().decode().strip()
        assert self.device.startswith("/dev/"), f"first line is not a device: {self.device!r}"
        assert os.path.realpath(self.link) == os.path.realpath(self.device), "the link does not point at the device"

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                code = self.proc.wait(5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                raise AssertionError("rb robot did not stop within 5 s of SIGTERM")
            if exc[0] is None:
                assert code == 0, f"rb robot exited with {code} after SIGTERM"
        self.log.close()
        if exc[0] is None:
            assert not os.path.lexists(self.link), "rb robot left its link behind"

    def log_text(self):
        with open(self.log_path) as f:
            return f.read()

    def commands(self):
        """The command bytes the emulator received, in order ("06 ff")."""
        out = []
        for line in self.log_text().splitlines():
            parts = line.split()
            if len(parts) >= 3 and len(parts[0]) == 2 and len(parts[1]) == 2 and "->" in parts:
                out.append(parts[0] + " " + parts[1])
        return out


class StandIn:
    """A robot on a pseudo-terminal that answers every two-byte command with the same five bytes,
    as the "SR15 RROS for Arduino" sketch (a firmware written for RobotBASIC's protocol) does:
    rBumper, rFeel, rSense, 0, 0. Written here, not with rb's own emulator, so that the bytes on
    the wire do not come from rb's encoding."""

    def __init__(self, reply):
        self.reply = bytes(reply)
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)  # no echo of the replies back to this side
        self.path = os.ttyname(self.slave)
        self.commands = []
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self.serve, daemon=True)
        self.thread.start()

    def serve(self):
        pending = b""
        while not self.stop.is_set():
            ready, _, _ = select.select([self.master], [], [], 0.05)
            if not ready:
                continue
            try:
                pending += os.read(self.master, 64)
            except OSError:
                return
            while len(pending) >= 2:
                self.commands.append(pending[:2].hex(" "))
                pending = pending[2:]
                os.write(self.master, self.reply)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.thread.join(5)
        os.close(self.slave)
        os.close(self.master)


def rb(*args, stdin="", timeout=30):
    start = time.monotonic()
    p = subprocess.run([RB, *args], input=stdin.encode(), capture_output=True, timeout=timeout, cwd=HERE)
    return p.returncode, p.stdout.decode(), p.stderr.decode(), time.monotonic() - start


def expect(cond, what, *context):
    if not cond:
        raise AssertionError(what + "".join("\n" + str(c) for c in context))


def trace(*args):
    code, out, err, _ = rb("trace", "--format", "csv", *args)
    expect(code == 0, f"rb trace {' '.join(args)} exited with {code}", err)
    return list(csv.DictReader(io.StringIO(out)))


def poses(events, kinds=None):
    return [(e["x"], e["y"], e["heading"]) for e in events if kinds is None or e["event"] in kinds]


# ----------------------------------------------------------------------------------------------
# Same robot, same numbers: the simulator and the emulated real robot agree.

def case_square_trace(tmp):
    sim = trace("square.bas")
    with Emulator(tmp) as robot:
        real = trace("--real", "--port", robot.link, "square.bas")
    # 11 robot events and the end record.
    expect(len(sim) == len(real) == 12, f"{len(sim)} and {len(real)} records, expected 12")
    for s, r in zip(sim, real):
        for key in ("event", "command", "args", "x", "y", "heading", "pen"):
            expect(s[key] == r[key], f"event {s['seq']}: {key} {s[key]!r} on the simulator, {r[key]!r} on the robot")


def case_fig_1_13_trace(tmp):
    sim = trace(os.path.join(EXAMPLES, "fig_1_13_sim.bas"))
    with Emulator(tmp) as robot:
        real = trace("--real", "--port", robot.link, os.path.join(EXAMPLES, "fig_1_13.bas"))
    moves = {"move", "turn"}
    expect(len(poses(sim, moves)) == 8, "Figure 1.13 should move and turn 8 times")
    expect(poses(sim, moves) == poses(real, moves), "poses differ", poses(sim, moves), poses(real, moves))


def case_fig_1_13_run(tmp):
    # Figure 1.13 as printed (Real = TRUE, PortNum = 5): --port wins over PortNum.
    with Emulator(tmp) as robot:
        code, out, err, _ = rb("run", os.path.join(EXAMPLES, "fig_1_13.bas"), "--port", robot.link)
        sent = robot.commands()
    expect(code == 0, f"exit {code}", err)
    expect(out == "" and err == "", "unexpected output", out, err)
    expect(sent == ["03 00"] + ["06 78", "0c 5a"] * 4, "commands on the wire", sent)


def case_line_poses_real(tmp):
    """rb trace --lines --real: each line event carries the real robot's pose (once every
    line event said x=0 y=0), the same poses as on the simulator."""
    sim = trace("--lines", "square.bas")
    with Emulator(tmp) as robot:
        real = trace("--lines", "--real", "--port", robot.link, "square.bas")
    # From rLocate on (before it, the simulator has no pose yet and the real robot its default).
    lines_sim = poses(sim, {"line"})[1:]
    lines_real = poses(real, {"line"})[1:]
    expect(len(lines_sim) > 10, "too few line events on the simulator", lines_sim)
    expect(lines_sim == lines_real, "line events' poses differ", lines_sim, lines_real)
    expect(any(p[1] not in ("0", "0.0") for p in lines_real[2:]), "line events at y=0", lines_real)


def case_render_real(tmp):
    """rb render --real --ascii draws the real robot where it ended (once it drew none)."""
    code, sim, err, _ = rb("render", "--ascii", "--cols", "80", "--rows", "30", "square.bas")
    expect(code == 0, f"render on the simulator: exit {code}", err)
    with Emulator(tmp) as robot:
        code, real, err, _ = rb("render", "--real", "--port", robot.link, "--ascii", "--cols", "80",
                                "--rows", "30", "square.bas")
    expect(code == 0, f"render --real: exit {code}", err)
    # The real robot draws no trail on the screen; its glyph stands where the simulator's does.
    def glyph(picture):
        return [(r, c) for r, row in enumerate(picture.splitlines()) for c, ch in enumerate(row) if ch == "^"]
    expect(glyph(sim) != [], "no robot glyph on the simulator's picture", sim)
    expect(glyph(real) == glyph(sim), "the real robot's glyph is not where the simulator's is", sim, real)


def case_gps_over_wire(tmp):
    _, sim, _, _ = rb("run", "square_gps.bas")
    with Emulator(tmp) as robot:
        code, real, err, _ = rb("run", "--real", "--port", robot.link, "square_gps.bas")
    expect(code == 0, f"exit {code}", err)
    expect(sim == real and sim.count("\n") == 4, "positions differ", sim, real)


def case_large_moves(tmp):
    with Emulator(tmp) as robot:
        code, _, err, _ = rb("run", "--real", "--port", robot.link, "large_move.bas")
        sent = robot.commands()
    expect(code == 0, f"exit {code}", err)
    want = ["03 00", "0c ff", "0c 91", "0d ff", "0d 91", "0c 5a", "03 00", "06 ff", "06 ff", "06 5a", "42 00", "42 01"]
    expect(sent == want, "commands on the wire", sent)


def case_sr15_reply_order(tmp):
    """A robot that answers as the SR15 RROS sketch does (bumper, feel, sense, then the result):
    bytes 04 10 02 00 00 are the front bumper, the left infrared sensor and the middle floor
    sensor. rb once read them as feel 4 and bumper 16 and stopped with a malformed reply."""
    readings = "print rBumper()\nprint rFeel()\nprint rSense()\n"
    real = os.path.join(tmp, "real.bas")
    with open(real, "w") as f:
        f.write("rLocate 400, 300\nrForward 10\n" + readings)
    comm = os.path.join(tmp, "comm.bas")
    with open(comm, "w") as f:
        f.write("rCommPort 5\n" + readings + "print rCommand(200, 7)\nrCommPort 0\n")
    with StandIn([4, 16, 2, 0, 0]) as robot:
        code, out, err, _ = rb("run", "--real", "--port", robot.path, real)
        expect(code == 0, f"--real: exit {code}", err)
        expect(out == "4\n16\n2\n", "--real: rBumper, rFeel, rSense", out, err)
        expect(robot.commands == ["03 00", "06 0a"], "--real: commands on the wire", robot.commands)
        del robot.commands[:]
        code, out, err, _ = rb("run", "--port", robot.path, comm)
        expect(code == 0, f"rCommPort: exit {code}", err)
        expect(out == "4\n16\n2\n0\n", "rCommPort: rBumper, rFeel, rSense, rCommand", out, err)
        # Nothing exchanged yet at rBumper(): rb asks with the status command (06 00) once.
        expect(robot.commands == ["06 00", "c8 07"], "rCommPort: commands on the wire", robot.commands)


# ----------------------------------------------------------------------------------------------
# Faults: error naming the port and the line (faults.bas:9), exit 70, on time.

def fault(tmp, options, message, limit):
    with Emulator(tmp, *options) as robot:
        code, out, err, took = rb("run", "--port", robot.link, "faults.bas")
        link = robot.link
    expect(code == 70, f"exit {code}, expected 70", err)
    expect(out == "start\n", "output", out)
    want = f"faults.bas:9:1: error: {message.format(port=link)}"
    expect(want in err, f"stderr lacks {want!r}", err)
    expect(took < limit, f"took {took:.2f} s, limit {limit} s")


def case_timeout(tmp):
    fault(tmp, ["--drop-every", "3"], "robot on {port} did not answer within 2 s", 3)


def case_slow_answer(tmp):
    with Emulator(tmp, "--latency", "3000") as robot:
        code, _, err, took = rb("run", "--port", robot.link, "--robot-timeout", "0.5", "faults.bas")
    expect(code == 70 and f"robot on {robot.link} did not answer within 0.5 s" in err, f"exit {code}", err)
    expect("faults.bas:7:1:" in err, "the error names the first robot command", err)
    expect(took < 1.5, f"took {took:.2f} s")
    with Emulator(tmp, "--latency", "100") as robot:
        code, out, err, _ = rb("run", "--real", "--port", robot.link, "square_gps.bas")
    expect(code == 0 and out.count("\n") == 4, f"a slow but timely robot works: exit {code}", err)


def case_timeout_while_waiting(tmp):
    # The run's --timeout ends a wait for a slow robot, and a long turn split into commands
    # (rTurn 10000: 40 of them, 1.5 s each), rather than after the robot's answer or the turn.
    prog = os.path.join(tmp, "turn.bas")
    with open(prog, "w") as f:
        f.write("rLocate 400, 300\nrTurn 10000\nprint \"turned\"\n")
    with Emulator(tmp, "--latency", "1500") as robot:
        code, out, err, took = rb("run", "--real", "--port", robot.link, "--robot-timeout", "3",
                                  "--timeout", "2", prog)
    expect(code == 70 and "turn.bas:2:1: error: stopped after 2 seconds (the --timeout limit)" in err,
           f"exit {code}", err)
    expect("turned" not in out, "the turn did not finish", out)
    expect(took < 2.5, f"took {took:.2f} s, the limit is 2 s")


def case_garbled(tmp):
    fault(tmp, ["--garble-every", "3"], "robot on {port} sent a malformed reply", 3)


def case_short_reply(tmp):
    fault(tmp, ["--short-every", "3"], "robot on {port} sent a short reply: 2 of 5 bytes within 2 s", 3)


def case_vanished(tmp):
    fault(tmp, ["--die-after", "2"], "lost the connection to the robot on {port}: the device hung up", 2)


def case_port_missing_real(tmp):
    missing = os.path.join(tmp, "no-robot")
    code, out, err, took = rb("run", "--real", "--port", missing, "square.bas")
    expect(code == 74, f"exit {code}, expected 74", err)
    expect(f"rb run: cannot open robot port {missing}: no such device" in err, "message", err)
    expect(took < 2, f"took {took:.2f} s")


def case_port_missing_program(tmp):
    missing = os.path.join(tmp, "no-robot")
    code, out, err, _ = rb("run", "--port", missing, "faults.bas")
    expect(code == 70, f"exit {code}, expected 70", err)
    expect(f"faults.bas:6:1: error: cannot open robot port {missing}: no such device" in err, "message", err)


def case_real_without_port(tmp):
    code, _, err, _ = rb("run", "--real", "square.bas")
    expect(code == 64, f"exit {code}", err)
    expect("--real requires --port" in err, "message", err)


def case_busy_then_released(tmp):
    with Emulator(tmp) as robot:
        holder = subprocess.Popen([RB, "run", "--port", robot.link, "hold_port.bas"], cwd=HERE,
                                  stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            line = holder.stdout.readline().decode()
            expect(line == "holding\n", "the holder did not get the port", line, holder.stderr.read1(4096) if holder.poll() is not None else "")
            code, _, err, took = rb("run", "--real", "--port", robot.link, "square.bas")
            expect(code == 74, f"second run: exit {code}, expected 74", err)
            expect(f"robot port {robot.link} is busy" in err, "message", err)
            expect(took < 2, f"took {took:.2f} s")
            holder.stdin.write(b"x\n")
            holder.stdin.flush()
            line = holder.stdout.readline().decode()
            expect(line == "x\n", "the echo of the line input read", line)
            line = holder.stdout.readline().decode()
            expect(line == "released\n", "after rCommPort 0", line)
            code, _, err, _ = rb("run", "--real", "--port", robot.link, "square.bas")
            expect(code == 0, f"after rCommPort 0 the port is free: exit {code}", err)
            holder.stdin.write(b"y\n")
            holder.stdin.close()
            expect(holder.wait(10) == 0, "the holder failed", holder.stderr.read().decode())
        finally:
            if holder.poll() is None:
                holder.kill()
                holder.wait()


def case_emulator_sessions(tmp):
    # One emulator, several runs in turn; a stale symbolic link from a killed emulator is
    # replaced; usage without --pty is refused.
    os.symlink("/nonexistent", os.path.join(tmp, "robot"))
    with Emulator(tmp) as robot:
        for _ in range(3):
            code, out, err, _ = rb("run", "--real", "--port", robot.link, "square_gps.bas")
            expect(code == 0 and out.count("\n") == 4, f"exit {code}", err)
    code, _, err, _ = rb("robot")
    expect(code == 64 and "--pty" in err, f"rb robot without --pty: exit {code}", err)


def case_ports(tmp):
    """rb ports lists the system's ports (whatever they are) and describes the emulator's pty."""
    code, out, err, _ = rb("ports")
    expect(code == 0, f"rb ports exited {code}", err)
    expect(out.startswith("--port  device") or out == "no serial ports found\n", "rb ports' table", out)
    with Emulator(tmp) as robot:
        code, out, err, _ = rb("ports", robot.device)
        expect(code == 0, f"rb ports DEVICE exited {code}", err)
        lines = out.splitlines()
        expect(len(lines) == 2 and lines[0].startswith("--port  device"), "table", out)
        # A pty has no COM number: only its path opens it.
        expect(lines[1].split()[:2] == ["-", robot.device], "the pty's row", out)


def main():
    global RB, EXAMPLES
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("--examples", required=True)
    ap.add_argument("cases", nargs="+")
    args = ap.parse_args()
    RB = os.path.abspath(args.rb)
    EXAMPLES = os.path.abspath(args.examples)
    failed = 0
    for name in args.cases:
        fn = globals().get("case_" + name)
        if not fn:
            print(f"no such case: {name}")
            return 2
        with tempfile.TemporaryDirectory(prefix="rb-link-") as tmp:
            try:
                fn(tmp)
                print(f"PASS {name}")
            except (AssertionError, subprocess.TimeoutExpired) as e:
                failed += 1
                print(f"FAIL {name}: {e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
