"""raycast.dask: queries over dask arrays of rays or points, chunk by chunk, on whatever Dask
scheduler is active (a dask.distributed cluster, or threads). Each worker process builds the
scene once, from a scene file's path or from a pickled RaycastingScene, and keeps it for every
later chunk (docs/python-dask.md)."""
import hashlib
import os
import pickle
import threading

import dask
import dask.array as da
import numpy as np

from . import _raycast
from .open3d_scene import RaycastingScene

# Per worker process: scene token -> built scene, and how many scenes this process has built.
_SCENES = {}
_LOCK = threading.Lock()
_BUILDS = 0

_TAILS = {"primitive_uvs": (2,), "primitive_normals": (3,), "points": (3,)}
_RAY_QUERIES = {"cast_rays", "test_occlusions", "count_intersections"}
_POINT_QUERIES = {"compute_distance", "compute_signed_distance", "compute_occupancy",
                  "compute_closest_points"}


def builds_in_this_process():
    """How many scenes this process has built for dask queries (one per scene and process)."""
    return _BUILDS


class _SceneSource:
    """What a task needs to build the scene: a path, or pickled RaycastingScene bytes."""

    def __init__(self, scene):
        if isinstance(scene, (str, os.PathLike)):
            path = os.path.abspath(os.fspath(scene))
            self.kind, self.payload = "path", path
            self.token = "path:" + path
        elif isinstance(scene, RaycastingScene):
            self.kind, self.payload = "pickle", pickle.dumps(scene)
            self.token = "pickle:" + hashlib.sha256(self.payload).hexdigest()
        else:
            raise TypeError("raycast.dask needs the scene as a scene file's path (loaded by "
                            "raycast.Scene.load on each worker) or a raycast.RaycastingScene "
                            f"(pickled once), got {type(scene).__name__}")


def _scene(kind, token, payload):
    global _BUILDS
    with _LOCK:
        scene = _SCENES.get(token)
        if scene is None:
            scene = _raycast.Scene.load(payload) if kind == "path" else pickle.loads(payload)
            _SCENES[token] = scene
            _BUILDS += 1
        return scene


def _run_block(block, payload, *, kind, scene_token, method, key, options):
    answer = getattr(_scene(kind, scene_token, payload), method)(block, **options)
    if isinstance(answer, dict):
        answer = answer[key]
    return np.asarray(answer)


def query(scene, array, method, key=None, dtype=None, **options):
    """A dask array of scene.<method>(chunk) for each chunk of `array` (rays (..., 6) or
    points (..., 3); the last axis is kept whole). For methods answering a dict, `key` names
    the answer to keep (e.g. "t_hit"). `dtype` is the answer's dtype (by default the engine's:
    float64 floats for a path's raycast.Scene, float32 for a RaycastingScene). `options` go to
    the method (tnear=, tfar=, dtype=...)."""
    width = 6 if method in _RAY_QUERIES else 3 if method in _POINT_QUERIES else None
    if width is None:
        raise ValueError(f"method must be one of {sorted(_RAY_QUERIES | _POINT_QUERIES)}, "
                         f"got {method!r}")
    if method in ("cast_rays", "compute_closest_points") and key is None:
        raise ValueError(f"{method} answers a dict: name the key to keep (key='t_hit', ...)")
    array = da.asarray(array)
    if array.ndim < 1 or array.shape[-1] != width:
        raise ValueError(f"{method} needs a dask array shaped (..., {width}), got {array.shape}")
    array = array.rechunk({array.ndim - 1: width})
    source = _SceneSource(scene)
    tail = _TAILS.get(key, ())
    if dtype is None:
        dtype = _default_dtype(method, key, source.kind == "pickle", options.get("dtype"))
    payload = dask.delayed(source.payload, pure=True)  # one graph node: sent once per worker
    lead = array.ndim - 1
    chunks = array.chunks[:-1] + tuple((n,) for n in tail)
    meta = np.empty((0,) * (lead + len(tail)), dtype)
    kwargs = dict(kind=source.kind, scene_token=source.token, method=method, key=key,
                  options=options, dtype=dtype, chunks=chunks, meta=meta)
    if not tail:
        kwargs["drop_axis"] = lead
    return da.map_blocks(_run_block, array, payload, **kwargs)


def _default_dtype(method, key, open3d_api, requested):
    ints = {"geometry_ids": np.uint32, "primitive_ids": np.uint32}
    if key in ints:
        return np.dtype(ints[key])
    if method == "test_occlusions":
        return np.dtype(bool)
    if method == "count_intersections":
        return np.dtype(np.int32)
    if method == "compute_occupancy":
        return np.dtype(np.float32)
    if requested is not None:
        return np.dtype(requested)
    return np.dtype(np.float32 if open3d_api else np.float64)


def cast_rays(scene, rays, key="t_hit", **options):
    """query(scene, rays, "cast_rays", key): one answer of the first hits, e.g. t_hit."""
    return query(scene, rays, "cast_rays", key=key, **options)


def compute_distance(scene, points, **options):
    """query(scene, points, "compute_distance")."""
    return query(scene, points, "compute_distance", **options)


def compute_signed_distance(scene, points, **options):
    """query(scene, points, "compute_signed_distance")."""
    return query(scene, points, "compute_signed_distance", **options)


def compute_occupancy(scene, points, **options):
    """query(scene, points, "compute_occupancy")."""
    return query(scene, points, "compute_occupancy", **options)
