#!/usr/bin/python3
"""Benchmarks of the Python module (docs/performance.md). Short runs; say the load.

  PYTHONPATH=build/release/python /usr/bin/python3 python/bench_python.py [--open3d] [--distance]

1. Python overhead of cast_rays over the C++ batch path (Scene::intersect over a RayArray with
   preallocated columns), 10^6 rays at a 1M-triangle sphere, best of 3 each.
2. compute_distance / compute_signed_distance points per second on the same sphere, and the same
   for Open3D's RaycastingScene when --open3d is given (python3-open3d). --distance runs only 2.
"""
import os
import sys
import time

import numpy as np

import raycast
from raycast import _raycast


def uv_sphere(n_theta, n_phi):
    """A closed sphere of 2 n_phi (n_theta - 1) triangles."""
    th = np.linspace(0, np.pi, n_theta + 1)[1:-1]
    ph = np.linspace(0, 2 * np.pi, n_phi, endpoint=False)
    t, p = np.meshgrid(th, ph, indexing="ij")
    v = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], -1).reshape(-1, 3)
    v = np.concatenate([[[0, 0, 1]], v, [[0, 0, -1]]])
    rows, tris = n_theta - 1, []
    idx = lambda i, j: 1 + i * n_phi + (j % n_phi)
    j = np.arange(n_phi)
    tris.append(np.stack([np.zeros(n_phi, int), idx(0, j), idx(0, j + 1)], 1))
    for i in range(rows - 1):
        a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j), idx(i + 1, j + 1)
        tris += [np.stack([a, c, d], 1), np.stack([a, d, b], 1)]
    last = len(v) - 1
    tris.append(np.stack([idx(rows - 1, j), np.full(n_phi, last), idx(rows - 1, j + 1)], 1))
    return v, np.concatenate(tris)


def best(f, k=2):
    """The least process CPU time (all threads) of k runs: robust to other processes' load."""
    out = []
    for _ in range(k):
        t0 = time.process_time()
        f()
        out.append(time.process_time() - t0)
    return min(out)


def main():
    open3d = "--open3d" in sys.argv
    v, f = uv_sphere(501, 1000)
    print(f"load {os.getloadavg()}; {len(f)} triangles; {os.cpu_count()} cores")
    scene = raycast.Scene()
    scene.add_triangles(v, f)
    scene.commit()
    rng = np.random.default_rng(1)
    n = 10**6
    o = rng.normal(size=(n, 3))
    o *= 3 / np.linalg.norm(o, axis=1, keepdims=True)
    rays = np.concatenate([o, rng.uniform(-1, 1, (n, 3)) - o], 1)
    for dtype in () if "--distance" in sys.argv else (np.float64, np.float32):
        r = rays.astype(dtype)
        py_s = best(lambda: scene.cast_rays(r))
        cpp_s = best(lambda: _raycast._time_intersect(scene, r))
        print(f"cast_rays {np.dtype(dtype).name}: python {py_s:.3f} cpu-s, C++ batch {cpp_s:.3f} "
              f"cpu-s, overhead {100 * (py_s - cpp_s) / cpp_s:.1f}%, "
              f"{n / py_s / 1e6:.2f} Mrays per cpu-s")
    scene.compute_distance(np.zeros((1, 3)))  # builds the distance BVH once
    d = rng.normal(size=(5000, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    sets = {"cube [-1.5, 1.5]^3": rng.uniform(-1.5, 1.5, (5000, 3)),
            "shell 1.2 < |p| < 1.5": d * rng.uniform(1.2, 1.5, (5000, 1)),
            "shell 0.5 < |p| < 0.9": d * rng.uniform(0.5, 0.9, (5000, 1))}
    o3 = None
    if open3d:
        import open3d as o3d
        mesh = o3d.t.geometry.TriangleMesh()
        mesh.vertex.positions = o3d.core.Tensor(v.astype(np.float32))
        mesh.triangle.indices = o3d.core.Tensor(f.astype(np.int32))
        o3 = o3d.t.geometry.RaycastingScene()
        o3.add_triangles(mesh)
        o3.compute_distance(o3d.core.Tensor(np.zeros((1, 3), np.float32)))
    for name, pts in sets.items():
        pts = pts.astype(np.float32).astype(np.float64)  # the same points for both
        d_s = best(lambda: scene.compute_distance(pts), 3)
        sd_s = best(lambda: scene.compute_signed_distance(pts), 3)
        sd = scene.compute_signed_distance(pts)
        r = np.linalg.norm(pts, axis=1)
        clear = np.abs(r - 1) > 1e-3  # the polyhedron is within 1e-5 of the unit sphere
        wrong = np.sum((sd[clear] < 0) != (r[clear] < 1))
        line = (f"{name}: raycast distance {len(pts) / d_s:,.0f}, signed {len(pts) / sd_s:,.0f} "
                f"points per cpu-s, {wrong} wrong signs")
        if o3 is not None:
            q = o3d.core.Tensor(pts.astype(np.float32))
            o_s = best(lambda: o3.compute_distance(q, nthreads=2), 3)
            od = o3.compute_distance(q, nthreads=2).numpy()
            osd = o3.compute_signed_distance(q, nthreads=2).numpy()
            ours = scene.compute_distance(pts)
            line += (f"; open3d distance {len(pts) / o_s:,.0f} points per cpu-s "
                     f"(max |difference| {np.max(np.abs(od - ours)):.1e}), "
                     f"{np.sum((osd[clear] < 0) != (r[clear] < 1))} wrong signs")
        print(line, flush=True)


if __name__ == "__main__":
    main()
