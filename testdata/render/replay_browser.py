#!/usr/bin/env python3
"""Replays of `rb render --animate` in a real browser: headless Chromium, driven over the
DevTools protocol on a pipe (--remote-debugging-pipe), with nothing but Python's standard library.

Usage: replay_browser.py --rb PATH/TO/rb --source SOURCE_DIR --work WORK_DIR CASE

Each CASE is one CTest test (testdata/render/CMakeLists.txt); WORK_DIR is emptied first. Exits 77
(skipped) when Chromium is not installed ($RB_CHROMIUM, else chromium or chromium-browser on the
PATH); `scripts/setup.sh --test` installs it, so CI runs these.

The HTML player must play, follow its slider and step buttons, show the run's end (and its error)
and leave on its canvas, after the last frame, exactly the pixels `rb render -o x.png` writes; at
every recorded step its canvas must be the GIF's frame for that step. The animated SVG must show
the GIF's frames at their times and, once played, exactly rb render's picture. The console must
stay free of errors throughout.
"""

import argparse
import base64
import fcntl
import hashlib
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib


class Failure(Exception):
    pass


def expect(cond, message):
    if not cond:
        raise Failure(message)


# ---------------------------------------------------------------- pictures


def read_png(data):
    """(width, height, RGB bytes) of a PNG: 8-bit RGB or RGBA (alpha dropped), or a palette of
    1, 2, 4 or 8 bits a pixel (what rb writes where a picture has at most 256 colours)."""
    expect(data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG")
    pos, idat, palette = 8, b"", None
    width = height = ctype = 0
    while pos < len(data):
        size, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + size]
        pos += 12 + size
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            expect(interlace == 0 and (depth == 8 or (ctype == 3 and depth in (1, 2, 4))),
                   f"PNG depth {depth} colour type {ctype} interlace {interlace}")
        elif kind == b"PLTE":
            palette = body
        elif kind == b"IDAT":
            idat += body
    channels = {2: 3, 6: 4, 3: 1}[ctype]
    raw = zlib.decompress(idat)
    stride = (width * channels * depth + 7) // 8  # bytes a row; the filters work on whole bytes
    rows, prev = [], bytearray(stride)
    # The "up" filter (Chromium's screenshots use only it) as whole-row arithmetic: bytes added
    # modulo 256 without carries between them.
    low = int.from_bytes(b"\x7f" * stride, "little")
    high = int.from_bytes(b"\x80" * stride, "little")
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if f == 2:
            a, b = int.from_bytes(line, "little"), int.from_bytes(prev, "little")
            line = bytearray((((a & low) + (b & low)) ^ ((a ^ b) & high)).to_bytes(stride, "little"))
        elif f == 1:
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 255
        elif f == 3:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 255
        elif f == 4:
            for i in range(stride):
                a = line[i - channels] if i >= channels else 0
                b, c = prev[i], prev[i - channels] if i >= channels else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    if depth < 8:  # indices packed several to a byte, the leftmost pixel in the high bits
        per, mask = 8 // depth, (1 << depth) - 1
        rows = [bytes((row[x // per] >> ((per - 1 - x % per) * depth)) & mask for x in range(width))
                for row in rows]
    pixels = b"".join(rows)
    if channels == 3:
        return width, height, pixels
    out = bytearray(width * height * 3)
    if channels == 4:
        out[0::3], out[1::3], out[2::3] = pixels[0::4], pixels[1::4], pixels[2::4]
    else:
        for i, index in enumerate(pixels):
            out[i * 3:i * 3 + 3] = palette[index * 3:index * 3 + 3]
    return width, height, bytes(out)


def read_gif(data):
    """The pictures a viewer shows for each image of a GIF (RGB bytes) and their delays."""
    expect(data[:6] in (b"GIF87a", b"GIF89a"), "not a GIF")
    width, height, flags = struct.unpack("<HHB", data[6:11])
    pos = 13
    table = []
    if flags & 0x80:
        n = 2 << (flags & 7)
        table = [data[pos + 3 * i:pos + 3 * i + 3] for i in range(n)]
        pos += 3 * n
    canvas = bytearray(width * height * 3)
    frames, delays = [], []
    delay, transparent = 0, None
    while True:
        block = data[pos]
        pos += 1
        if block == 0x3B:
            break
        if block == 0x21:
            label = data[pos]
            pos += 1
            subs = []
            while data[pos]:
                subs.append(data[pos + 1:pos + 1 + data[pos]])
                pos += 1 + data[pos]
            pos += 1
            if label == 0xF9:
                packed, delay, index = struct.unpack("<BHB", subs[0][:4])
                transparent = index if packed & 1 else None
            continue
        expect(block == 0x2C, f"unexpected GIF block {block:#x}")
        left, top, w, h, iflags = struct.unpack("<HHHHB", data[pos:pos + 9])
        pos += 9
        colours = table
        if iflags & 0x80:
            n = 2 << (iflags & 7)
            colours = [data[pos + 3 * i:pos + 3 * i + 3] for i in range(n)]
            pos += 3 * n
        min_code = data[pos]
        pos += 1
        lzw = bytearray()
        while data[pos]:
            lzw += data[pos + 1:pos + 1 + data[pos]]
            pos += 1 + data[pos]
        pos += 1
        indices = lzw_decode(bytes(lzw), min_code, w * h)
        for y in range(h):
            for x in range(w):
                index = indices[y * w + x]
                if index == transparent:
                    continue
                at = ((top + y) * width + left + x) * 3
                canvas[at:at + 3] = colours[index]
        frames.append(bytes(canvas))
        delays.append(delay)
    return width, height, frames, delays


def lzw_decode(data, min_code, count):
    clear, end = 1 << min_code, (1 << min_code) + 1
    size = min_code + 1
    table = [bytes([i]) for i in range(clear)] + [b"", b""]
    out = bytearray()
    bitpos, prev = 0, None
    total = len(data) * 8
    while bitpos + size <= total and len(out) < count:
        code = (int.from_bytes(data[bitpos >> 3:(bitpos >> 3) + 3], "little") >> (bitpos & 7)) & ((1 << size) - 1)
        bitpos += size
        if code == clear:
            table = table[:clear + 2]
            size, prev = min_code + 1, None
            continue
        if code == end:
            break
        if prev is None:
            entry = table[code]
        elif code < len(table):
            entry = table[code]
            table.append(prev + entry[:1])
        else:
            entry = prev + prev[:1]
            table.append(entry)
        out += entry
        prev = entry
        if len(table) == (1 << size) and size < 12:
            size += 1
    return out


def first_difference(width, a, b):
    for i in range(0, min(len(a), len(b)), 3):
        if a[i:i + 3] != b[i:i + 3]:
            return f"pixel ({i // 3 % width}, {i // 3 // width}): {a[i:i + 3].hex()} and {b[i:i + 3].hex()}"
    return "sizes differ" if len(a) != len(b) else ""


# ---------------------------------------------------------------- the browser


def find_chromium():
    for name in [os.environ.get("RB_CHROMIUM"), "chromium", "chromium-browser"]:
        if name and shutil.which(name):
            return shutil.which(name)
    return None


class Browser:
    """Headless Chromium and one page of it, over the DevTools protocol on fds 3 and 4."""

    def __init__(self, chromium, work):
        self.profile = tempfile.mkdtemp(prefix="chromium-", dir=work)
        to_chrome_r, to_chrome_w = os.pipe()
        from_chrome_r, from_chrome_w = os.pipe()

        def child():
            # Out of the way of 3 and 4 first, then onto them.
            a = fcntl.fcntl(to_chrome_r, fcntl.F_DUPFD, 10)
            b = fcntl.fcntl(from_chrome_w, fcntl.F_DUPFD, 10)
            os.dup2(a, 3)
            os.dup2(b, 4)

        self.proc = subprocess.Popen(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
             "--disable-component-update", "--disable-sync", "--no-first-run", "--no-default-browser-check",
             "--disable-extensions", "--mute-audio", "--hide-scrollbars", "--force-color-profile=srgb",
             "--user-data-dir=" + self.profile, "--remote-debugging-pipe", "about:blank"],
            pass_fds=(3, 4), preexec_fn=child, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.out, self.inp = to_chrome_w, from_chrome_r
        self.buffer = b""
        self.next_id = 0
        self.events = []
        self.errors = []
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ["Page", "Runtime", "Log"]:
            self.call(domain + ".enable", session=True)
        self.viewport(1280, 900)

    def viewport(self, width, height, scale=1):
        """The page's size in CSS pixels and device pixels per CSS pixel: a window of 1366x768 at
        200% zoom is viewport(683, 384, 2)."""
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": scale, "mobile": False}, session=True)

    def close(self):
        try:
            self.call("Browser.close", timeout=5)
        except Exception:
            pass
        try:
            self.proc.wait(10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        os.close(self.out)
        os.close(self.inp)
        shutil.rmtree(self.profile, ignore_errors=True)

    def _receive(self, deadline):
        while b"\0" not in self.buffer:
            if time.monotonic() > deadline:
                raise Failure("Chromium did not answer in time")
            chunk = os.read(self.inp, 1 << 20)
            if not chunk:
                raise Failure("Chromium closed the pipe")
            self.buffer += chunk
        message, _, self.buffer = self.buffer.partition(b"\0")
        message = json.loads(message)
        method = message.get("method", "")
        params = message.get("params", {})
        if method == "Runtime.exceptionThrown":
            self.errors.append("exception: " + json.dumps(params.get("exceptionDetails", {}))[:500])
        elif method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
            self.errors.append("console." + params["type"] + ": " + json.dumps(params.get("args", []))[:500])
        elif method == "Log.entryAdded" and params.get("entry", {}).get("level") == "error":
            self.errors.append("log: " + params["entry"].get("text", "")[:500])
        return message

    def call(self, method, params=None, session=False, timeout=60):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = self.session
        os.write(self.out, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._receive(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise Failure(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def wait_event(self, method, timeout=60):
        deadline = time.monotonic() + timeout
        for i, e in enumerate(self.events):
            if e.get("method") == method:
                del self.events[i]
                return e
        while True:
            e = self._receive(deadline)
            if e.get("method") == method:
                return e
            self.events.append(e)

    def open(self, path):
        self.events = [e for e in self.events if e.get("method") != "Page.loadEventFired"]
        self.call("Page.navigate", {"url": "file://" + os.path.abspath(path)}, session=True)
        self.wait_event("Page.loadEventFired")

    def js(self, expression, timeout=60):
        """The value of a JavaScript expression in the page (awaited when it is a promise)."""
        r = self.call("Runtime.evaluate", {"expression": expression, "awaitPromise": True, "returnByValue": True},
                      session=True, timeout=timeout)
        if "exceptionDetails" in r:
            raise Failure(f"{expression[:80]}: {json.dumps(r['exceptionDetails'])[:800]}")
        return r["result"].get("value")

    def screenshot(self, width, height):
        r = self.call("Page.captureScreenshot",
                      {"format": "png", "optimizeForSpeed": True, "clip": {"x": 0, "y": 0, "width": width, "height": height, "scale": 1}},
                      session=True)
        return read_png(base64.b64decode(r["data"]))


# The player's canvas as RGB bytes: its SHA-256 (quick), or the bytes themselves (for a message).
CANVAS_JS = """
window.__rgb = () => {
  const c = document.getElementById('screen');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  const rgb = new Uint8Array(c.width * c.height * 3);
  for (let i = 0, j = 0; i < d.length; i += 4) { rgb[j++] = d[i]; rgb[j++] = d[i + 1]; rgb[j++] = d[i + 2]; }
  return rgb;
};
window.__hash = async () => Array.from(new Uint8Array(await crypto.subtle.digest('SHA-256', __rgb())))
    .map((b) => b.toString(16).padStart(2, '0')).join('');
window.__b64 = (rgb) => {
  let s = '';
  for (let i = 0; i < rgb.length; i += 32768) s += String.fromCharCode.apply(null, rgb.subarray(i, i + 32768));
  return btoa(s);
};
window.__bytes = () => __b64(__rgb());
true
"""


class Env:
    def __init__(self, rb, source, work, chromium):
        self.rb, self.source, self.work, self.chromium = rb, source, work, chromium
        self.fig17 = os.path.join(source, "examples", "fig_1_7.bas")
        self.browser = None

    def path(self, name):
        return os.path.join(self.work, name)

    def program(self, name, text):
        p = self.path(name)
        with open(p, "w") as f:
            f.write(text)
        return p

    def render(self, *args, code=0, stdin=""):
        r = subprocess.run([self.rb, "render", *args], capture_output=True, text=True, timeout=120, input=stdin)
        expect(r.returncode == code, f"rb render {' '.join(args)}: exit {r.returncode}, expected {code}\n{r.stderr}")
        return r

    def start(self):
        self.browser = Browser(self.chromium, self.work)
        return self.browser

    def open_player(self, html):
        b = self.browser
        b.open(html)
        b.js("window.rbPlayer.ready.then(() => true)")
        b.js(CANVAS_JS)
        return b

    def expect_canvas(self, png_path, what):
        """The player's canvas is the PNG's pixels exactly."""
        width, height, want = read_png(open(png_path, "rb").read())
        got_hash = self.browser.js("__hash()")
        if got_hash == hashlib.sha256(want).hexdigest():
            return
        got = base64.b64decode(self.browser.js("__bytes()"))
        raise Failure(f"{what}: the canvas is not rb render's picture: {first_difference(width, got, want)}")

    def expect_quiet(self):
        expect(not self.browser.errors, "the console shows errors:\n" + "\n".join(self.browser.errors))


# ---------------------------------------------------------------- cases


def case_html_plays(env):
    """The seed's square: the player plays to the end, where its canvas is rb render's PNG; the
    slider and the step buttons move one recorded step; the source line follows."""
    html, png = env.path("square.html"), env.path("square.png")
    env.render(env.fig17, "--animate", html, "-o", png)
    b = env.start()
    env.open_player(html)
    expect(b.js("rbPlayer.count") == 18, f"{b.js('rbPlayer.count')} steps, expected 17 statements and the end")
    expect(b.js("rbPlayer.step") == 0, "the player does not start at the first step")
    white = b.js("__rgb().every((v) => v === 255)")
    expect(white, "the first step is not the white screen")
    # Play at four times the speed (75 frames at 10 a second: under 2 s), noting each position
    # the player shows.
    b.js("window.__seen = []; new MutationObserver(() => __seen.push(rbPlayer.step))"
         ".observe(document.getElementById('position'), {childList: true, characterData: true, subtree: true});"
         "document.getElementById('speed').value = '4'; document.getElementById('speed')"
         ".dispatchEvent(new Event('change')); document.getElementById('play').click(); true")
    expect(b.js("rbPlayer.playing"), "play did not start")
    deadline = time.monotonic() + 20
    while b.js("rbPlayer.playing"):
        expect(time.monotonic() < deadline, "the player did not reach the end")
        time.sleep(0.05)
    expect(b.js("rbPlayer.step") == 17, f"playing stopped at step {b.js('rbPlayer.step')}, not the end")
    # The animation's frames in order (a machine too busy to draw every frame in time skips
    # some, never the end): the steps' own and, before each side's and each turn's end, the
    # glide's frames, which show the step whose move they show (5 before 6, 6 before 7..).
    seen, frames = b.js("__seen"), [1, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17]
    expect(seen == sorted(seen) and set(seen) <= set(frames) and seen[-1] == 17 and len(set(seen)) >= 5,
           f"playing showed the steps {seen}, not the frames {frames} in order")
    expect(seen.count(5) > 1, f"the first side did not glide: {seen}")
    env.expect_canvas(png, "after the last frame")
    banner = b.js("document.getElementById('banner').textContent")
    expect("the program ended" in banner, f"the end is not named: {banner!r}")
    end_hash = b.js("__hash()")
    # The slider: step 6 is rTurn 90 about to run (line 7), the first side drawn.
    b.js("const t = document.getElementById('timeline'); t.value = '6'; t.dispatchEvent(new Event('input')); true")
    expect(b.js("rbPlayer.step") == 6, "the slider did not move the player")
    expect(b.js("__hash()") != end_hash, "the slider did not change the picture")
    line = b.js("document.querySelector('#source .now').textContent")
    expect(line.startswith("7") and "rTurn 90" in line, f"the current line is {line!r}, not 7: rTurn 90")
    expect(b.js("document.getElementById('banner').hidden"), "the end banner shows before the end")
    b.js("document.getElementById('back').click(); true")
    expect(b.js("rbPlayer.step") == 5, "step back did not go one recorded step back")
    line = b.js("document.querySelector('#source .now').textContent")
    expect("rForward 120" in line, f"after a step back the current line is {line!r}")
    pose = b.js("document.getElementById('pose').textContent")
    expect("x 400.00" in pose and "y 300.00" in pose and "pen down" in pose, f"the pose reads {pose!r}")
    b.js("document.getElementById('forward').click(); document.getElementById('forward').click(); true")
    expect(b.js("rbPlayer.step") == 7, "step forward did not go one recorded step on")
    pose = b.js("document.getElementById('pose').textContent")
    expect("y 180.00" in pose and "heading 90.00" in pose, f"after the first side the pose reads {pose!r}")
    env.expect_quiet()


def case_html_steps(env):
    """A roam off whole pixels: at every recorded step the player's canvas is the GIF's frame of
    that step (the GIF's frames are rb render's pictures, render/animation_test.cpp), the robot
    drawn pixel for pixel; the sensors and the output follow."""
    prog = env.program("roam.bas",
                       "input \"turn? \", t\nrLocate 400, 300\nrInvisible RED\nrPen DOWN\nfor i = 1 to 150\n"
                       "  if rFeel() then rTurn 77 else rForward 3\n  if i % 50 = 0 then rTurn t\n"
                       "  if i % 60 = 0 then print \"i = \" + i\nnext\n")
    html, gif, png = env.path("roam.html"), env.path("roam.gif"), env.path("roam.png")
    env.render(prog, "--animate", html, "--every", "1", stdin="33.3\n")
    env.render(prog, "--animate", gif, "--every", "1", "-o", png, stdin="33.3\n")
    width, _, frames, delays = read_gif(open(gif, "rb").read())
    b = env.start()
    env.open_player(html)
    count = b.js("rbPlayer.count")
    expect(count > 300, f"only {count} steps")
    # At 10 frames a second each step lasts 10/100 s; a step that changes nothing lengthens the
    # frame before it.
    start, want = 0, {}
    for k, (frame, delay) in enumerate(zip(frames, delays)):
        first = start // 10
        last = count - 1 if k + 1 == len(frames) else (start + delay) // 10 - 1
        for s in (first, last):
            want[s] = k
        start += delay
    expect(len(want) > 150, f"only {len(want)} steps to compare")
    # All in one go in the page: the steps whose canvas differs from the hash wanted.
    hashes = {s: hashlib.sha256(frames[k]).hexdigest() for s, k in want.items()}
    wrong = b.js("(async (want) => { const bad = []; for (const [s, h] of Object.entries(want)) {"
                 " rbPlayer.show(Number(s)); if (await __hash() !== h) bad.push(Number(s)); } return bad; })"
                 f"({json.dumps(hashes)})", timeout=120)
    if wrong:
        s = wrong[0]
        b.js(f"rbPlayer.show({s}); true")
        got = base64.b64decode(b.js("__bytes()"))
        raise Failure(f"{len(wrong)} steps ({wrong[:10]}...) are not the GIF's frames; step {s}: "
                      f"{first_difference(width, got, frames[want[s]])}")
    b.js(f"rbPlayer.show({count - 1}); true")
    env.expect_canvas(png, "the last step")
    sensors = b.js("document.getElementById('sensors').textContent")
    expect("rFeel" in sensors, f"no sensor shown: {sensors!r}")
    output = b.js("document.getElementById('output').textContent")
    expect(output == "turn? 33.3\ni = 60\ni = 120\n", f"the output at the end is {output!r}")
    inputs = b.js("document.getElementById('inputs').textContent")
    expect(inputs == 'input read: 1 line: "33.3"', f"the input read shows as {inputs!r}")
    b.js("rbPlayer.show(0); true")
    expect(b.js("document.getElementById('output').textContent") == "", "output shows before anything printed")
    expect(b.js("document.getElementById('inputs').textContent") == "", "input shows before it was read")
    env.expect_quiet()


def case_html_error(env):
    """A run that ends in a runtime error: the player's end is that moment, named with its line."""
    prog = env.program("crash.bas", "rLocate 400, 60\nrPen DOWN\nLineWidth 3\nfor i = 1 to 20\n  rForward 10\nnext\n")
    html, png = env.path("crash.html"), env.path("crash.png")
    r = env.render(prog, "--animate", html, "-o", png, code=70)
    expect("error" in r.stderr, f"no error on stderr: {r.stderr}")
    b = env.start()
    env.open_player(html)
    b.js("rbPlayer.show(rbPlayer.count - 1); true")
    env.expect_canvas(png, "at the error")
    banner = b.js("document.getElementById('banner').textContent")
    expect("runtime error" in banner and "line 5" in banner, f"the error is not named: {banner!r}")
    expect("runtime error" in b.js("document.getElementById('ending').textContent"), "the header does not say how it ended")
    line = b.js("document.querySelector('#source .err').textContent")
    expect("rForward 10" in line, f"the error's line is not marked: {line!r}")
    env.expect_quiet()


def case_svg(env):
    """The animated SVG: at each frame's time it shows the GIF's frame; played to its end, rb
    render's picture exactly."""
    svg, gif, png = env.path("square.svg"), env.path("square.gif"), env.path("square.png")
    env.render(env.fig17, "--animate", svg, "-o", png)
    env.render(env.fig17, "--animate", gif)
    width, height, frames, delays = read_gif(open(gif, "rb").read())
    text = open(svg).read()
    expect("<script" not in text, "the SVG has a script")
    b = env.start()
    b.open(svg)
    # Played in real time: once its animations have run (the last frame at 1 s) it shows rb
    # render's picture.
    count = b.js("document.getAnimations().length")
    expect(count == len(frames) - 1, f"{count} animations for the {len(frames) - 1} frames after the first")
    deadline = time.monotonic() + 30
    while not b.js("document.getAnimations().every((a) => a.playState === 'finished')"):
        expect(time.monotonic() < deadline, "the SVG's animations did not finish")
        time.sleep(0.1)
    b.js("new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(true))))")
    w, h, shot = b.screenshot(width, height)
    _, _, want = read_png(open(png, "rb").read())
    expect(shot == want, f"after the animation the SVG is not rb render's picture: {first_difference(w, shot, want)}")
    # Then each frame's moment, the animations held there.
    start = 0
    for k, (frame, delay) in enumerate(zip(frames, delays)):
        b.js(f"document.getAnimations().forEach((a) => {{ a.pause(); a.currentTime = {start * 10 + 5}; }});"
             "new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(true))))")
        _, _, shot = b.screenshot(width, height)
        expect(shot == frame, f"at {start}/100 s the SVG is not the GIF's frame {k}: {first_difference(width, shot, frame)}")
        start += delay
    expect(len(frames) > 5, f"only {len(frames)} frames")
    env.expect_quiet()


def case_html_glides(env):
    """The square glides: each side in 12 frames, each turn in 6; the player's canvas at every
    frame it plays is the GIF's (glides included), the steps' own frames rb render's pictures."""
    html, gif, png = env.path("square.html"), env.path("square.gif"), env.path("square.png")
    env.render(env.fig17, "--animate", html)
    env.render(env.fig17, "--animate", gif, "-o", png)
    width, _, gif_frames, _ = read_gif(open(gif, "rb").read())
    b = env.start()
    env.open_player(html)
    frames = b.js("rbPlayer.frames") or []
    expect(len(frames) == 11 + 4 * 11 + 4 * 5, f"{len(frames)} frames play, not 11 and the glides")
    expect([f[0] for f in frames if f[1] == 0] == [0, 1, 6, 7, 9, 10, 12, 13, 15, 16, 17],
           f"the steps' own frames: {frames}")
    expect(sum(1 for f in frames if f[0] == 5 and f[2] == 12) == 11, f"the first side's glide: {frames}")
    # The GIF holds the end's frame (the same picture as the last turn's) in the one before it.
    expect(len(gif_frames) == len(frames) - 1, f"{len(gif_frames)} GIF frames for {len(frames)}")
    hashes = [hashlib.sha256(f).hexdigest() for f in gif_frames] + [hashlib.sha256(gif_frames[-1]).hexdigest()]
    wrong = b.js("(async (want) => { const bad = []; const f = rbPlayer.frames;"
                 " for (let k = 0; k < f.length; k++) { if (f[k][1]) rbPlayer.glide(f[k][0], f[k][1], f[k][2]);"
                 " else rbPlayer.show(f[k][0]); if (await __hash() !== want[k]) bad.push(k); } return bad; })"
                 f"({json.dumps(hashes)})", timeout=120)
    if wrong:
        k = wrong[0]
        f = frames[k]
        b.js(f"rbPlayer.glide({f[0]}, {f[1]}, {f[2]}); true" if f[1] else f"rbPlayer.show({f[0]}); true")
        got = base64.b64decode(b.js("__bytes()"))
        raise Failure(f"{len(wrong)} frames ({wrong[:10]}...) are not the GIF's; frame {k} {f}: "
                      f"{first_difference(width, got, gif_frames[min(k, len(gif_frames) - 1)])}")
    # Mid-way along the first side the robot is half-way up it.
    b.js("rbPlayer.glide(5, 6, 12); true")
    pose = b.js("document.getElementById('pose').textContent")
    expect("y 300.00" in pose, f"a glide's panes are its step's: {pose!r}")
    b.js(f"rbPlayer.show({b.js('rbPlayer.count')} - 1); true")
    env.expect_canvas(png, "the end")
    env.expect_quiet()


FIT_JS = """(() => {
  const r = (id) => document.getElementById(id).getBoundingClientRect();
  const bottom = Math.max(...['controls', 'position', 'keys', 'banner'].map((id) => r(id).bottom));
  return {bottom, height: innerHeight, canvas: r('screen').width, canvasBottom: r('screen').bottom,
          sideways: document.documentElement.scrollWidth > innerWidth};
})()"""


def case_html_fits(env):
    """The screen fits the window with its controls, the position and the end's banner under it
    (no scrolling to reach them) at 1366 x 768, in a browser's window of that screen (about
    1366 x 650), at 1280 x 600 and at --scale 2; and in a program's page of rb test --html,
    once its replay is in view."""
    html = env.path("square.html")
    env.render(env.fig17, "--animate", html)
    big = env.path("big.html")
    env.render(env.fig17, "--animate", big, "--scale", "2")
    b = env.start()
    for page, (w, h) in [(html, (1366, 768)), (html, (1366, 650)), (html, (1280, 600)), (big, (1366, 768))]:
        b.viewport(w, h)
        env.open_player(page)
        b.js("rbPlayer.show(rbPlayer.count - 1); new Promise((r) => requestAnimationFrame(() => r(true)))")
        fit = b.js(FIT_JS)
        what = f"{os.path.basename(page)} at {w} x {h}"
        expect(fit["bottom"] <= fit["height"], f"{what}: the controls end at {fit['bottom']}, below the window ({fit})")
        expect(fit["canvas"] >= 0.7 * (h - 120) * 4 / 3 or fit["canvas"] >= 790, f"{what}: the screen is only {fit}")
        expect(not fit["sideways"], f"{what}: the page scrolls sideways")
        expect(not b.js("document.getElementById('banner').hidden"), f"{what}: no banner at the end")
    b.viewport(1366, 768)
    # The class report's program page: its replay's frame, scrolled into view, shows the whole player.
    cls = env.path("class")
    os.makedirs(cls)
    shutil.copy(env.fig17, os.path.join(cls, "square.bas"))
    report = env.path("report")
    r = subprocess.run([env.rb, "test", cls, "--html", report], capture_output=True, text=True, timeout=120)
    expect(os.path.exists(os.path.join(report, "programs", "square.html")), f"rb test --html: {r.stdout}{r.stderr}")
    b.open(os.path.join(report, "programs", "square.html"))
    frame = b.js("(() => { const f = document.querySelector('iframe.replay'); f.scrollIntoView();"
                 " const r = f.getBoundingClientRect();"
                 " return {top: r.top, bottom: r.bottom, height: innerHeight, w: f.clientWidth, h: f.clientHeight,"
                 " src: f.src}; })()")
    expect(frame["top"] >= -1 and frame["bottom"] <= frame["height"] + 1, f"the replay's frame is not in view: {frame}")
    # The player in the frame sees a window of the frame's size (a file:// frame's document is
    # out of the page's reach): the player opened alone in a window of that size.
    b.viewport(frame["w"], frame["h"])
    env.open_player(frame["src"][len("file://"):])
    inner = b.js("(() => { rbPlayer.pause(); rbPlayer.show(rbPlayer.count - 1);"
                 " const r = (id) => document.getElementById(id).getBoundingClientRect();"
                 " return {bottom: Math.max(r('controls').bottom, r('position').bottom, r('banner').bottom),"
                 " height: innerHeight, canvas: r('screen').width}; })()")
    expect(inner["bottom"] <= inner["height"], f"in the report's frame the controls end below it: {inner}")
    expect(inner["canvas"] >= 500, f"in the report's frame the screen is only {inner['canvas']} wide")
    env.expect_quiet()


def case_html_autoplay(env):
    """--autoplay: the player plays once open, not when the viewer asks for reduced motion; its
    'play on opening' box, once set, decides (remembered across replays); without --autoplay it
    waits."""
    plain, auto = env.path("plain.html"), env.path("auto.html")
    env.render(env.fig17, "--animate", plain)
    env.render(env.fig17, "--animate", auto, "--autoplay")
    b = env.start()
    settle = "new Promise((r) => setTimeout(() => r(true), 400))"
    env.open_player(plain)
    b.js(settle)
    expect(not b.js("rbPlayer.playing") and b.js("rbPlayer.step") == 0, "a replay without --autoplay plays by itself")
    expect(not b.js("document.getElementById('autoplay').checked"), "the box is ticked without --autoplay")
    env.open_player(auto)
    b.js(settle)
    expect(b.js("rbPlayer.playing || rbPlayer.step > 0"), "--autoplay did not start the replay")
    expect(b.js("document.getElementById('autoplay').checked"), "the box is not ticked with --autoplay")
    b.call("Emulation.setEmulatedMedia", {"features": [{"name": "prefers-reduced-motion", "value": "reduce"}]},
           session=True)
    env.open_player(auto)
    b.js(settle)
    expect(not b.js("rbPlayer.playing") and b.js("rbPlayer.step") == 0, "--autoplay played under reduced motion")
    expect(not b.js("document.getElementById('autoplay').checked"), "the box is ticked under reduced motion")
    # The viewer asks: ticked, remembered; the plain replay plays too, reduced motion or not.
    b.js("document.getElementById('autoplay').click(); true")
    env.open_player(plain)
    b.js(settle)
    expect(b.js("document.getElementById('autoplay').checked"), "the box's choice was not remembered")
    expect(b.js("rbPlayer.playing || rbPlayer.step > 0"), "the box's choice did not start the replay")
    # Cleared: the --autoplay replay waits.
    b.js("rbPlayer.pause(); document.getElementById('autoplay').click(); true")
    b.call("Emulation.setEmulatedMedia", {"features": []}, session=True)
    env.open_player(auto)
    b.js(settle)
    expect(not b.js("rbPlayer.playing") and b.js("rbPlayer.step") == 0, "the cleared box did not stop --autoplay")
    # rb test's replays play once scrolled into view in a program's page (the box cleared above
    # is forgotten: a fresh browser).
    b.close()
    env.browser = None
    cls = env.path("class")
    os.makedirs(cls)
    shutil.copy(env.fig17, os.path.join(cls, "square.bas"))
    report = env.path("report")
    subprocess.run([env.rb, "test", cls, "--html", report], capture_output=True, text=True, timeout=120)
    b = env.start()
    b.viewport(1366, 768)
    b.open(os.path.join(report, "programs", "square.html"))
    tree = b.call("Page.getFrameTree", session=True)["frameTree"]
    child = tree.get("childFrames", [{}])[0].get("frame", {}).get("id")
    expect(child, f"no replay frame in the program's page: {tree}")
    world = b.call("Page.createIsolatedWorld", {"frameId": child}, session=True)["executionContextId"]

    def position():
        r = b.call("Runtime.evaluate", {"expression": "document.getElementById('position').textContent",
                                        "contextId": world, "returnByValue": True}, session=True)
        return r["result"].get("value") or ""
    below = b.js("document.querySelector('iframe.replay').getBoundingClientRect().top > innerHeight")
    b.js(settle)
    if below:
        expect(position().startswith("step 1 of"), f"the report's replay played out of view: {position()!r}")
    b.js("document.querySelector('iframe.replay').scrollIntoView(); true")
    deadline = time.monotonic() + 10
    while position().startswith("step 1 of"):
        expect(time.monotonic() < deadline, "the report's replay did not start once in view")
        time.sleep(0.1)
    env.expect_quiet()


CASES = {name[len("case_"):]: fn for name, fn in globals().items() if name.startswith("case_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("case", choices=sorted(CASES))
    a = ap.parse_args()
    chromium = find_chromium()
    if not chromium:
        print("skipped: no Chromium (scripts/setup.sh --test installs it)")
        return 77
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    env = Env(a.rb, a.source, a.work, chromium)
    try:
        CASES[a.case](env)
    except Failure as e:
        print(f"FAIL {a.case}: {e}")
        return 1
    finally:
        if env.browser:
            env.browser.close()
    print(f"ok {a.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
