#!/usr/bin/env python3
"""POV-Ray corpus runner: renders every example scene of Debian's povray-examples that POV-Ray
3.7 itself renders, with raycast, at 160x120 from the scene's own folder, and reports ok / error
(first message) / crash / timeout by folder, the most common first errors and warnings, and the
parse times of both programs.

    python3 bench/pov-corpus/run.py [--examples DIR] [--raycast PATH] [--cache DIR] [--jobs N]
    python3 bench/pov-corpus/run.py --compare [...]

The list of scenes POV-Ray renders is made once with povray (160x120, -D) and cached in
--cache (default build/pov-corpus): delete it to make it again.

--compare also measures how close raycast's pictures are to POV-Ray's: each scene is rendered by
POV-Ray 3.7 (160x120, no antialiasing, 8-bit sRGB PNG) once and cached in --cache/povray-images
(a scene POV-Ray fails on is cached as NAME.failed), and by raycast at 160x120 into
--cache/raycast-images; `raycast compare` gives the mean absolute difference of their 4x4 block
means in 8-bit codes. Per folder it reports the scenes POV-Ray rendered, those raycast rendered and
those close (block mean <= CLOSE), then the first warning of each rendered scene that is not close.
"""
import argparse
import collections
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def scenes(examples):
    out = []
    for d, _, files in os.walk(examples):
        for f in files:
            if f.endswith(".pov"):
                out.append(os.path.join(d, f))
    return sorted(out)


PARSE_TIME = re.compile(r"Parse Time:.*\(([0-9.]+) seconds\)")


def povray_run(scene, timeout):
    """(ok, parse seconds) for POV-Ray 3.7 rendering the scene at 160x120 from its folder."""
    with tempfile.TemporaryDirectory() as tmp:
        cmd = ["povray", "+I" + os.path.basename(scene), "+W160", "+H120", "-D", "+FN", "+O" + os.path.join(tmp, "out.png")]
        try:
            p = subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, text=True,
                               timeout=timeout, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return False, None
        m = PARSE_TIME.search(p.stderr + p.stdout)
        return p.returncode == 0, float(m.group(1)) if m else None


def povray_list(examples, cache, jobs, timeout):
    path = os.path.join(cache, "povray-renders.json")
    if os.path.exists(path):
        with open(path) as f:
            return json.load(f)
    all_scenes = scenes(examples)
    result = {}
    with concurrent.futures.ThreadPoolExecutor(jobs) as ex:
        for s, (ok, t) in zip(all_scenes, ex.map(lambda s: povray_run(s, timeout), all_scenes)):
            if ok:
                result[s] = t
    os.makedirs(cache, exist_ok=True)
    with open(path, "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
    return result


POVRAY_IMAGE_OPTIONS = ["+W160", "+H120", "+FN8", "-GA", "File_Gamma=sRGB", "-D"]
CLOSE = 6.0  # the block-4 mean absolute difference, in 8-bit codes, of a close picture


def povray_image(scene, examples, cache, timeout):
    """POV-Ray's picture of the scene (cached), or None when POV-Ray does not render it."""
    base = os.path.join(os.path.abspath(cache), "povray-images", os.path.relpath(scene, examples))[:-4]
    if os.path.exists(base + ".png"):
        return base + ".png"
    if os.path.exists(base + ".failed"):
        return None
    os.makedirs(os.path.dirname(base), exist_ok=True)
    cmd = ["povray", "+I" + os.path.basename(scene), "+O" + base + ".tmp.png"] + POVRAY_IMAGE_OPTIONS
    try:
        p = subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, text=True,
                           timeout=timeout, stdin=subprocess.DEVNULL)
        ok = p.returncode == 0 and os.path.exists(base + ".tmp.png")
        why = "exit code %d" % p.returncode
    except subprocess.TimeoutExpired:
        ok, why = False, "timeout"
    if ok:
        os.replace(base + ".tmp.png", base + ".png")
        return base + ".png"
    with open(base + ".failed", "w") as f:
        f.write(why + "\n")
    return None


