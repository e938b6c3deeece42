#!/usr/bin/env python3
"""Held-out POV-Ray corpus runner: renders every scene of scenes.json with POV-Ray 3.7 and with
raycast at 160x120 from the scene's own folder, reports raycast's ok / error (first message) /
crash / timeout, the most common first errors and warnings, and how close raycast's picture is
to POV-Ray's where both render.

    python3 bench/pov-heldout/compare.py --scenes DIR [--raycast PATH] [--out DIR] [--json FILE]

Closeness: both PNGs as 8-bit sRGB codes, averaged over 4x4 pixel blocks (so a pixel or an
edge that moves a little costs little), then the mean absolute difference over every block and
channel; 0 is the same picture, close is <= 6. POV-Ray's renders are kept in --out/povray and
reused (delete them to render again); raycast's go to --out/raycast.
"""
import argparse
import collections
import json
import os
import re
import subprocess
import sys

import numpy as np
from PIL import Image

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CLOSE = 6.0
BLOCK = 4
# A warning line: where it points (file:line:column, or the command), then its message.
WARNING = re.compile(r"^(.*?)warning: (.*)$", re.M)
# Warnings that point into POV-Ray's own include files come from declarations the scene may
# never use (colors.inc, textures.inc ...), so they are counted apart.
STANDARD_INCLUDES = "/usr/share/povray"


