#!/usr/bin/env python3
"""Frames a second on the web page while the robot roams, sensing every step: headless Chromium
(as testdata/web/page_test.py drives it) runs a program whose robot drives about an arena of
obstacles at the page's default speed, reading rFeel and rRange before every step, and counts
for N seconds (default 5) the page's animation frames (requestAnimationFrame callbacks: the page
stays responsive) and the screen's updates (putImageData on the canvas: what the user sees move).

Usage: bench/web_fps.py [--seconds N] [--speed S]   (scripts/web.sh builds the site first)
"""
import argparse
import sys
import time

from web_page import open_page

ROAM = """rectangle 100, 100, 200, 500
rectangle 600, 100, 700, 500
circle 350, 250, 450, 350
rLocate 400, 500
while true
  if rFeel() > 0 or rRange(0) < 15
    rTurn 90 + random(90)
  else
    rForward 1
  endif
wend
"""

COUNT_JS = """
(() => {
  window.__frames = 0; window.__draws = 0;
  const tick = () => { window.__frames++; requestAnimationFrame(tick); };
  requestAnimationFrame(tick);
  const put = CanvasRenderingContext2D.prototype.putImageData;
  CanvasRenderingContext2D.prototype.putImageData = function (...a) { window.__draws++; return put.apply(this, a); };
  return true;
})()
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seconds", type=float, default=5)
    ap.add_argument("--speed", help="the page's speed field (default: as the page starts)")
    a = ap.parse_args()
    with open_page() as b:
        b.js(COUNT_JS)
        if a.speed is not None:
            b.js(f"document.getElementById('speed').value = {a.speed!r}; "
                 "document.getElementById('speed').dispatchEvent(new Event('input')); true")
        b.js(f"rbPage.setSource({ROAM!r}); window.__run = rbPage.runProgram(); true")
        time.sleep(1)  # the run under way
        f0, d0 = b.js("[window.__frames, window.__draws]")
        t0 = time.monotonic()
        time.sleep(a.seconds)
        f1, d1 = b.js("[window.__frames, window.__draws]")
        t = time.monotonic() - t0
        b.js("rbPage.stopProgram(); true")
        end = b.js("window.__run.then(() => ({status: rbLastRun.status, steps: rbLastRun.steps, "
                   "error: rbLastRun.error}))", timeout=10)
        print(f"{t:.1f} s of roaming: {(f1 - f0) / t:.1f} animation frames/s, {(d1 - d0) / t:.1f} screen updates/s; "
              f"the run: {end}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
