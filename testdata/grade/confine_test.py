#!/usr/bin/env python3
"""What a graded program may touch, tried as an attacker in the class would (docs/confinement.md):
one CTest test per hole, each failing on an rb without the layer that closes it.

Usage: confine_test.py --rb PATH/TO/rb --work WORK_DIR [--no-landlock PATH] CASE

WORK_DIR is emptied first; the cases build a class folder and a teacher's folder beside it. Exit
77: skipped (the kernel lacks what the case needs).
"""

import argparse
import json
import os
import shutil
import signal
import stat
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grade_test import Failure, Skip, expect  # noqa: E402


class Env:
    def __init__(self, rb, work, no_landlock):
        self.rb, self.work, self.no_landlock = rb, work, no_landlock

    def path(self, *names):
        return os.path.join(self.work, *names)

    def write(self, name, text, mode="w"):
        p = self.path(name)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        with open(p, mode) as f:
            f.write(text)
        return p

    def read(self, name):
        with open(self.path(name), errors="replace") as f:
            return f.read()

    def run(self, *args, timeout=120, cwd=None):
        return subprocess.run([self.rb, *args], capture_output=True, text=True, timeout=timeout,
                              cwd=cwd or self.work, errors="replace")

    def teacher(self):
        """The teacher's folder beside the class: what no student may reach."""
        self.write("teacher/.bashrc", "alias ls='ls --color'\n")
        self.write("teacher/secret.txt", "PASSWORD=hunter2\n")
        self.write("teacher/notes.txt", "grades are due friday\n")
        self.write("teacher/solution.bas", 'print "the answer is 42"\n')
        return self.path("teacher")

    def snapshot(self, folder):
        """Every file below `folder` with its bytes (links as their targets' text)."""
        out = {}
        for root, dirs, files in os.walk(self.path(folder)):
            for name in dirs + files:
                p = os.path.join(root, name)
                rel = os.path.relpath(p, self.path(folder))
                if os.path.islink(p):
                    out[rel] = "-> " + os.readlink(p)
                elif os.path.isfile(p):
                    with open(p, "rb") as f:
                        out[rel] = f.read()
        return out


def assignment(env, text="[[check]]\nkind = \"no-error\"\n", name="a.toml"):
    return env.write(name, text)


def programs(doc):
    return {os.path.basename(p["program"]): p for p in doc["programs"]}


# 1. A name that cannot be resolved (too long, a loop of links) was resolved from its spelling,
#    and the kernel then followed the link out of the folder.
def case_unresolvable(env):
    env.teacher()
    os.makedirs(env.path("class"))
    os.symlink("../teacher", env.path("class", "home"))
    os.symlink("loop", env.path("class", "loop"))
    env.write("class/payload.txt", "rm -rf ~\n")
    long_name = "home/" + "x/../" * 1100 + ".bashrc"
    env.write("class/long.bas", f'FileRename "payload.txt", "{long_name}"\nprint "renamed"\n')
    env.write("class/loop.bas", 'FileRename "loop/../home/secret.txt", "stolen.txt"\nprint "moved"\n')
    before = env.snapshot("teacher")
    for prog in ("long.bas", "loop.bas"):
        r = env.run("run", env.path("class", prog))
        expect(r.returncode == 70, f"rb run {prog}: refused (exit 70), got {r.returncode}", r.stdout, r.stderr)
        expect("renamed" not in r.stdout and "moved" not in r.stdout, f"{prog} went on", r.stdout)
    expect("too long" in env.run("run", env.path("class", "long.bas")).stderr, "a long name says so")
    expect("too many symbolic links" in env.run("run", env.path("class", "loop.bas")).stderr, "a loop says so")
    expect(env.snapshot("teacher") == before, "the teacher's folder changed", env.snapshot("teacher"))
    expect(not os.path.exists(env.path("class", "stolen.txt")), "a teacher's file came into the class")
    # rb test alike (one folder per student, the links in the student's folder).
    os.makedirs(env.path("class2", "ana"))
    os.symlink("../../teacher", env.path("class2", "ana", "home"))
    os.symlink("loop", env.path("class2", "ana", "loop"))
    env.write("class2/ana/payload.txt", "rm -rf ~\n")
    shutil.copy(env.path("class", "long.bas"), env.path("class2", "ana", "long.bas"))
    shutil.copy(env.path("class", "loop.bas"), env.path("class2", "ana", "loop.bas"))
    r = env.run("test", "--format", "json", "-a", assignment(env), env.path("class2"))
    for name, p in programs(json.loads(r.stdout)).items():
        expect(p["result"] == "fail", f"{name} passed", p)
    expect(env.snapshot("teacher") == before, "rb test: the teacher's folder changed")