def block_means(path):
    """The picture's RGB codes averaged over BLOCKxBLOCK blocks (edges that do not fill a
    block are dropped)."""
    a = np.asarray(Image.open(path).convert("RGB"), dtype=np.float64)
    h, w = a.shape[0] // BLOCK * BLOCK, a.shape[1] // BLOCK * BLOCK
    a = a[:h, :w].reshape(h // BLOCK, BLOCK, w // BLOCK, BLOCK, 3)
    return a.mean(axis=(1, 3))


def closeness(png_a, png_b):
    """Mean absolute difference of 8-bit sRGB codes between two same-size PNGs after 4x4
    block averaging; None when the sizes differ."""
    a, b = block_means(png_a), block_means(png_b)
    if a.shape != b.shape:
        return None
    return float(np.abs(a - b).mean())


def is_flat(png):
    """Whether the picture is one colour (a scene file holding only objects, with no camera or
    light, renders black): such scenes test the reader but not the picture."""
    return float(np.asarray(Image.open(png).convert("RGB"), dtype=np.float64).std()) < 1.0


def povray_render(scene, png, timeout):
    """'ok', 'error' or 'timeout' for POV-Ray 3.7 writing png from the scene's folder."""
    if os.path.exists(png):
        return "ok"
    os.makedirs(os.path.dirname(png), exist_ok=True)
    cmd = ["povray", "+W160", "+H120", "-D", "+FN8", "-GA", "File_Gamma=sRGB", "+O" + png,
           "+I" + os.path.basename(scene)]
    try:
        p = subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, text=True,
                           timeout=timeout, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return "timeout"
    return "ok" if p.returncode == 0 and os.path.exists(png) else "error"


def raycast_render(raycast, scene, png, timeout):
    """(status, first error, warnings) for raycast writing png from the scene's folder."""
    os.makedirs(os.path.dirname(png), exist_ok=True)
    if os.path.exists(png):
        os.remove(png)
    cmd = [raycast, "render", os.path.basename(scene), "-o", png, "--width", "160",
           "--height", "120"]
    try:
        p = subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, text=True,
                           timeout=timeout, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return "timeout", "", []
    warnings = [[m.group(1), m.group(2)] for m in WARNING.finditer(p.stderr)]
    if p.returncode == 0:
        return "ok", "", warnings
    if p.returncode == 2:
        lines = [l for l in p.stderr.splitlines() if l.startswith("raycast")]
        return "error", (lines[0] if lines else p.stderr.strip()[:200]), warnings
    if p.returncode < 0:
        return "crash", "signal %d: %s" % (-p.returncode, p.stderr.strip()[-200:]), warnings
    return "crash", "exit code %d: %s" % (p.returncode, p.stderr.strip()[-200:]), warnings


def shorten(message):
    """The message without its file position, numbers and names, to count kinds."""
    m = re.sub(r"^raycast: [^ ]*:\d+:\d+: ", "", message)
    m = re.sub(r"^[^ ]*:\d+:\d+: ", "", m)
    m = re.sub(r"'[^']*'", "'...'", m)
    return re.sub(r"\d+(\.\d+)?", "N", m)[:110]


def run_scene(a, entry):
    """One scene's result record."""
    rel = os.path.join(entry["repo"].replace("/", "__"), entry["path"])
    scene = os.path.join(a.scenes, rel)
    png = rel[:-len(".pov")] + ".png"
    pov_png = os.path.join(a.out, "povray", png)
    ray_png = os.path.join(a.out, "raycast", png)
    r = {"scene": rel, "povray": "missing", "raycast": "", "error": "", "warnings": [],
         "difference": None, "flat": None}
    if not os.path.exists(scene):
        return r
    r["povray"] = povray_render(scene, pov_png, a.pov_timeout)
    if r["povray"] != "ok":
        return r
    r["flat"] = is_flat(pov_png)
    r["raycast"], r["error"], r["warnings"] = raycast_render(a.raycast, scene, ray_png, a.timeout)
    if r["raycast"] == "ok" and os.path.exists(ray_png):
        r["difference"] = closeness(pov_png, ray_png)
    return r


def report(results):
    """Prints the counts, the common first errors and warnings, crashes and hangs."""
    rendered = [r for r in results if r["povray"] == "ok"]
    status = collections.Counter(r["raycast"] for r in rendered)
    diffs = [r["difference"] for r in rendered if r["difference"] is not None]
    close = sum(1 for d in diffs if d <= CLOSE)
    pictures = [r["difference"] for r in rendered
                if r["difference"] is not None and not r["flat"]]
    print("scenes %d from %d repositories; POV-Ray renders %d (missing %d, error %d, timeout %d)"
          % (len(results), len({r["scene"].split(os.sep)[0] for r in results}), len(rendered),
             sum(r["povray"] == "missing" for r in results),
             sum(r["povray"] == "error" for r in results),
             sum(r["povray"] == "timeout" for r in results)))
    print("raycast: ok %d, error %d, crash %d, timeout %d; close (<= %g) %d of %d compared, "
          "median difference %.1f" % (status["ok"], status["error"], status["crash"],
                                       status["timeout"], CLOSE, close, len(diffs),
                                       float(np.median(diffs)) if diffs else float("nan")))
    print("  without the %d whose POV-Ray picture is one flat colour: close %d of %d, median %.1f"
          % (len(diffs) - len(pictures), sum(1 for d in pictures if d <= CLOSE), len(pictures),
             float(np.median(pictures)) if pictures else float("nan")))
    errors, examples = collections.Counter(), {}
    own, standard = collections.Counter(), collections.Counter()
    for r in rendered:
        if r["raycast"] == "error":
            kind = shorten(r["error"])
            errors[kind] += 1
            examples.setdefault(kind, r["scene"])
        for w in set(shorten(m) for f, m in r["warnings"] if not f.startswith(STANDARD_INCLUDES)):
            own[w] += 1
        for w in set(shorten(m) for f, m in r["warnings"] if f.startswith(STANDARD_INCLUDES)):
            standard[w] += 1
    print("\nmost common first errors (count, message, one scene):")
    for e, n in errors.most_common(15):
        print("  %4d  %s\n        %s" % (n, e, examples[e]))
    print("\nmost common warnings from the scenes' own files (scenes):")
    for w, n in own.most_common(15):
        print("  %4d  %s" % (n, w))
    print("\nmost common warnings from POV-Ray's include files (scenes):")
    for w, n in standard.most_common(8):
        print("  %4d  %s" % (n, w))
    print("\ncrashes and timeouts:")
    for r in rendered:
        if r["raycast"] in ("crash", "timeout"):
            print("  %s  %s  %s\n    (cd %s && raycast render %s -o out.png --width 160 --height 120)"
                  % (r["raycast"], r["scene"], r["error"], os.path.dirname(r["scene"]) or ".",
                     os.path.basename(r["scene"])))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", required=True, help="the folder fetch.py wrote")
    ap.add_argument("--manifest", default=os.path.join(HERE, "scenes.json"))
    ap.add_argument("--raycast", default=os.path.join(ROOT, "build/release/raycast"))
    ap.add_argument("--out", default=os.path.join(ROOT, "build/pov-heldout"))
    ap.add_argument("--timeout", type=float, default=30, help="seconds for raycast")
    ap.add_argument("--pov-timeout", type=float, default=60, help="seconds for POV-Ray")
    ap.add_argument("--json", help="write every scene's result to this file")
    a = ap.parse_args()
    a.scenes, a.out = os.path.abspath(a.scenes), os.path.abspath(a.out)
    with open(a.manifest) as f:
        manifest = json.load(f)["scenes"]
    results = []
    for entry in manifest:
        results.append(run_scene(a, entry))
        r = results[-1]
        print("%-8s %-8s %s" % (r["povray"], r["raycast"], r["scene"]), file=sys.stderr)
    report(results)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
