#!/usr/bin/env python3
"""Parse speed against POV-Ray: a scene that builds 100,000 spheres in a #while loop, and a mesh2
of 2,000,000 triangles. Writes both into --out (default build/pov-corpus), then reports POV-Ray's
own "Parse Time" (povray +W16 +H12 -D) beside raycast's: `raycast info SCENE`'s load time less
its BVH builds (reading, interpreting, building the engine's objects), and its whole wall time.

    python3 bench/pov-corpus/parse_speed.py [--raycast PATH] [--out DIR] [--runs N]
"""
import argparse
import os
import re
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def write_loop(path, n):
    with open(path, "w") as f:
        f.write("camera { location <50, 60, -150> look_at <50, 0, 50> }\n"
                "light_source { <0, 200, -100> color rgb 1 }\n"
                "#declare I = 0;\n#while (I < %d)\n"
                "  sphere { <mod(I, 316), 0, div(I, 316)>, 0.4 pigment { rgb <1, 0.5, 0.2> } }\n"
                "  #declare I = I + 1;\n#end\n" % n)


def write_mesh(path, side):
    """A (side + 1) x (side + 1) grid of vertices: 2 side^2 triangles."""
    with open(path, "w") as f:
        f.write("camera { location <0.5, 2, -1> look_at <0.5, 0, 0.5> }\n"
                "light_source { <0, 5, -5> color rgb 1 }\nmesh2 {\n vertex_vectors { %d\n" %
                ((side + 1) ** 2))
        for j in range(side + 1):
            f.write(",".join("<%g,%g,%g>" % (i / side, ((i * 7 + j * 3) % 11) / 1100.0, j / side)
                             for i in range(side + 1)))
            f.write(",\n" if j < side else "\n")
        f.write(" }\n face_indices { %d\n" % (2 * side * side))
        for j in range(side):
            row = []
            for i in range(side):
                a = j * (side + 1) + i
                row.append("<%d,%d,%d>,<%d,%d,%d>" % (a, a + 1, a + side + 1, a + 1, a + side + 2,
                                                       a + side + 1))
            f.write(",".join(row))
            f.write(",\n" if j < side - 1 else "\n")
        f.write(" }\n pigment { rgb 0.8 }\n}\n")


def povray_parse(scene):
    with tempfile.TemporaryDirectory() as tmp:
        p = subprocess.run(["povray", "+I" + scene, "+W16", "+H12", "-D", "+FN",
                            "+O" + os.path.join(tmp, "o.png")], capture_output=True, text=True)
    m = re.search(r"Parse Time:.*\(([0-9.]+) seconds\)", p.stdout + p.stderr)
    return float(m.group(1)) if m else float("nan")


def raycast_load(raycast, scene):
    """(wall seconds of `raycast info`, its load time less the BVH builds)."""
    t0 = time.monotonic()
    p = subprocess.run([raycast, "info", scene], capture_output=True, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        raise SystemExit(p.stderr)
    loaded = float(re.search(r"loaded in ([0-9.]+) ms", p.stdout).group(1))
    bvh = sum(float(m) for m in re.findall(r"built in ([0-9.]+) ms", p.stdout))
    return wall, (loaded - bvh) / 1000


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--raycast", default=os.path.join(ROOT, "build/release/raycast"))
    ap.add_argument("--out", default=os.path.join(ROOT, "build/pov-corpus"))
    ap.add_argument("--runs", type=int, default=1)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    loop = os.path.join(a.out, "loop100k.pov")
    mesh = os.path.join(a.out, "mesh2m.pov")
    if not os.path.exists(loop):
        write_loop(loop, 100000)
    if not os.path.exists(mesh):
        write_mesh(mesh, 1000)
    print("| scene | POV-Ray Parse Time (s) | raycast: load less BVH builds (s) | raycast info, wall (s) |")
    print("| --- | ---: | ---: | ---: |")
    for name, scene in (("100,000 spheres from #while", loop), ("mesh2, 2,000,000 triangles", mesh)):
        pov = min(povray_parse(scene) for _ in range(a.runs))
        ray = min(raycast_load(a.raycast, scene) for _ in range(a.runs))
        print("| %s | %.2f | %.2f | %.2f |" % (name, pov, ray[1], ray[0]))


if __name__ == "__main__":
    main()