# 2. `// args:` passed rb's own options for its jobs.
def case_internal_args(env):
    env.teacher()
    os.makedirs(env.path("class"))
    env.write("class/screen.bas", "// args: --screen ../teacher/notes.txt\nprint 1 // expect: 1\n")
    env.write("class/replay.bas", "// args: --replay ../teacher/replay.html\nprint 1 // expect: 1\n")
    env.write("class/ports.bas", "// args: --ports\nrCommPort 1\nprint 1 // expect: 1\n")
    env.write("class/world.bas", "// args: --world ../teacher/secret.txt\nprint 1 // expect: 1\n")
    env.write("class/record.bas", "// args: --record ../teacher/notes.txt -- ../teacher/solution.bas\nprint 1 // expect: 1\n")
    before = env.snapshot("teacher")
    r = env.run("test", "--format", "json", env.path("class"))
    doc = json.loads(r.stdout)
    expect(env.snapshot("teacher") == before, "the teacher's folder changed", r.stdout)
    expect("hunter2" not in r.stdout and "hunter2" not in r.stderr, "the secret is quoted", r.stdout)
    expect("the answer is 42" not in r.stdout, "the solution ran", r.stdout)
    by = programs(doc)
    for name in ("screen.bas", "replay.bas", "world.bas", "record.bas"):
        notes = "\n".join(by[name].get("notes", []))
        expect("not an option of rb run a program's comments may give" in notes, f"{name}: no note", by[name])
        expect(by[name]["result"] == "pass", f"{name} did not run as if the option were not there", by[name])
    expect("opens no serial port" in by["ports.bas"]["errors"], "--ports granted a port", by["ports.bas"])
    # Trusting the comments grants rb run's options, never rb test's own.
    r = env.run("test", "--format", "json", "--trust-comments", env.path("class", "screen.bas"))
    expect(env.snapshot("teacher") == before, "--trust-comments: the teacher's folder changed", r.stdout)


# 3. A class file that is a link to a file outside the class folder was graded and shown.
def case_link_out(env):
    env.teacher()
    os.makedirs(env.path("class"))
    os.symlink(env.path("teacher", "secret.txt"), env.path("class", "leak.bas"))
    os.symlink("../teacher", env.path("class", "teacherdir"))
    os.mkfifo(env.path("class", "pipe.bas"))
    env.write("class/ok.bas", "print 1\n")
    html, fb = env.path("html"), env.path("feedback")
    r = env.run("test", "--format", "json", "-a", assignment(env), "--html", html, "--feedback", fb,
                env.path("class"), timeout=60)
    by = programs(json.loads(r.stdout))
    expect("leads out of the class folder" in by["leak.bas"]["reason"], "the link is graded", by["leak.bas"])
    expect("FIFO" in by["pipe.bas"]["reason"], "the FIFO is not listed as such", by)
    everything = r.stdout + r.stderr
    for root, _, files in os.walk(env.path()):
        if root.startswith(env.path("teacher")):
            continue
        for f in files:
            p = os.path.join(root, f)
            if os.path.isfile(p) and not os.path.islink(p) and stat.S_ISREG(os.stat(p).st_mode):
                with open(p, "rb") as fh:
                    everything += fh.read().decode("utf-8", "replace")
    expect("hunter2" not in everything, "the secret reached a report")
    t = env.run("test", env.path("class"))
    expect("hunter2" not in t.stdout, "the comment mode's table shows the secret", t.stdout)
    expect("leads out of the class folder" in t.stdout, "comment mode lists the link", t.stdout)


