#!/usr/bin/env python3
"""End-to-end test of `rb lsp`: starts the server as an editor does, plays a recorded session
(session.jsonl: initialize, didOpen of a program with errors, hover, completion, signature help,
definition across #include, documentSymbol, shutdown, exit) and checks the replies' structure
and key values, then that the process exits 0.

Usage: lsp_session.py --rb PATH/TO/rb
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import threading

HERE = pathlib.Path(__file__).resolve().parent


def frame(msg):
    body = json.dumps(msg).encode("utf-8")
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


class Client:
    def __init__(self, rb, cwd):
        self.proc = subprocess.Popen([rb, "lsp", "--stdio"], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=cwd)
        self.messages = []
        self.cond = threading.Condition()
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        out = self.proc.stdout
        while True:
            length = None
            while True:
                line = out.readline()
                if not line:
                    # The server closed its output (it ended, or crashed): keep what it said on
                    # standard error for the failure message.
                    self.proc.wait()
                    self.stderr_text = self.proc.stderr.read().decode("utf-8", "replace")
                    with self.cond:
                        self.messages.append(None)
                        self.cond.notify_all()
                    return
                line = line.strip()
                if not line:
                    break
                name, _, value = line.partition(b":")
                if name.strip().lower() == b"content-length":
                    length = int(value)
            body = out.read(length)
            with self.cond:
                self.messages.append(json.loads(body))
                self.cond.notify_all()

    def send(self, msg):
        self.proc.stdin.write(frame(msg))
        self.proc.stdin.flush()

    def wait_for(self, pred, what, timeout=20):
        with self.cond:
            while True:
                for m in self.messages:
                    if m is not None and pred(m):
                        self.messages.remove(m)
                        return m
                if None in self.messages:
                    raise AssertionError(f"rb lsp closed its output while waiting for {what}; "
                                         f"its standard error: {getattr(self, 'stderr_text', '')[-3000:]}")
                if not self.cond.wait(timeout):
                    raise AssertionError(f"timed out waiting for {what}")


def check(cond, what):
    if not cond:
        raise AssertionError(what)


def labels(items):
    return {i["label"] for i in items}


def expect(reply, step):
    """Checks one reply against what the recorded step expects."""
    want = step.get("expect", {})
    check("error" not in reply, f"{step['method']}: error {reply.get('error')}")
    result = reply["result"]
    if "capabilities" in want:
        for key in want["capabilities"]:
            check(key in result["capabilities"], f"initialize: no capability {key}")
    if "contains" in want:
        text = result["contents"]["value"]
        for s in want["contains"]:
            check(s in text, f"hover: {s!r} not in {text!r}")
    if "labels" in want:
        got = labels(result)
        for s in want["labels"]:
            check(s in got, f"completion: {s} missing")
    if "no_labels" in want:
        got = labels(result)
        for s in want["no_labels"]:
            check(s not in got, f"completion: {s} offered")
    if "signature" in want:
        check(result["signatures"][0]["label"] == want["signature"], f"signature: {result}")
        check(result["activeParameter"] == want["activeParameter"], f"active parameter: {result}")
    if "definition" in want:
        check(len(result) == 1, f"definition: {result}")
        check(result[0]["uri"].endswith(want["definition"]["uri_end"]), f"definition uri: {result}")
        check(result[0]["range"]["start"]["line"] == want["definition"]["line"], f"definition line: {result}")
    if "symbols" in want:
        check([s["name"] for s in result] == want["symbols"], f"symbols: {result}")
    if "result" in want:
        check(result == want["result"], f"{step['method']}: {result!r}")


def substitute(value, mapping):
    text = json.dumps(value)
    for k, v in mapping.items():
        text = text.replace(k, v)
    return json.loads(text)


def bad_input(rb):
    """Garbage, a request before initialize, a header without a length, a body that is not JSON
    and declared lengths far above the cap (2^63 too): every one gets an error reply (or is skipped), and
    when the input closes without shutdown the server exits 1 instead of hanging."""
    import random
    rng = random.Random(11)
    junk = bytes(rng.randrange(256) for _ in range(5000)).replace(b"\n", b" ")
    data = (frame({"jsonrpc": "2.0", "id": 1, "method": "textDocument/hover", "params": {}}) +
            b"X-Nothing: 1\r\n\r\n" +
            b"Content-Length: 7\r\n\r\n{oops!}" +
            frame({"jsonrpc": "2.0", "id": 2, "method": "initialize", "params": {"capabilities": {}}}) +
            frame({"jsonrpc": "2.0", "id": 3, "method": "no/such/method", "params": {}}) +
            b"Content-Length: 40000000\r\n\r\n" + b"x" * 40000000 +
            # 2^63 bytes: not waited for; the next message is still answered.
            b"Content-Length: 9223372036854775808\r\n\r\n{}" +
            frame({"jsonrpc": "2.0", "id": 5, "method": "no/such/method", "params": {}}) +
            frame({"jsonrpc": "2.0", "id": 4, "method": "shutdown"}) +
            junk + b"\r\n\r\n")
    proc = subprocess.run([rb, "lsp"], input=data, capture_output=True, timeout=60)
    replies = []
    out = proc.stdout
    while out:
        head, sep, rest = out.partition(b"\r\n\r\n")
        check(sep and head.startswith(b"Content-Length: "), f"bad framing in the output: {out[:80]!r}")
        n = int(head.split(b":")[1])
        replies.append(json.loads(rest[:n]))
        out = rest[n:]
    codes = [(r.get("id"), r.get("error", {}).get("code")) for r in replies]
    want = [(1, -32002), (None, -32700), (None, -32700), (2, None), (3, -32601), (None, -32600),
            (None, -32600), (5, -32601), (4, None)]
    check(codes[:len(want)] == want, f"replies to bad input: {codes}")
    check(proc.returncode == 1, f"exit status {proc.returncode} after the input ended without exit")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rb", required=True)
    ap.add_argument("--bad-input", action="store_true", help="play bad input instead of the session")
    args = ap.parse_args()
    if args.bad_input:
        bad_input(os.path.abspath(args.rb))
        print("lsp bad input: OK")
        return 0
    steps = [json.loads(l) for l in (HERE / "session.jsonl").read_text().splitlines() if l.strip()]
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "lib").mkdir()
        (root / "lib" / "shapes.bas").write_text(
            "goto shapesEnd\nsub Square(size)\n  for i = 1 to 4\n    rForward size\n    rTurn 90\n"
            "  next\nendsub\nshapesEnd:\n")
        mapping = {"$ROOT_URI": root.as_uri(), "$ROOT": str(root)}
        client = Client(os.path.abspath(args.rb), tmp)
        next_id = 1
        for step in steps:
            step = substitute(step, mapping)
            msg = {"jsonrpc": "2.0", "method": step["method"], "params": step.get("params", {})}
            if step["method"] == "exit" or step.get("notification"):
                client.send(msg)
            else:
                msg["id"] = next_id
                next_id += 1
                client.send(msg)
                reply = client.wait_for(lambda m, i=msg["id"]: m.get("id") == i, step["method"])
                expect(reply, step)
            if "diagnostics" in step:
                want = step["diagnostics"]
                note = client.wait_for(lambda m: m.get("method") == "textDocument/publishDiagnostics",
                                       "publishDiagnostics")
                diags = note["params"]["diagnostics"]
                got = [(d["range"]["start"]["line"], d["severity"]) for d in diags]
                check(got == [tuple(x) for x in want["lines_severities"]], f"diagnostics: {diags}")
                for d, text in zip(diags, want["messages"]):
                    check(text in d["message"], f"diagnostic {text!r} not in {d['message']!r}")
                for d, code in zip(diags, want.get("codes", [])):
                    check(d.get("code") == code, f"diagnostic code {d.get('code')!r}, expected {code!r}")
        try:
            code = client.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            client.proc.kill()
            raise AssertionError("rb lsp did not exit after 'exit'")
        stderr = client.proc.stderr.read().decode("utf-8", "replace")
        check(code == 0, f"rb lsp exited {code}: {stderr}")
    print(f"lsp session: {len(steps)} steps OK")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except AssertionError as e:
        print(f"FAIL: {e}", file=sys.stderr)
        sys.exit(1)
