#!/usr/bin/python3
"""raycast.dask throughput on a LocalCluster of 1 and then 2 worker processes (one thread each)
(docs/python-dask.md):

  PYTHONPATH=build/release/python /usr/bin/python3 python/bench_dask.py [--rays N] [--chunk C]

The scene is a pickled RaycastingScene holding a 200,000-triangle sphere; N rays (default
4,000,000) in chunks of C (default 250,000), drawn on the workers (dask.array.random), are cast
for t_hit. Each cluster first runs one small query so that every worker has built the scene; the
figure is rays per wall-clock second of the compute that follows, best of 2. For scale, the
same graph run chunk after chunk in this process (dask's synchronous scheduler).
"""
import argparse
import os
import time

import dask.array as da
import numpy as np
from dask.distributed import Client, LocalCluster

import raycast
import raycast.dask as rd
from bench_python import uv_sphere


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rays", type=int, default=4_000_000)
    parser.add_argument("--chunk", type=int, default=250_000)
    args = parser.parse_args()
    vertices, triangles = uv_sphere(201, 500)
    scene = raycast.RaycastingScene()
    scene.add_triangles(vertices.astype(np.float32), triangles)
    rng = da.random.RandomState(1)
    origins = rng.normal(size=(args.rays, 3), chunks=(args.chunk, 3))
    origins = 3 * origins / da.linalg.norm(origins, axis=1, keepdims=True)
    directions = rng.uniform(-1, 1, (args.rays, 3), chunks=(args.chunk, 3)) - origins
    rays = da.concatenate([origins, directions], axis=1).astype(np.float32)
    print(f"load {os.getloadavg()}; {len(triangles):,} triangles; {args.rays:,} rays in chunks "
          f"of {args.chunk:,}; {os.cpu_count()} cores")
    scene.cast_rays(rays[:10].compute())  # builds the scene
    start = time.perf_counter()
    rd.cast_rays(scene, rays).compute(scheduler="sync")
    print(f"in this process, one chunk after another (no cluster): "
          f"{args.rays / (time.perf_counter() - start) / 1e6:.2f} Mrays per second", flush=True)
    for workers in (1, 2):
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            client.compute(rd.cast_rays(scene, rays[: args.chunk * workers]), sync=True)
            best = float("inf")
            for _ in range(2):
                start = time.perf_counter()
                t = client.compute(rd.cast_rays(scene, rays), sync=True)
                best = min(best, time.perf_counter() - start)
            builds = sum(client.run(rd.builds_in_this_process).values())
            print(f"{workers} worker(s): {args.rays / best / 1e6:.2f} Mrays per second "
                  f"({best:.2f} s), {int(np.isfinite(t).sum()):,} hits, scene built {builds} "
                  f"time(s)", flush=True)


if __name__ == "__main__":
    main()