def raycast_image(raycast, scene, examples, cache, timeout, reference, comparer):
    """(status, first warning, block mean or None) of raycast's picture against POV-Ray's."""
    out = os.path.join(os.path.abspath(cache), "raycast-images", os.path.relpath(scene, examples))[:-4] + ".png"
    os.makedirs(os.path.dirname(out), exist_ok=True)
    try:
        p = subprocess.run([raycast, "render", os.path.basename(scene), "-o", out, "--width",
                            "160", "--height", "120"], cwd=os.path.dirname(scene),
                           capture_output=True, text=True, timeout=timeout,
                           stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return "timeout", "", None
    warnings = [m.group(1) for m in WARNING.finditer(p.stderr)]
    first = shorten(warnings[0]) if warnings else "(no warning)"
    if p.returncode != 0:
        return ("error" if p.returncode == 2 else "crash"), first, None
    c = subprocess.run([comparer or raycast, "compare", reference, out, "--json"], capture_output=True,
                       text=True, timeout=timeout)
    if c.returncode != 0:
        return "error", "compare: " + c.stderr.strip()[:100], None
    return "ok", first, json.loads(c.stdout)["block_mean"]


def compare_corpus(a):
    """The --compare mode: POV-Ray's and raycast's pictures, folder by folder."""
    all_scenes = scenes(a.examples)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as ex:
        refs = dict(zip(all_scenes, ex.map(
            lambda s: povray_image(s, a.examples, a.cache, a.pov_timeout), all_scenes)))
    names = [s for s in all_scenes if refs[s]]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as ex:
        results = dict(zip(names, ex.map(lambda s: raycast_image(
            a.raycast, s, a.examples, a.cache, a.timeout, refs[s], a.comparer), names)))
    by_folder = collections.defaultdict(collections.Counter)
    first_warnings = collections.Counter()
    for s, (status, first, diff) in results.items():
        folder = os.path.relpath(os.path.dirname(s), a.examples).split(os.sep)[0]
        c = by_folder[folder]
        c["scenes"] += 1
        c["rendered"] += status == "ok"
        c["close"] += diff is not None and diff <= CLOSE
        if status == "ok" and diff > CLOSE:
            first_warnings[first] += 1
    total = collections.Counter()
    print("| folder | POV-Ray rendered | raycast rendered | close (block-4 mean <= %g) |" % CLOSE)
    print("| --- | ---: | ---: | ---: |")
    for folder in sorted(by_folder):
        c = by_folder[folder]
        total.update(c)
        print("| %s | %d | %d | %d |" % (folder, c["scenes"], c["rendered"], c["close"]))
    print("| **all** | %d | %d | %d |" % (total["scenes"], total["rendered"], total["close"]))
    print("\nfirst warning of the rendered scenes that are not close:")
    for w, n in first_warnings.most_common(25):
        print("  %4d  %s" % (n, w))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)


WARNING = re.compile(r"warning: (.*)")
LOADED = re.compile(r"loaded in ([0-9.]+) ms")
BUILT = re.compile(r"top-level BVH, \d+ bytes, built in ([0-9.]+) ms")


