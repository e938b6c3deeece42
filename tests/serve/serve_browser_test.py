"""Browser test of `raycast serve` (docs/serve.md): headless Chromium loads the page, which draws
each pass on its canvas; once the final pass is drawn the page (in its ?test=1 mode) closes its
event stream and puts the canvas, read back as a PNG data URL, into the DOM, which
`chromium --dump-dom` prints. The canvas must equal `raycast render` of the same scene: every
channel within 1 of 255 (colour management or canvas round trips could move a code by one; we
expect and report 0). The page also checks its camera gestures' geometry (orbit, pan, zoom) in
the browser and reports "ok" in the DOM. Skipped (exit 77) when Chromium is not installed."""
import base64
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from serve_support import Server, max_difference, render  # noqa: E402

SCENE = """\
camera: {type: perspective, position: [0, 1.8, -7], look_at: [0, 0.4, 0], up: [0, 1, 0], fov: 40}
image: {width: 160, height: 120, samples: 4}
render: {integrator: whitted, max_depth: 8, background: [0.45, 0.65, 1.0], seed: 1}
materials:
  floor:  {texture: {checker: {colors: [[0.95, 0.8, 0.15], [0.75, 0.08, 0.06]], scale: 1.0}}}
  mirror: {color: [0.9, 0.9, 0.9], diffuse: 0.15, specular: 0.6, shininess: 120, reflection: 0.8}
  glass:  {color: [0.95, 0.97, 1.0], diffuse: 0, specular: 0.8, transmission: 0.95, ior: 1.5}
lights:
  - {type: point, position: [-4, 8, -6], color: [1, 1, 1], intensity: 1.0}
objects:
  - plane: {normal: [0, 1, 0], point: [0, -0.5, 0]}
    material: floor
  - sphere: {center: [1.1, 0.6, 1.2], radius: 1.1}
    material: mirror
  - sphere: {center: [-0.9, 0.35, -1.0], radius: 0.85}
    material: glass
"""

TOLERANCE = 1  # 8-bit codes per channel


def main():
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("serve_browser: chromium not installed, skipped")
        sys.exit(77)
    tmp = tempfile.mkdtemp(prefix="raycast_serve_browser_")
    scene = os.path.join(tmp, "scene.yaml")
    with open(scene, "w") as f:
        f.write(SCENE)
    reference = render(scene, os.path.join(tmp, "ref.png"))
    server = Server(scene)
    try:
        start = time.monotonic()
        result = subprocess.run(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
             "--no-first-run", "--disable-background-networking", "--disable-component-update",
             "--disable-sync", "--user-data-dir=" + os.path.join(tmp, "profile"),
             "--virtual-time-budget=15000", "--dump-dom", server.url + "?test=1"],
            capture_output=True, text=True, timeout=60)
        seconds = time.monotonic() - start
        match = re.search(r'<pre id="final-image" data-frame="(\d+)">data:image/png;base64,'
                          r'([A-Za-z0-9+/=]+)</pre>', result.stdout)
        assert match, "no final image in the page's DOM:\n" + result.stdout[-2000:] + \
            result.stderr[-2000:]
        self_test = re.search(r'<pre id="self-test">([^<]*)</pre>', result.stdout)
        assert self_test and self_test.group(1) == "ok", self_test and self_test.group(1)
        # The explain panel on the centre pixel: a collapsible tree with the colour of
        # `raycast explain --json`, and its rays drawn over the picture.
        panel = re.search(r'<pre id="explain-test"[^>]*>([^<]*)</pre>', result.stdout)
        assert panel and panel.group(1).startswith("{"), panel and panel.group(1)
        panel = json.loads(panel.group(1))
        cli = json.loads(subprocess.run(
            [os.environ["RAYCAST_BINARY"], "explain", scene, "--pixel", "80", "60", "--spp", "1",
             "--json"], capture_output=True, text=True, check=True).stdout)
        assert panel["color"] == cli["color"], (panel, cli["color"])
        assert panel["details"] >= 2 and panel["segments"] >= 1, panel
        state = server.get_json("/state")
        assert state["final"] and int(match.group(1)) == state["frame"], (match.group(1), state)
        canvas = base64.b64decode(match.group(2))
        worst, mean = max_difference(canvas, reference)
        print("serve_browser: canvas vs raycast render: max difference %d, mean %.4f (codes); "
              "chromium %.1f s" % (worst, mean, seconds))
        assert worst <= TOLERANCE, (worst, mean)
        assert server.stop() == 0
    finally:
        if server.proc.poll() is None:
            server.proc.kill()
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
