"""Latency of `raycast serve`'s preview (docs/serve.md "Latency"): time to the first image and to
the final image, at start and after an edit of the scene file, next to `raycast render` of the same
scene in the same run. Usage (from the repository root, after building the release preset):
    /usr/bin/python3 bench/serve_latency.py [SCENE] [--runs N]
SCENE defaults to scenes/demo.yaml; RAYCAST_BINARY overrides build/release/raycast."""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "serve"))
import serve_support  # noqa: E402

serve_support.BINARY = os.environ.get("RAYCAST_BINARY", "build/release/raycast")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scene", nargs="?", default="scenes/demo.yaml")
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    tmp = tempfile.mkdtemp(prefix="raycast_serve_latency_")
    scene = os.path.join(tmp, os.path.basename(args.scene))
    shutil.copy(args.scene, scene)
    with open(scene) as f:
        original = f.read()
    rows = {k: [] for k in ("start first", "start final", "edit first", "edit final", "render")}
    for _ in range(args.runs):
        with open(scene, "w") as f:
            f.write(original)
        t0 = time.monotonic()
        server = serve_support.Server(scene)
        try:
            state = server.wait(lambda s: s["frame"] >= 1, timeout=120)
            rows["start first"].append(time.monotonic() - t0)
            state = server.wait(lambda s: s["final"], timeout=600)
            rows["start final"].append(time.monotonic() - t0)
            # An edit: the file gains a comment line (same scene, full reload).
            frame = state["frame"]
            t0 = time.monotonic()
            with open(scene, "a") as f:
                f.write("# edited\n")
            server.wait(lambda s: s["reloads"] >= 2 and s["frame"] > frame, timeout=120)
            rows["edit first"].append(time.monotonic() - t0)
            server.wait(lambda s: s["reloads"] >= 2 and s["final"], timeout=600)
            rows["edit final"].append(time.monotonic() - t0)
        finally:
            server.stop()
        t0 = time.monotonic()
        subprocess.run([serve_support.BINARY, "render", scene, "-o", os.path.join(tmp, "r.png")],
                       check=True, stderr=subprocess.DEVNULL)
        rows["render"].append(time.monotonic() - t0)
    print("scene %s, %d runs, wall seconds (median, min, max); the machine may be loaded:"
          % (args.scene, args.runs))
    for name, values in rows.items():
        print("  %-12s %7.3f %7.3f %7.3f" % (name, statistics.median(values), min(values),
                                              max(values)))
    render = statistics.median(rows["render"])
    print("  final / render: start %.2f, edit %.2f" % (
        statistics.median(rows["start final"]) / render,
        statistics.median(rows["edit final"]) / render))
    shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