def raycast_run(raycast, scene, timeout):
    """(status, first error, warnings, parse seconds) for raycast on the scene."""
    with tempfile.TemporaryDirectory() as tmp:
        cwd = os.path.dirname(scene)
        try:
            info = subprocess.run([raycast, "info", os.path.basename(scene)], cwd=cwd,
                                  capture_output=True, text=True, timeout=timeout,
                                  stdin=subprocess.DEVNULL)
            m = LOADED.search(info.stdout)
            b = BUILT.search(info.stdout)
            # The scene's reading and object building, without the BVH (POV-Ray's Parse Time
            # does not count its bounding either).
            parse = (float(m.group(1)) - float(b.group(1))) / 1000 if m and b else None
            p = subprocess.run([raycast, "render", os.path.basename(scene), "-o",
                                os.path.join(tmp, "out.png"), "--width", "160", "--height", "120"],
                               cwd=cwd, capture_output=True, text=True, timeout=timeout,
                               stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return "timeout", "", [], None
        warnings = [m.group(1) for m in WARNING.finditer(p.stderr)]
        if p.returncode == 0:
            return "ok", "", warnings, parse if info.returncode == 0 else None
        if p.returncode == 2:
            lines = [l for l in p.stderr.splitlines() if l.startswith("raycast")]
            return "error", (lines[0] if lines else p.stderr.strip()[:200]), warnings, None
        return "crash", "exit code %d: %s" % (p.returncode, p.stderr.strip()[-200:]), warnings, None


def shorten(message):
    """The error without its file position, numbers and names, to count kinds."""
    m = re.sub(r"^raycast: [^ ]*:\d+:\d+: ", "", message)
    m = re.sub(r"'[^']*'", "'...'", m)
    return re.sub(r"\d+(\.\d+)?", "N", m)[:110]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--examples", default="/usr/share/doc/povray/examples")
    ap.add_argument("--raycast", default=os.path.join(ROOT, "build/release/raycast"))
    ap.add_argument("--cache", default=os.path.join(ROOT, "build/pov-corpus"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--pov-timeout", type=float, default=300,
                    help="seconds for one POV-Ray picture (--compare)")
    ap.add_argument("--compare", action="store_true",
                    help="compare raycast's pictures with POV-Ray's (cached) ones")
    ap.add_argument("--comparer", help="the raycast that runs `raycast compare` (--compare; "
                    "default: --raycast), to measure a build without the command")
    ap.add_argument("--json", help="write every scene's result to this file")
    a = ap.parse_args()
    if not os.path.isdir(a.examples):
        sys.exit("no examples at %s (Debian's povray-examples)" % a.examples)
    if a.compare:
        compare_corpus(a)
        return
    pov = povray_list(a.examples, a.cache, a.jobs, a.timeout)
    names = sorted(pov)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as ex:
        results = dict(zip(names, ex.map(lambda s: raycast_run(a.raycast, s, a.timeout), names)))
    by_folder = collections.defaultdict(collections.Counter)
    errors, warnings = collections.Counter(), collections.Counter()
    ray_parse = pov_parse = 0.0
    for s, (status, err, warns, parse) in results.items():
        folder = os.path.relpath(os.path.dirname(s), a.examples).split(os.sep)[0]
        by_folder[folder][status] += 1
        if err:
            errors[shorten(err)] += 1
        for w in set(shorten(x) for x in warns):
            warnings[w] += 1
        if parse is not None and pov[s] is not None:
            ray_parse += parse
            pov_parse += pov[s]
    total = collections.Counter()
    print("| folder | scenes | ok | error | crash | timeout |")
    print("| --- | ---: | ---: | ---: | ---: | ---: |")
    for folder in sorted(by_folder):
        c = by_folder[folder]
        total.update(c)
        print("| %s | %d | %d | %d | %d | %d |" % (folder, sum(c.values()), c["ok"], c["error"],
                                                  c["crash"], c["timeout"]))
    print("| **all** | %d | %d | %d | %d | %d |" % (sum(total.values()), total["ok"],
                                                    total["error"], total["crash"], total["timeout"]))
    print("\nrendered %d of %d (%.1f%%)" % (total["ok"], len(names), 100.0 * total["ok"] / max(1, len(names))))
    print("parse time over the rendered scenes: raycast %.2f s (`raycast info`'s load time less "
          "its BVH build), POV-Ray %.2f s (its Parse Time)" % (ray_parse, pov_parse))
    print("\nmost common first errors:")
    for e, n in errors.most_common(15):
        print("  %4d  %s" % (n, e))
    print("\nmost common warnings (scenes):")
    for w, n in warnings.most_common(15):
        print("  %4d  %s" % (n, w))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
