"""HTTP-level tests of `raycast serve` (docs/serve.md): the page, progressive images equal to
`raycast render`, reloads on edits of the scene and of a file it names, errors with their position
while the last image stays, the page's requests, and hostile requests that must get a 4xx while the
server stays up. Run by ctest (serve_http); stdlib only."""
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from serve_support import Server, max_difference, render  # noqa: E402

SCENE = """\
camera: {type: perspective, position: [0, 0, -5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 40}
image: {width: 80, height: 60, samples: 4}
render: {integrator: whitted, background: [0.2, 0.3, 0.4], seed: 1}
materials:
  red: {color: [0.9, 0.1, 0.1]}
lights:
  - {type: point, position: [-3, 4, -5], color: [1, 1, 1], intensity: 1.0}
objects:
  - sphere: {center: [0, 0, 0], radius: 1}
    material: red
  - mesh: {file: tri.ply}
"""


def write_ply(path, dx):
    """One triangle, binary little-endian PLY, shifted by dx along x."""
    header = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
              b"property float x\nproperty float y\nproperty float z\n"
              b"element face 1\nproperty list uchar int vertex_indices\nend_header\n")
    body = struct.pack("<9f", 1.3 + dx, -1, 0, 2.3 + dx, -1, 0, 1.8 + dx, 1, 0)
    body += struct.pack("<B3i", 3, 0, 1, 2)
    with open(path + ".tmp", "wb") as f:
        f.write(header + body)
    os.replace(path + ".tmp", path)


