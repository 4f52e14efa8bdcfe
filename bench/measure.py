"""What the bench scripts share: one run of a command with its wall time, processor time and
peak resident memory (the child's own, from wait4), runs that take turns between commands so
that background load falls on all of them alike, medians, and the machine's description.
Import it from a script in bench/ (sys.path gets this folder)."""
import os
import platform
import statistics
import subprocess
import tempfile
import time


class Failed(Exception):
    pass


def run_once(cmd, expect=None, cwd=None):
    """Runs cmd once. Returns (wall seconds, cpu seconds, peak RSS in KiB, stdout text).
    Raises Failed on a non-zero exit or, when `expect` is given, a different standard output
    (compared without trailing white space)."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err, \
            tempfile.NamedTemporaryFile("r") as peak:
        # The peak memory comes from GNU time when there is one: a child forked from Python
        # keeps Python's high-water mark across exec, so wait4's figure is at least Python's.
        timed = (["/usr/bin/time", "-f", "%M", "-o", peak.name] + cmd
                 if os.path.exists("/usr/bin/time") else cmd)
        t = time.perf_counter()
        p = subprocess.Popen(timed, stdout=out, stderr=err, cwd=cwd)
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.perf_counter() - t
        try:
            maxrss = int(peak.read().strip().splitlines()[-1])
        except (ValueError, IndexError):
            maxrss = usage.ru_maxrss
        p.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        text = out.read().decode(errors="replace")
        if p.returncode != 0:
            raise Failed(f"{' '.join(cmd)}: exit {p.returncode}: {err.read().decode(errors='replace')[:400]}")
        if expect is not None and text.strip() != expect.strip():
            raise Failed(f"{' '.join(cmd)}: printed {text.strip()[:200]!r}, expected {expect.strip()[:200]!r}")
        return wall, usage.ru_utime + usage.ru_stime, maxrss, text


def alternate(jobs, runs):
    """jobs: {name: (cmd, expect)}. Runs each job `runs` times, one round of all jobs at a time.
    Returns {name: {"wall": median s, "cpu": median s, "rss": max KiB, "walls": [...]}}."""
    got = {name: {"walls": [], "cpus": [], "rss": 0} for name in jobs}
    for _ in range(runs):
        for name, (cmd, expect) in jobs.items():
            wall, cpu, rss, _ = run_once(cmd, expect)
            g = got[name]
            g["walls"].append(wall)
            g["cpus"].append(cpu)
            g["rss"] = max(g["rss"], rss)
    for g in got.values():
        g["wall"] = statistics.median(g["walls"])
        g["cpu"] = statistics.median(g["cpus"])
    return got


def machine():
    """One line: CPU model, cores, memory, kernel, load average."""
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
        with open("/proc/meminfo") as f:
            mem = int(f.readline().split()[1]) / 1024 / 1024
    except OSError:
        mem = 0
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else 0
    return (f"{model}, {os.cpu_count()} cores, {mem:.0f} GiB, Linux {platform.release()}, "
            f"load average {load:.1f} at start")


def ms(seconds):
    return f"{seconds * 1000:.0f} ms" if seconds >= 0.0995 else f"{seconds * 1000:.1f} ms"


def mib(kib):
    return f"{kib / 1024:.1f} MiB"
