"""Helpers for the `raycast serve` tests: start the server on a free port, talk HTTP to it,
decode PNG files (stdlib only: zlib)."""
import http.client
import json
import os
import signal
import struct
import subprocess
import time
import zlib

BINARY = os.environ.get("RAYCAST_BINARY", "build/release/raycast")


class Server:
    """`raycast serve SCENE --port 0`, stopped with SIGTERM."""

    def __init__(self, scene, *extra):
        self.proc = subprocess.Popen([BINARY, "serve", scene, "--port", "0", *extra],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.proc.stdout.readline()
        if "http://" not in line:
            self.proc.kill()
            raise RuntimeError("no URL printed: %r %r" % (line, self.proc.stderr.read()))
        self.url = line.split()[2]
        self.host, port = self.url[len("http://"):].rstrip("/").rsplit(":", 1)
        self.port = int(port)

    def request(self, method, path, body=None, headers=None, timeout=10):
        """(status, headers, body bytes); path is sent exactly as given."""
        conn = http.client.HTTPConnection(self.host, self.port, timeout=timeout)
        all_headers = {}
        if body is not None and not isinstance(body, bytes):
            body = json.dumps(body).encode()
            all_headers["Content-Type"] = "application/json"
        all_headers.update(headers or {})
        conn.request(method, path, body=body, headers=all_headers)
        response = conn.getresponse()
        data = response.read()
        conn.close()
        return response.status, dict(response.getheaders()), data

    def get_json(self, path):
        status, _, data = self.request("GET", path)
        assert status == 200, (path, status, data)
        return json.loads(data)

    def post(self, path, body=None, **kw):
        status, _, data = self.request("POST", path, body if body is not None else {}, **kw)
        return status, json.loads(data) if data else None

    def wait(self, predicate, timeout=15):
        """Polls /state until predicate(state) holds; returns that state."""
        deadline = time.monotonic() + timeout
        while True:
            state = self.get_json("/state")
            if predicate(state):
                return state
            if time.monotonic() > deadline:
                raise AssertionError("timed out waiting; last state: %r" % state)
            time.sleep(0.02)

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                return self.proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
                raise
        return self.proc.returncode


def render(scene, out, *extra):
    subprocess.run([BINARY, "render", scene, "-o", out, *extra], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(out, "rb") as f:
        return f.read()


def decode_png(data):
    """(width, height, channels, rows of bytes) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunk)
            assert depth == 8 and colour in (2, 6) and interlace == 0, (depth, colour, interlace)
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += chunk
        elif kind == b"IEND":
            break
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, channels, rows


def rgb_pixels(data):
    """(width, height, flat list of R, G, B bytes) whatever the PNG's channel count."""
    width, height, channels, rows = decode_png(data)
    out = []
    for row in rows:
        for x in range(width):
            out.extend(row[x * channels:x * channels + 3])
    return width, height, out


def max_difference(a_png, b_png):
    """The largest per-channel difference of two PNGs of the same size, and the mean."""
    wa, ha, a = rgb_pixels(a_png)
    wb, hb, b = rgb_pixels(b_png)
    assert (wa, ha) == (wb, hb), ((wa, ha), (wb, hb))
    diffs = [abs(x - y) for x, y in zip(a, b)]
    return max(diffs), sum(diffs) / len(diffs)
