"""Shared helpers of the raycast Python tests (docs/python.md): the module from the build tree,
the CLI binary for cross-checks and small scenes."""
import os
import subprocess

import numpy as np
import pytest

import raycast

SOURCE_DIR = os.environ.get(
    "RAYCAST_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(__file__))))
BINARY = os.environ.get("RAYCAST_BINARY", os.path.join(SOURCE_DIR, "build", "release", "raycast"))


def cli_cast(scene_path, rays, mode=None):
    """Runs `raycast cast` on float64 rays (n, 6) and returns its answer lines split in floats."""
    args = [BINARY, "cast", scene_path]
    if mode:
        args.append(mode)
    text = "\n".join(" ".join(repr(float(x)) for x in r) for r in rays) + "\n"
    # The CLI carries its own sanitizer runtime when the tests run under a preloaded one.
    env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
    out = subprocess.run(args, input=text, capture_output=True, text=True, check=True,
                         env=env).stdout
    return [[float(x) for x in line.split()] for line in out.splitlines()]


def cube_mesh(lo=-1.0, hi=1.0):
    """A closed axis-aligned cube as 8 vertices and 12 counter-clockwise (outward) triangles."""
    v = np.array([[x, y, z] for x in (lo, hi) for y in (lo, hi) for z in (lo, hi)], np.float64)
    # vertex index = 4 x + 2 y + z
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = []
    for a, b, c, d in quads:
        tris += [(a, b, c), (a, c, d)]
    return v, np.array(tris, np.int64)


def icosphere(subdivisions=2, radius=1.0):
    """A closed triangulated sphere (outward triangles)."""
    t = (1 + 5 ** 0.5) / 2
    v = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t],
         [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
         [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
         [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    v = [np.array(p, float) / np.linalg.norm(p) for p in v]
    for _ in range(subdivisions):
        cache = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                m = v[a] + v[b]
                v.append(m / np.linalg.norm(m))
                cache[key] = len(v) - 1
            return cache[key]

        nf = []
        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        f = nf
    return np.array(v) * radius, np.array(f, np.int64)


def random_rays(rng, n, spread=3.0, target=0.8):
    """Rays from points on a sphere of radius `spread` towards points near the origin."""
    o = rng.normal(size=(n, 3))
    o *= spread / np.linalg.norm(o, axis=1, keepdims=True)
    d = rng.uniform(-target, target, size=(n, 3)) - o
    return np.concatenate([o, d], axis=1)


@pytest.fixture
def rng():
    return np.random.default_rng(12345)
