"""raycast.RaycastingScene: Open3D's `open3d.t.geometry.RaycastingScene` API over raycast's
engine (docs/python.md "Coming from Open3D"). Same constructor, methods, keywords, answer keys,
shapes and dtypes; there is no commit step: the first query builds the acceleration structure
and a query after more add_triangles calls rebuilds it."""
import numpy as np

from . import _raycast
from .answers import answer_dict, as_answer
from .inputs import TRIANGLES, VERTICES, as_numpy, mesh_arrays, points_array, rays_array
from .pinhole import pinhole_rays_fov, pinhole_rays_intrinsic


def _check_count(name, value, least):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) \
            or value < least:
        raise ValueError(f"{name} must be an integer >= {least}, got {value!r}")


class RaycastingScene:
    """A set of triangle meshes to query with rays and points, as Open3D's class.

    `nthreads` is accepted and unused (every query runs on all cores); `device` must be the CPU.
    Answers are `raycast.Tensor`s: numpy arrays that also answer `.numpy()`, `.cpu()` and
    `.to(dtype)`. Floats are float32 as Open3D's; `dtype=numpy.float64` gives the engine's
    float64 answers unrounded."""

    INVALID_ID = _raycast.INVALID_ID

    def __init__(self, nthreads=0, device="CPU:0"):
        _check_count("nthreads", nthreads, 0)
        if str(device).lower().split(":")[0] != "cpu":
            raise ValueError(f"raycast runs on the CPU: device must be 'CPU:0', got {device}")
        self._meshes = []  # (vertices float (n, 3), triangles int64 (m, 3)) in id order
        self._engine = _raycast.Scene()

    def add_triangles(self, vertex_positions, triangle_indices=None):
        """Adds a mesh from vertices (n, 3) and triangles (m, 3), or from one mesh object
        (Open3D's tensor or legacy TriangleMesh); returns its geometry id (0, 1, ... in order)."""
        if triangle_indices is None:
            vertices, triangles = mesh_arrays(vertex_positions)
        else:
            vertices = as_numpy(vertex_positions, "vertex_positions", VERTICES, real=True)
            triangles = as_numpy(triangle_indices, "triangle_indices", TRIANGLES)
        if self._engine.committed:
            self._rebuild()
        geometry_id = self._engine.add_triangles(vertices, triangles)
        self._meshes.append((np.array(vertices), np.array(triangles, np.int64)))
        return geometry_id

    def _rebuild(self):
        # The engine's scenes are immutable once built: a new one takes every mesh so far.
        engine = _raycast.Scene()
        for vertices, triangles in self._meshes:
            engine.add_triangles(vertices, triangles)
        self._engine = engine

    def cast_rays(self, rays, nthreads=0, dtype=np.float32):
        """The first hit of each ray (..., 6): dict of t_hit (inf on a miss), geometry_ids and
        primitive_ids (INVALID_ID on a miss), primitive_uvs (..., 2) and primitive_normals
        (..., 3, unit)."""
        _check_count("nthreads", nthreads, 0)
        ans = self._engine.cast_rays(rays_array(rays))
        del ans["points"]
        return answer_dict(ans, {"t_hit": dtype, "primitive_uvs": dtype,
                                 "primitive_normals": dtype})

    def test_occlusions(self, rays, tnear=0.0, tfar=np.inf, nthreads=0):
        """True where a ray meets a surface with tnear <= t <= tfar (bool, shape (...))."""
        _check_count("nthreads", nthreads, 0)
        return as_answer(self._engine.test_occlusions(rays_array(rays), float(tnear), float(tfar)))

    def count_intersections(self, rays, nthreads=0):
        """The number of surfaces each ray crosses at t >= 0 (int32, shape (...))."""
        _check_count("nthreads", nthreads, 0)
        return as_answer(self._engine.count_intersections(rays_array(rays)))

    def list_intersections(self, rays, nthreads=0, dtype=np.float32):
        """Every crossing of every ray: dict of ray_splits (num_rays + 1; ray i's crossings are
        [ray_splits[i], ray_splits[i + 1])), ray_ids, t_hit, geometry_ids, primitive_ids and
        primitive_uvs (num_intersections, 2)."""
        _check_count("nthreads", nthreads, 0)
        r = rays_array(rays)
        ans = self._engine.list_intersections(r)
        flat = np.asarray(r, np.float64).reshape(-1, 6)[ans["ray_ids"]]
        points = flat[:, :3] + ans["t_hit"][:, None] * flat[:, 3:]
        # The triangle of each crossing is the one closest to its point (at distance ~0).
        closest = self._engine.compute_closest_points(points)
        uvs, _ = self._barycentric(points, ans["geometry_ids"], closest["primitive_ids"])
        out = {"ray_splits": ans["ray_splits"], "ray_ids": ans["ray_ids"], "t_hit": ans["t_hit"],
               "geometry_ids": ans["geometry_ids"], "primitive_ids": closest["primitive_ids"],
               "primitive_uvs": uvs}
        return answer_dict(out, {"ray_splits": np.uint32, "ray_ids": np.uint32, "t_hit": dtype,
                                 "primitive_uvs": dtype})

    def compute_closest_points(self, query_points, nthreads=0, dtype=np.float32):
        """The closest surface point to each query point (..., 3): dict of points, geometry_ids,
        primitive_ids, primitive_uvs (..., 2) and primitive_normals (..., 3, unit)."""
        _check_count("nthreads", nthreads, 0)
        ans = self._engine.compute_closest_points(points_array(query_points))
        uvs, normals = self._barycentric(ans["points"], ans["geometry_ids"],
                                         ans["primitive_ids"])
        out = {"points": ans["points"], "geometry_ids": ans["geometry_ids"],
               "primitive_ids": ans["primitive_ids"], "primitive_uvs": uvs,
               "primitive_normals": normals}
        return answer_dict(out, {"points": dtype, "primitive_uvs": dtype,
                                 "primitive_normals": dtype})

    def compute_distance(self, query_points, nthreads=0, dtype=np.float32):
        """The distance from each point (..., 3) to the closest surface."""
        _check_count("nthreads", nthreads, 0)
        return as_answer(self._engine.compute_distance(points_array(query_points)), dtype)

    def compute_signed_distance(self, query_points, nthreads=0, nsamples=1, dtype=np.float32):
        """The distance to the closest surface, negative inside a closed mesh. The inside test
        is exact, so `nsamples` (Open3D's number of voting rays) is accepted and unnecessary."""
        _check_count("nthreads", nthreads, 0)
        _check_count("nsamples", nsamples, 1)
        return as_answer(self._engine.compute_signed_distance(points_array(query_points)),
                         dtype)

    def compute_occupancy(self, query_points, nthreads=0, nsamples=1):
        """1.0 where a point (..., 3) is inside or on a closed mesh, else 0.0 (float32). Exact,
        so `nsamples` (Open3D's number of voting rays) is accepted and unnecessary."""
        _check_count("nthreads", nthreads, 0)
        _check_count("nsamples", nsamples, 1)
        return as_answer(self._engine.compute_occupancy(points_array(query_points)))

    @staticmethod
    def create_rays_pinhole(*args, **kwargs):
        """Open3D's pinhole rays (height_px, width_px, 6) float32, in either of its forms:
        (intrinsic_matrix 3x3, extrinsic_matrix 4x4 world-to-camera, width_px, height_px) or
        (fov_deg, center, eye, up, width_px, height_px) with fov_deg horizontal. Directions
        have unit depth, so t_hit is the depth along the optical axis."""
        if "intrinsic_matrix" in kwargs or (args and np.ndim(as_numpy(
                args[0], "intrinsic_matrix", "3x3")) == 2):
            return as_answer(pinhole_rays_intrinsic(*args, **kwargs))
        return as_answer(pinhole_rays_fov(*args, **kwargs))

    def _barycentric(self, points, geometry_ids, primitive_ids):
        """Open3D's (u, v) of each point in its triangle (point = (1 - u - v) a + u b + v c)
        and the triangle's unit normal (b - a) x (c - a); 0 where there is no triangle."""
        lead = np.shape(geometry_ids)
        uvs, normals = np.zeros(lead + (2,)), np.zeros(lead + (3,))
        valid = (geometry_ids != _raycast.INVALID_ID) & (primitive_ids != _raycast.INVALID_ID)
        for g in np.unique(geometry_ids[valid]):
            rows = valid & (geometry_ids == g)
            vertices, triangles = self._meshes[int(g)]
            a, b, c = (vertices[triangles[primitive_ids[rows], k]].astype(np.float64)
                       for k in range(3))
            e1, e2, w = b - a, c - a, np.asarray(points[rows], np.float64) - a
            d00, d01, d11 = (e1 * e1).sum(-1), (e1 * e2).sum(-1), (e2 * e2).sum(-1)
            d20, d21 = (w * e1).sum(-1), (w * e2).sum(-1)
            with np.errstate(divide="ignore", invalid="ignore"):
                det = d00 * d11 - d01 * d01
                uvs[rows] = np.nan_to_num(np.stack(
                    [(d11 * d20 - d01 * d21) / det, (d00 * d21 - d01 * d20) / det], -1))
                n = np.cross(e1, e2)
                normals[rows] = np.nan_to_num(n / np.linalg.norm(n, axis=-1, keepdims=True))
        return uvs, normals

    def __reduce__(self):
        # Pickles as its meshes (Dask ships scenes to workers this way); the copy rebuilds
        # on its first query.
        return (_restore, (list(self._meshes),))


def _restore(meshes):
    scene = RaycastingScene()
    for vertices, triangles in meshes:
        scene.add_triangles(vertices, triangles)
    return scene