# 4. In a flat class folder a program changed classmates' work and the roster.
def case_flat_class(env):
    os.makedirs(env.path("class"))
    env.write("class/roster.csv", "student,file\nAna,ana.bas\nBen,ben.bas\nCy,cy.bas\n")
    env.write("class/ana.bas",
              'FileRename "ben.bas", "ben.old"\nFileRename "cy.bas", ".cy"\nFileRename "roster.csv", "gone.csv"\n'
              'print 1\n')
    env.write("class/ben.bas", 'print "ben"\n')
    env.write("class/cy.bas", 'print "cy"\n')
    before = env.snapshot("class")
    a = assignment(env, 'roster = "class/roster.csv"\n[[check]]\nkind = "no-error"\n')
    r = env.run("test", "--format", "json", "-j", "1", "-a", a, env.path("class"))
    by = programs(json.loads(r.stdout))
    expect(env.snapshot("class") == before, "the class folder changed", env.snapshot("class"))
    expect(by["ana.bas"]["result"] == "fail" and "No such file" in by["ana.bas"]["reason"],
           "ana's program saw its classmates' files", by["ana.bas"])
    expect(by["ben.bas"]["result"] == "pass" and by["cy.bas"]["result"] == "pass", "the others are graded", by)
    expect(all(p["result"] != "missing" for p in by.values()), "a student is missing", by)


# 5. A program that renamed a decoy over its own file defeated --similarity and the report.
def case_decoy(env):
    os.makedirs(env.path("class", "ana"))
    os.makedirs(env.path("class", "ben"))
    body = ("rInvisible GREEN\nLineWidth 4\nrPen DOWN\nsides = 0\nfor n = 1 to 4\n  rForward 120\n"
            "  rTurn 90\n  sides = sides + 1\n  if rBumper() > 0 then\n    print \"bumped at side \" + sides\n"
            "    rTurn 180\n  endif\nnext\nwhile sides < 8\n  rForward 10\n  sides = sides + 1\nwend\n"
            "print \"perimeter \" + 4 * 120\nprint \"step 29\"\n")
    env.write("class/ben/square.bas", "rLocate 400, 300\n" + body)
    env.write("class/ana/decoy.bas", 'print "all my own work"\n')
    env.write("class/ana/square.bas", "rLocate 400, 300\n" + body + 'FileRename "decoy.bas", "square.bas"\n')
    before = env.snapshot("class")
    html = env.path("html")
    r = env.run("test", "--format", "json", "--similarity", "--html", html, "-a", assignment(env), env.path("class"))
    doc = json.loads(r.stdout)
    expect(env.snapshot("class") == before, "the class folder changed")
    pairs = doc.get("similarity", [])
    expect(any("ana" in json.dumps(p) and "ben" in json.dumps(p) for p in pairs), "the copy is not found", doc.get("similarity"))
    page = next(f for f in os.listdir(os.path.join(html, "programs")) if f.startswith("ana_square"))
    with open(os.path.join(html, "programs", page)) as f:
        text = f.read()
    expect("all my own work" not in text and "step 29" in text, "the page shows the decoy", text[:400])


# 8. class/x/y.bas and class/x_y.bas shared one feedback file, picture and replay.
def case_report_names(env):
    os.makedirs(env.path("class", "x"))
    env.write("class/x/y.bas", 'rLocate 100, 100\nprint "from the folder"\n')
    env.write("class/x_y.bas", 'rLocate 500, 500\nprint "from the flat file"\n')
    fb, pics = env.path("feedback"), env.path("pictures")
    r = env.run("test", "-a", assignment(env), "--feedback", fb, "--pictures", pics, "--replays", "html", env.path("class"))
    expect(r.returncode == 0, f"exit {r.returncode}", r.stdout, r.stderr)
    feedback = sorted(os.listdir(fb))
    expect(len(feedback) == 2, "two feedback files", feedback)
    texts = []
    for f in feedback:
        with open(os.path.join(fb, f)) as fh:
            texts.append(fh.read())
    expect(sum("x/y.bas" in t for t in texts) == 1 and sum("x_y.bas" in t and "x/y.bas" not in t for t in texts) == 1,
           "each program its own feedback", texts)
    expect(len([f for f in os.listdir(pics) if f.endswith(".png")]) == 2, "two pictures", os.listdir(pics))
    expect(len([f for f in os.listdir(pics) if f.endswith(".html")]) == 2, "two replays", os.listdir(pics))


