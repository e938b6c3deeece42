#!/usr/bin/python3
"""Render speed on scenes other people wrote: POV-Ray 3.7 and raycast on the example scenes of
Debian's povray-examples whose raycast picture is close to POV-Ray's (a `run.py --compare --json`
result names them), each scene rendered by both programs in the same run, one after the other.

    /usr/bin/python3 bench/pov-corpus/speed.py --close RESULT.json [--width 320 --height 240]
        [--repeat 3] [--raycast build/release/raycast] [--json OUT.json]

Both render at the same size, one thread, no antialiasing, from the scene's own folder. POV-Ray's
time is its "Trace Time" (the render without parsing and bounding); raycast's is the pixel loop's
time of its summary line (also without loading and the BVH build). Each is the least of --repeat
runs, alternating the two programs so that both see the same machine. A scene's ratio is
POV-Ray's time over raycast's (above 1: raycast is faster). Reported per folder and over all
scenes: the median, the worst 10% (the 10th percentile) and the worst, then the slowest scenes.
"""
import argparse
import collections
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = "/usr/share/doc/povray/examples"
CLOSE = 6.0
POV_TRACE = re.compile(r"Trace Time:.*\(([0-9.]+) seconds\)")
RAYCAST_TIME = re.compile(r": ([0-9.]+) s \(cpu ")


def povray_seconds(scene, width, height, timeout):
    """POV-Ray's Trace Time for the scene, or None when it fails."""
    with tempfile.TemporaryDirectory() as tmp:
        cmd = ["povray", "+I" + os.path.basename(scene), "+W%d" % width, "+H%d" % height, "-D",
               "-A", "+WT1", "+FN", "+O" + os.path.join(tmp, "out.png")]
        try:
            p = subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, text=True,
                               timeout=timeout, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return None
        m = POV_TRACE.search(p.stderr + p.stdout)
        return float(m.group(1)) if p.returncode == 0 and m else None


def raycast_seconds(raycast, scene, width, height, timeout):
    """raycast's pixel-loop time for the scene, or None when it fails."""
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [raycast, "render", os.path.basename(scene), "-o", os.path.join(tmp, "out.png"),
               "--width", str(width), "--height", str(height), "--threads", "1"]
        try:
            p = subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, text=True,
                               timeout=timeout, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return None
        m = RAYCAST_TIME.search(p.stderr)
        return float(m.group(1)) if p.returncode == 0 and m else None


def least(values):
    values = [v for v in values if v is not None]
    return min(values) if values else None


def distribution(ratios):
    """(median, worst 10%, worst) of a list of ratios."""
    r = sorted(ratios)
    return statistics.median(r), r[int(0.1 * (len(r) - 1))], r[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--close", required=True, help="run.py --compare --json output")
    ap.add_argument("--examples", default=EXAMPLES)
    ap.add_argument("--raycast", default=os.path.join(ROOT, "build/release/raycast"))
    ap.add_argument("--width", type=int, default=320)
    ap.add_argument("--height", type=int, default=240)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--json", help="write every scene's times to this file")
    a = ap.parse_args()
    with open(a.close) as f:
        compared = json.load(f)
    names = sorted(s for s, (status, _, diff) in compared.items()
                   if status == "ok" and diff is not None and diff <= CLOSE)
    times = {}
    for i, s in enumerate(names):
        pov, ours = [], []
        for _ in range(a.repeat):
            pov.append(povray_seconds(s, a.width, a.height, a.timeout))
            ours.append(raycast_seconds(a.raycast, s, a.width, a.height, a.timeout))
        times[s] = (least(pov), least(ours))
        print("%3d/%d %s: POV-Ray %s s, raycast %s s" % (i + 1, len(names),
              os.path.relpath(s, a.examples), times[s][0], times[s][1]), file=sys.stderr)
    by_folder = collections.defaultdict(list)
    ratios = {}
    for s, (pov, ours) in times.items():
        # Scenes POV-Ray traces in under 10 ms are timer noise (its times have 1 ms steps).
        if pov is None or ours is None or pov < 0.01:
            continue
        ratios[s] = pov / max(ours, 1e-4)
        by_folder[os.path.relpath(s, a.examples).split(os.sep)[0]].append(ratios[s])
    print("| folder | scenes | median | worst 10% | worst |")
    print("| --- | ---: | ---: | ---: | ---: |")
    for folder in sorted(by_folder):
        print("| %s | %d | %.2fx | %.2fx | %.2fx |" % ((folder, len(by_folder[folder])) +
                                                    distribution(by_folder[folder])))
    if ratios:
        print("| **all** | %d | %.2fx | %.2fx | %.2fx |" % ((len(ratios),) +
                                                          distribution(list(ratios.values()))))
    print("\nslowest against POV-Ray (POV-Ray's time / raycast's):")
    for s in sorted(ratios, key=ratios.get)[:10]:
        print("  %.2fx  %s (POV-Ray %.3f s, raycast %.3f s)" % (ratios[s],
              os.path.relpath(s, a.examples), times[s][0], times[s][1]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(times, f, indent=1)


if __name__ == "__main__":
    main()