def write(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def final_after(server, previous_frame, reloads=None):
    return server.wait(lambda s: s["final"] and s["frame"] > previous_frame and not s["error"]
                       and (reloads is None or s["reloads"] >= reloads))


def settled(server, quiet=1.0):
    """The state once the render loop is idle: final, with the same frame and reload count over
    `quiet` seconds (ten of the file watcher's 100 ms polls, so a reload of a file written just
    before has started and finished)."""
    state = server.wait(lambda s: s["final"])
    while True:
        time.sleep(quiet)
        again = server.wait(lambda s: s["final"])
        if (again["frame"], again["reloads"]) == (state["frame"], state["reloads"]):
            return again
        state = again


def image(server):
    status, headers, data = server.request("GET", "/image.png")
    assert status == 200 and headers["Content-Type"] == "image/png", (status, headers)
    return int(headers["X-Raycast-Frame"]), data


def check_camera_saves(tmp):
    """Save camera on other layouts: a block-style camera (with comments around it), no camera at
    all, and a JSON scene (which gets a sidecar file instead)."""
    camera = {"position": [0.5, 1, -4], "look_at": [0, 0.25, 0], "up": [0, 1, 0], "fov": 30}
    line = ("camera: {type: perspective, position: [0.5,1,-4], look_at: [0,0.25,0], up: [0,1,0], "
            "fov: 30}")
    rest = SCENE.split("\n", 1)[1]
    block = ("# a comment before\ncamera:\n  type: perspective\n  position: [0, 0, -5]  # eye\n"
             "  look_at: [0, 0, 0]\n\n# about the image\n")
    cases = [
        ("block.yaml", block + rest, "# a comment before\n" + line + "\n\n# about the image\n" + rest),
        ("none.yaml", rest, rest + line + "\n"),
    ]
    for name, text, expected in cases:
        path = os.path.join(tmp, name)
        write(path, text)
        server = Server(path)
        try:
            final_after(server, 0)
            assert server.post("/camera", camera)[0] == 200
            status, saved = server.post("/camera/save")
            assert status == 200 and not saved["sidecar"], saved
            with open(path) as f:
                assert f.read() == expected, name
            assert server.stop() == 0
        finally:
            if server.proc.poll() is None:
                server.proc.kill()
    path = os.path.join(tmp, "scene.json")
    write(path, '{"objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}}],\n'
                ' "image": {"width": 32, "height": 24}}\n')
    server = Server(path)
    try:
        final_after(server, 0)
        assert server.post("/camera", camera)[0] == 200
        status, saved = server.post("/camera/save")
        assert status == 200 and saved["sidecar"] and saved["written"] == path + ".camera.yaml"
        with open(path + ".camera.yaml") as f:
            assert f.read().splitlines()[1] == line
        assert server.stop() == 0
    finally:
        if server.proc.poll() is None:
            server.proc.kill()


def check_broken_at_start(tmp):
    """A scene that does not load at start: the server runs, shows the error, has no image, stays
    idle through view changes, and renders once the file is fixed."""
    path = os.path.join(tmp, "late.yaml")
    write(path, SCENE.replace("radius: 1}", "radius: -1}"))
    server = Server(path)
    try:
        state = server.wait(lambda s: s["error"] != "")
        assert re.search(r"late\.yaml:9:\d+: sphere\.radius must be > 0", state["error"]), state
        assert server.request("GET", "/image.png")[0] == 503
        assert server.post("/camera/reset")[0] == 200
        assert server.post("/pick", {"x": 1, "y": 1})[0] == 409
        time.sleep(0.3)
        write(path, SCENE)
        final_after(server, 0)
        assert server.stop() == 0
    finally:
        if server.proc.poll() is None:
            server.proc.kill()


def main():
    tmp = tempfile.mkdtemp(prefix="raycast_serve_http_")
    scene = os.path.join(tmp, "scene.yaml")
    write(scene, SCENE)
    write_ply(os.path.join(tmp, "tri.ply"), 0)
    server = Server(scene)
    try:
        assert server.host == "127.0.0.1", server.url  # loopback by default
        # The page: one self-contained document.
        status, headers, page = server.request("GET", "/")
        assert status == 200 and headers["Content-Type"].startswith("text/html"), status
        assert b"<canvas" in page and b"EventSource" in page and b"http://" not in page.split(b"<script>")[1]

        # Progressive passes end with exactly what `raycast render` writes.
        state = final_after(server, 0)
        assert state["passes"] == 3 and state["width"] == 80 and state["first_ms"] > 0, state
        frame, png = image(server)
        assert frame == state["frame"]
        assert max_difference(png, render(scene, os.path.join(tmp, "ref.png")))[0] == 0

        # Editing the scene reloads it and restarts the refinement.
        write(scene, SCENE.replace("[0.2, 0.3, 0.4]", "[0.8, 0.3, 0.1]"))
        state = final_after(server, state["frame"], reloads=2)
        _, png2 = image(server)
        assert png2 != png
        assert max_difference(png2, render(scene, os.path.join(tmp, "ref2.png")))[0] == 0

        # So does editing a file the scene names (the mesh).
        write_ply(os.path.join(tmp, "tri.ply"), -0.6)
        state = final_after(server, state["frame"], reloads=3)
        _, png3 = image(server)
        assert max_difference(png3, render(scene, os.path.join(tmp, "ref3.png")))[0] == 0
        assert png3 != png2

        # A broken scene: its error with file:line:column, and the last image stays.
        broken = SCENE.replace("radius: 1}", "radus: 1}").replace("[0.2, 0.3, 0.4]", "[0.8, 0.3, 0.1]")
        write(scene, broken)
        state = server.wait(lambda s: s["error"] != "")
        match = re.search(r"scene\.yaml:(\d+):(\d+): .*radus", state["error"])
        assert match and int(match.group(1)) == 9, state["error"]
        assert image(server)[1] == png3
        write(scene, SCENE)
        state = final_after(server, state["frame"], reloads=4)

        # Pick: the centre pixel's ray meets the sphere head-on at t = 5 - 1.
        status, pick = server.post("/pick", {"x": 40, "y": 30})
        assert status == 200 and pick["hit"], pick
        assert abs(pick["t"] - 4) < 1e-9 and pick["material"] == "red", pick
        assert pick["object"]["shape"] == "sphere" and pick["object"]["line"] == 9, pick
        assert max(abs(a - b) for a, b in zip(pick["normal"], [0, 0, -1])) < 1e-9, pick
        status, pick = server.post("/pick", {"x": 1, "y": 1})
        assert status == 200 and not pick["hit"], pick

        # Explain: the centre pixel's ray tree, its root colour `raycast explain --json`'s.
        status, tree = server.post("/explain", {"x": 40, "y": 30})
        assert status == 200 and tree["pixel"] == [40, 30], tree
        assert tree["ray"]["kind"] == "camera" and tree["ray"]["hit"]["shape"] == "sphere", tree
        cli = json.loads(subprocess.run(
            [os.environ["RAYCAST_BINARY"], "explain", scene, "--pixel", "40", "30", "--spp", "1",
             "--json"], capture_output=True, text=True, check=True).stdout)
        assert tree["color"] == cli["color"], (tree["color"], cli["color"])

        # The integrator switch gives `raycast render --integrator normal`.
        status, reply = server.post("/integrator", {"integrator": "normal"})
        assert status == 200 and reply["integrator"] == "normal", reply
        state = final_after(server, state["frame"])
        assert max_difference(image(server)[1], render(scene, os.path.join(tmp, "n.png"),
                                                       "--integrator", "normal"))[0] == 0
        assert server.post("/integrator", {"integrator": "whitted"})[0] == 200

        # Moving the camera re-renders from there; saving writes only the camera line.
        camera = {"position": [1.5, 2, -4.5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 35}
        status, reply = server.post("/camera", camera)
        assert status == 200 and reply["camera_overridden"], reply
        state = final_after(server, state["frame"])
        moved = image(server)[1]
        status, saved = server.post("/camera/save")
        assert status == 200 and not saved["sidecar"] and saved["written"] == scene, saved
        with open(scene) as f:
            text = f.read()
        expected = SCENE.replace(SCENE.splitlines()[0], "camera: {type: perspective, position: "
                                 "[1.5,2,-4.5], look_at: [0,0,0], up: [0,1,0], fov: 35}")
        assert text == expected, text
        assert max_difference(moved, render(scene, os.path.join(tmp, "moved.png")))[0] == 0

        # Hostile and malformed requests: 4xx, nothing served from disk, server still up.
        for path in ["/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/scene.yaml",
                     "/" + scene, "/image.png/../scene.yaml", "/events/../../etc/passwd",
                     "//etc/passwd", "/index.html"]:
            status, _, body = server.request("GET", path)
            assert status == 404 and b"root:" not in body, (path, status)
        bad = [
            ("/camera", b'{"position": [1, 2', 400),                      # bad JSON
            ("/camera", b'[1, 2, 3]', 400),                                # not an object
            ("/camera", b'{"position": [NaN, 0, 0]}', 400),                # NaN
            ("/camera", b'{"position": [.nan, 0, 0]}', 400),
            ("/camera", b'{"fov": 1e999}', 400),                           # overflow
            ("/camera", b'{"fov": 180}', 400),
            ("/camera", b'{"position": [0, 0, 0], "look_at": [0, 0, 0]}', 400),
            ("/camera", b'{"up": [0, 0, 1], "position": [0, 0, -5], "look_at": [0, 0, 0]}', 400),
            ("/camera", b'{"position": [1e300, 0, 0]}', 400),
            ("/camera", b'{"positon": [0, 0, -5]}', 400),                  # unknown key
            ("/camera", b'{"a": ' + b'[' * 5000 + b']' * 5000 + b'}', 413),  # too deep and big
            ("/camera", b'{"a": [[[[1]]]]}', 400),                         # too deep
            ("/camera", b'{"x": "' + b'a' * 1_000_000 + b'"}', 413),      # huge body
            ("/pick", b'{"x": -1, "y": 0}', 400),
            ("/pick", b'{"x": 80, "y": 0}', 400),
            ("/pick", b'{"x": "a", "y": 0}', 400),
            ("/explain", b'{"x": 80, "y": 0}', 400),
            ("/explain", b'{"x": 1}', 400),
            ("/integrator", b'{"integrator": "path"}', 400),
            ("/integrator", b'{}', 400),
        ]
        for path, body, expected_status in bad:
            status, _, reply = server.request("POST", path, body,
                                              {"Content-Type": "application/json"})
            assert status == expected_status, (path, body[:60], status, reply[:200])
        status, _, _ = server.request("POST", "/camera", b"{}", {"Content-Type": "text/plain"})
        assert status == 415, status
        status, _, _ = server.request("POST", "/camera/reset", b"{}", {
            "Content-Type": "application/json", "Origin": "http://evil.example"})
        assert status == 403, status
        status, _, _ = server.request("GET", "/state", headers={"Host": "evil.example:80"})
        assert status == 403, status
        status, _, _ = server.request("GET", "/image.png",
                                      headers={"Range": "bytes=" + ",".join(["0-"] * 1000)})
        assert status == 416, status
        status, _, _ = server.request("PUT", "/camera", b"{}", {"Content-Type": "application/json"})
        assert 400 <= status < 500, status
        assert server.get_json("/state")["camera"]["fov"] == 35  # nothing bad was applied

        # Open pages share one render loop: 16 event streams at most, more get 503, and opening
        # them starts no rendering. The camera save above rewrote the scene file: its reload and
        # render finish first (an asynchronous frame would otherwise land in the window).
        frame_before = settled(server)["frame"]
        import http.client
        streams = []
        for _ in range(16):
            conn = http.client.HTTPConnection(server.host, server.port, timeout=10)
            conn.request("GET", "/events")
            response = conn.getresponse()
            assert response.status == 200
            assert response.readline().startswith(b"event: state")
            streams.append((conn, response))
        status, _, _ = server.request("GET", "/events")
        assert status == 503, status
        assert server.get_json("/state")["frame"] == frame_before
        for conn, _ in streams:
            conn.close()

        assert server.get_json("/state")["error"] == ""
        code = server.stop()
        assert code == 0, (code, server.proc.stderr.read())
    finally:
        if server.proc.poll() is None:
            server.proc.kill()
    check_camera_saves(tmp)
    check_broken_at_start(tmp)
    shutil.rmtree(tmp, ignore_errors=True)
    print("serve_http: all checks passed")


if __name__ == "__main__":
    main()
