"""The built web page in headless Chromium for the browser benchmarks (bench/web_browser.py,
bench/web_fps.py), as testdata/web/page_test.py drives it: the site served by Python's
http.server, Chromium over the DevTools protocol."""
import argparse
import contextlib
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "testdata", "web"))
sys.path.insert(0, os.path.join(HERE, "..", "testdata", "render"))
from page_test import Env  # noqa: E402
from replay_browser import find_chromium  # noqa: E402

SITE = os.path.join(HERE, "..", "build-web", "site")
RB = os.path.join(HERE, "..", "build", "cmd", "rb")


@contextlib.contextmanager
def open_page(site=SITE, rb=RB):
    """The page, loaded and ready, as a Browser (replay_browser.py); SystemExit(66) when the
    site is not built or Chromium is missing."""
    chromium = find_chromium()
    if not os.path.exists(os.path.join(site, "index.html")) or not chromium:
        print("needs the site (scripts/web.sh) and Chromium", file=sys.stderr)
        raise SystemExit(66)
    work = tempfile.mkdtemp()
    env = Env(argparse.Namespace(site=site, work=work, rb=rb, source=os.path.join(HERE, "..")), chromium)
    try:
        yield env.open()
    finally:
        env.close()
        shutil.rmtree(work, ignore_errors=True)