# 9. A FIFO where a picture goes blocked rb test with its signals held back; after SIGKILL of rb
#    test its programs ran on.
def case_fifo_and_kill(env):
    os.makedirs(env.path("class"))
    env.write("class/p.bas", "rLocate 100, 100\nrForward 50\n")
    pics = env.path("pictures")
    os.makedirs(pics)
    os.mkfifo(os.path.join(pics, "p.png"))
    os.mkfifo(os.path.join(pics, "p.html"))
    start = time.time()
    r = env.run("test", "-a", assignment(env), "--pictures", pics, "--replays", "html", env.path("class"), timeout=60)
    expect(time.time() - start < 30, "rb test waited on the FIFO")
    expect(r.returncode == 74 and "FIFO nothing reads from" in r.stderr, f"exit {r.returncode}", r.stderr)
    expect(stat.S_ISFIFO(os.stat(os.path.join(pics, "p.html")).st_mode), "the replay's FIFO was replaced")
    # SIGKILL of rb test: its programs end with it.
    env.write("hung/a.bas", "// timeout: 30\nwhile 1\nwend\n")
    env.write("hung/b.bas", "// timeout: 30\nwhile 1\nwend\n")
    proc = subprocess.Popen([env.rb, "test", "-j", "2", env.path("hung")], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    kids = []
    for _ in range(100):
        kids = children(proc.pid)
        if len(kids) == 2:
            break
        time.sleep(0.05)
    expect(len(kids) == 2, "two programs running", kids)
    proc.kill()
    proc.wait()
    time.sleep(0.5)
    alive = [k for k in kids if os.path.exists(f"/proc/{k}") and state(k) != "Z"]
    expect(not alive, "programs ran on after rb test was killed", alive)


def children(pid):
    out = []
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                with open(f"/proc/{d}/stat") as f:
                    fields = f.read().rsplit(")", 1)[1].split()
                if int(fields[1]) == pid:
                    out.append(int(d))
            except OSError:
                pass
    return out


def state(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0]
    except OSError:
        return "gone"


def status_fields(pid):
    with open(f"/proc/{pid}/status") as f:
        return dict(line.split(":", 1) for line in f.read().splitlines() if ":" in line)


# The kernel's layer: a graded child runs with no new privileges and a seccomp filter.
def case_kernel_status(env):
    os.makedirs(env.path("class"))
    env.write("class/wait.bas", "while 1\nwend\n")
    a = assignment(env, "[run]\ntimeout = 20\n[[check]]\nkind = \"no-error\"\n")
    proc = subprocess.Popen([env.rb, "test", "-a", a, env.path("class")], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    try:
        fields = {}
        for _ in range(200):
            kids = children(proc.pid)
            if kids:
                fields = status_fields(kids[0])
                if fields.get("Seccomp", "").strip() == "2":
                    break
            time.sleep(0.05)
        expect(fields.get("NoNewPrivs", "").strip() == "1", "NoNewPrivs", fields.get("NoNewPrivs"))
        expect(fields.get("Seccomp", "").strip() == "2", "Seccomp", fields.get("Seccomp"))
        if os.geteuid() == 0:
            expect(fields.get("CapEff", "").strip() == "0000000000000000", "root's capabilities kept", fields.get("CapEff"))
    finally:
        proc.kill()
        proc.wait()


# A teacher grants Spawn: what the program starts cannot read outside its scratch folder, even by
# an absolute path, and gets nothing of rb test's environment.
def case_spawn_confined(env):
    if not landlock():
        raise Skip("the kernel has no Landlock")
    teacher = env.teacher()
    secret = os.path.join(teacher, "secret.txt")
    os.makedirs(env.path("class"))
    env.write("data/maze.txt", "####\n#  #\n####\n")
    env.write("class/spy.bas",
              f'print "cat: " + Spawn("cat {secret}", 0)\n'
              f'print "own: " + Spawn("cat maze.txt > /dev/null", 0)\n'
              f'print "write: " + Spawn("echo x > {teacher}/planted.txt", 0)\n'
              'print "env: " + Spawn("env | grep -q GRADER_TOKEN", 0)\n'
              'print "net: " + Spawn("bash -c \'exec 3<>/dev/tcp/127.0.0.1/9\'", 0)\n')
    a = assignment(env, '[run]\nspawn = true\nfiles = ["data/maze.txt"]\n[[check]]\nkind = "output"\n'
                        'regex = ["cat: [1-9]", "own: 0", "write: [1-9]", "env: 1", "net: [1-9]"]\n')
    envvars = dict(os.environ, GRADER_TOKEN="s3cr3t")
    r = subprocess.run([env.rb, "test", "--format", "json", "-a", a, env.path("class")], capture_output=True,
                       text=True, timeout=60, env=envvars)
    p = programs(json.loads(r.stdout))["spy.bas"]
    expect("hunter2" not in r.stdout, "the spawned cat read the teacher's secret", r.stdout)
    expect(p["result"] == "pass", "confined as expected", p, r.stderr)
    expect(not os.path.exists(os.path.join(teacher, "planted.txt")), "a file was planted in the teacher's folder")


# rb test --in-process (the web page's way: no child processes) has rb's own rules alone, which
# cannot confine what a program starts: a program that may start others (spawn = true) is not
# run, and nothing it would have started reaches the teacher's folder or rb test's own output.
def case_in_process_spawn(env):
    teacher = env.teacher()
    os.makedirs(env.path("class"))
    env.write("class/spy.bas",
              f'print "write: " + Spawn("echo x > {teacher}/planted.txt", 0)\n'
              'print "out: " + Spawn("for fd in 1 2 3 4 5 6 7 8 9; do echo INJECTED >&$fd; done", 0)\n')
    a = assignment(env, '[run]\nspawn = true\n[[check]]\nkind = "no-error"\n')
    r = subprocess.run([env.rb, "test", "--in-process", "--format", "json", "-a", a, env.path("class")],
                       capture_output=True, text=True, timeout=60)
    p = programs(json.loads(r.stdout))["spy.bas"]
    expect(p["result"] == "error" and "spawn = true" in p["reason"], "a program that may start others is not run", p)
    expect(not os.path.exists(os.path.join(teacher, "planted.txt")), "a file was planted in the teacher's folder")
    expect("INJECTED" not in r.stdout + r.stderr, "a started program wrote to rb test's output", r.stdout, r.stderr)


def landlock():
    """The kernel's Landlock ABI version, 0 without it (landlock_create_ruleset's version query)."""
    import ctypes
    libc = ctypes.CDLL(None, use_errno=True)
    return max(0, libc.syscall(444, None, ctypes.c_size_t(0), ctypes.c_uint32(1)))


# Where the kernel has no Landlock, every report says so once, and --require-sandbox refuses.
def case_no_landlock(env):
    if not env.no_landlock:
        raise Skip("no rb_no_landlock helper")
    os.makedirs(env.path("class"))
    env.write("class/p.bas", "print 1\n")
    a = assignment(env)
    run = [env.no_landlock, env.rb]
    r = subprocess.run(run + ["test", "--format", "json", "-a", a, env.path("class")], capture_output=True, text=True)
    doc = json.loads(r.stdout)
    expect("no Landlock" in doc.get("confinement", ""), "the JSON report says nothing", doc.keys())
    t = subprocess.run(run + ["test", "-a", a, env.path("class")], capture_output=True, text=True)
    expect(t.stdout.count("no Landlock") == 1, "the table says it once", t.stdout)
    q = subprocess.run(run + ["test", "--require-sandbox", "-a", a, env.path("class")], capture_output=True, text=True)
    expect(q.returncode == 69 and "--require-sandbox" in q.stderr, f"exit {q.returncode}", q.stderr)
    s = subprocess.run(run + ["run", "--require-sandbox", env.path("class", "p.bas")], capture_output=True, text=True)
    expect(s.returncode == 70 and "cannot confine" in s.stderr, f"rb run: exit {s.returncode}", s.stderr)
    ok = subprocess.run(run + ["run", env.path("class", "p.bas")], capture_output=True, text=True)
    expect(ok.returncode == 0 and ok.stdout == "1\n", "rb run without the option runs", ok.stdout, ok.stderr)


CASES = {name[5:]: fn for name, fn in globals().items() if name.startswith("case_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--no-landlock", default="")
    ap.add_argument("case", nargs="?")
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    if args.list:
        print(";".join(CASES))
        return 0
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    env = Env(os.path.abspath(args.rb), os.path.abspath(args.work), args.no_landlock)
    try:
        CASES[args.case](env)
    except Skip as e:
        print(f"skipped: {e}")
        return 77
    except Failure as e:
        print(f"FAIL {args.case}: {e}")
        return 1
    print(f"ok {args.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
