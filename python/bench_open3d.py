#!/usr/bin/python3
"""raycast.RaycastingScene beside Open3D's RaycastingScene (python3-open3d), the same script
for both (docs/performance.md "Python"):

  PYTHONPATH=build/release/python /usr/bin/python3 python/bench_open3d.py [--points N]

A 1,000,000-triangle sphere; 10^6 rays for cast_rays, N points (default 200,000) for
compute_distance, compute_signed_distance and compute_occupancy, in a cube around it. Figures
are queries per CPU second (process time over all threads, best of 2), after one small query
that builds each library's acceleration structure. Open3D 0.16 as packaged by Debian returns no
ray hits (its Embree intersection misses), so its cast_rays and its ray-based occupancy and sign
are compared for throughput only; the hit counts are printed beside them.
"""
import argparse
import os
import time

import numpy as np

import raycast
from bench_python import uv_sphere


def per_cpu_second(query, count, repeats=2):
    """count / the least process CPU time of `repeats` runs of query()."""
    best = float("inf")
    for _ in range(repeats):
        start = time.process_time()
        query()
        best = min(best, time.process_time() - start)
    return count / best


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=200_000)
    args = parser.parse_args()
    import open3d as o3d

    vertices, triangles = uv_sphere(501, 1000)
    vertices, triangles = vertices.astype(np.float32), triangles.astype(np.uint32)
    print(f"load {os.getloadavg()}; {len(triangles):,} triangles; {os.cpu_count()} cores; "
          f"raycast {raycast.__version__}, open3d {o3d.__version__}")
    rng = np.random.default_rng(1)
    n_rays = 10**6
    origins = rng.normal(size=(n_rays, 3))
    origins *= 3 / np.linalg.norm(origins, axis=1, keepdims=True)
    rays = np.concatenate([origins, rng.uniform(-1, 1, (n_rays, 3)) - origins], 1)
    rays = rays.astype(np.float32)
    points = rng.uniform(-1.5, 1.5, (args.points, 3)).astype(np.float32)

    scenes = {"raycast": raycast.RaycastingScene(), "open3d": o3d.t.geometry.RaycastingScene()}
    inputs = {"raycast": (rays, points),
              "open3d": (o3d.core.Tensor(rays), o3d.core.Tensor(points))}
    for name, scene in scenes.items():
        scene.add_triangles(vertices, triangles) if name == "raycast" else scene.add_triangles(
            o3d.core.Tensor(vertices), o3d.core.Tensor(triangles))
        start = time.perf_counter()
        scene.compute_distance(inputs[name][1][:1])
        scene.cast_rays(inputs[name][0][:1])
        print(f"{name}: first queries (builds) {time.perf_counter() - start:.2f} s wall")
    queries = [("cast_rays", 0, n_rays), ("compute_distance", 1, args.points),
               ("compute_signed_distance", 1, args.points), ("compute_occupancy", 1, args.points)]
    for method, which, count in queries:
        rates = {}
        for name, scene in scenes.items():
            data = inputs[name][which]
            rates[name] = per_cpu_second(lambda: getattr(scene, method)(data), count)
        note = ""
        if method == "cast_rays":
            hits = {n: int(np.isfinite(s.cast_rays(inputs[n][0])["t_hit"].numpy()).sum())
                    for n, s in scenes.items()}
            note = f"; hits raycast {hits['raycast']:,}, open3d {hits['open3d']:,}"
        if method == "compute_occupancy":
            inside = {n: int(s.compute_occupancy(inputs[n][1]).numpy().sum())
                      for n, s in scenes.items()}
            exact = int((np.linalg.norm(points.astype(np.float64), axis=1) < 1).sum())
            note = (f"; inside raycast {inside['raycast']:,}, open3d {inside['open3d']:,}, "
                    f"|p| < 1: {exact:,}")
        print(f"{method}: raycast {rates['raycast']:,.0f}, open3d {rates['open3d']:,.0f} per "
              f"cpu-s, ratio {rates['raycast'] / rates['open3d']:.2f}{note}", flush=True)


if __name__ == "__main__":
    main()
