"""raycast.RaycastingScene against Open3D's documented RaycastingScene API: constructor,
add_triangles forms, answer keys, shapes and dtypes, no commit step, pinhole rays."""
import pickle

import numpy as np
import pytest

import raycast
from conftest import cube_mesh, icosphere

TRIANGLE_V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0]], np.float32)
TRIANGLE_T = np.array([[0, 1, 2]], np.uint32)
INVALID = raycast.RaycastingScene.INVALID_ID


class FakeTensor:
    """Open3D's tensor as raycast sees it: only .numpy()."""

    def __init__(self, a):
        self._a = np.asarray(a)

    def numpy(self):
        return self._a


class DLPackOnly:
    """An array seen only through the DLPack protocol."""

    def __init__(self, a):
        self._a = np.ascontiguousarray(a)

    def __dlpack__(self, stream=None):
        return self._a.__dlpack__()

    def __dlpack_device__(self):
        return self._a.__dlpack_device__()


class ArrayInterfaceOnly:
    """An array seen only through __array__."""

    def __init__(self, a):
        self._a = np.asarray(a)

    def __array__(self, dtype=None):
        return self._a if dtype is None else self._a.astype(dtype)


class FakeTensorMesh:
    """Open3D's t.geometry.TriangleMesh shape: vertex.positions, triangle.indices."""

    class _Attrs:
        pass

    def __init__(self, v, t):
        self.vertex, self.triangle = self._Attrs(), self._Attrs()
        self.vertex.positions, self.triangle.indices = FakeTensor(v), FakeTensor(t)


class FakeLegacyMesh:
    """Open3D's legacy geometry.TriangleMesh shape: vertices, triangles (array-likes)."""

    def __init__(self, v, t):
        self.vertices, self.triangles = v.tolist(), t.tolist()


def unit_cube():
    v, t = cube_mesh(0.0, 1.0)
    return v.astype(np.float32), t


def test_cast_rays_answers_open3d_keys_shapes_and_dtypes():
    scene = raycast.RaycastingScene()
    assert scene.add_triangles(TRIANGLE_V, TRIANGLE_T) == 0
    rays = np.array([[0.2, 0.1, 1, 0, 0, -1], [10, 10, 10, 1, 0, 0]], np.float32)
    ans = scene.cast_rays(rays)
    assert list(ans) == ["t_hit", "geometry_ids", "primitive_ids", "primitive_uvs",
                         "primitive_normals"]
    dtypes = {k: v.dtype for k, v in ans.items()}
    assert dtypes == {"t_hit": np.float32, "geometry_ids": np.uint32, "primitive_ids": np.uint32,
                      "primitive_uvs": np.float32, "primitive_normals": np.float32}
    assert ans["t_hit"][0].item() == 1.0 and np.isinf(ans["t_hit"][1].item())
    assert ans["geometry_ids"].tolist() == [0, INVALID]
    assert ans["primitive_ids"].tolist() == [0, INVALID]
    np.testing.assert_allclose(ans["primitive_uvs"][0], [0.1, 0.1], atol=1e-6)  # .8 a+.1 b+.1 c
    np.testing.assert_allclose(np.abs(ans["primitive_normals"][0]), [0, 0, 1])


def test_cast_rays_float64_keyword_gives_engine_answers():
    scene = raycast.RaycastingScene()
    scene.add_triangles(TRIANGLE_V, TRIANGLE_T)
    rays = np.array([[0.2, 0.1, 1 / 3, 0, 0, -1]])
    ans = scene.cast_rays(rays, dtype=np.float64)
    assert ans["t_hit"].dtype == np.float64 and ans["t_hit"][0] == 1 / 3


@pytest.mark.parametrize("shape", [[11], [1, 2, 3], [32, 14]])
def test_answers_keep_the_leading_shape(shape, rng):
    scene = raycast.RaycastingScene()
    scene.add_triangles(TRIANGLE_V, TRIANGLE_T)
    rays = rng.uniform(size=shape + [6]).astype(np.float32)
    points = rng.uniform(size=shape + [3]).astype(np.float32)
    tails = {"primitive_uvs": [2], "primitive_normals": [3], "points": [3]}
    for name in ["count_intersections", "test_occlusions"]:
        assert list(getattr(scene, name)(rays).shape) == shape
    for name in ["compute_distance", "compute_signed_distance", "compute_occupancy"]:
        assert list(getattr(scene, name)(points).shape) == shape
    for k, v in scene.cast_rays(rays).items():
        assert list(v.shape) == shape + tails.get(k, []), k
    for k, v in scene.compute_closest_points(points).items():
        assert list(v.shape) == shape + tails.get(k, []), k


def test_no_commit_step_and_rebuild_after_adding():
    scene = raycast.RaycastingScene()
    ray = np.array([[5, 0.5, 0.5, -1, 0, 0]], np.float32)
    assert np.isinf(scene.cast_rays(ray)["t_hit"][0])  # an empty scene answers misses
    v, t = unit_cube()
    assert scene.add_triangles(v, t) == 0
    assert scene.cast_rays(ray)["t_hit"][0] == 4.0
    assert scene.add_triangles(v + np.float32(3), t) == 1  # after a query: rebuilt
    assert scene.count_intersections(ray)[0] == 2
    assert scene.add_triangles(v + np.float32([2.5, 0, 0]), t) == 2
    ans = scene.cast_rays(ray)
    assert ans["t_hit"][0] == 1.5 and ans["geometry_ids"][0] == 2
    assert scene.count_intersections(ray)[0] == 4


@pytest.mark.parametrize("make", [
    lambda v, t: (FakeTensorMesh(v, t),),
    lambda v, t: (FakeLegacyMesh(v, t),),
    lambda v, t: (FakeTensor(v), FakeTensor(t)),
    lambda v, t: (v.tolist(), t.astype(np.int64)),
    lambda v, t: (v.astype(int).tolist(), t.tolist()),
    lambda v, t: (DLPackOnly(v), DLPackOnly(t)),
    lambda v, t: (ArrayInterfaceOnly(v), ArrayInterfaceOnly(t)),
    lambda v, t: (memoryview(np.ascontiguousarray(v)), t.astype(np.int32)),
])
def test_add_triangles_accepts_meshes_tensors_and_array_likes(make):
    v, t = unit_cube()
    scene = raycast.RaycastingScene()
    scene.add_triangles(*make(v, t))
    rays = np.array([[0.5, 0.5, -1, 0, 0, 1], [0.5, 0.5, 0.5, 0, 0, 1], [10, 10, 10, 1, 0, 0]],
                    np.float32)
    np.testing.assert_array_equal(scene.count_intersections(FakeTensor(rays)).numpy(), [2, 1, 0])
    np.testing.assert_array_equal(scene.count_intersections(DLPackOnly(rays)), [2, 1, 0])
    np.testing.assert_array_equal(scene.count_intersections(ArrayInterfaceOnly(rays)), [2, 1, 0])


def test_occlusions_respect_tnear_and_tfar():
    scene = raycast.RaycastingScene()
    scene.add_triangles(TRIANGLE_V, TRIANGLE_T)
    rays = np.array([[0.2, 0.1, 1, 0, 0, -1], [10, 10, 10, 1, 0, 0]], np.float32)
    assert scene.test_occlusions(rays).tolist() == [True, False]
    assert scene.test_occlusions(rays, tfar=0.5).tolist() == [False, False]
    assert scene.test_occlusions(rays, tnear=1.5).tolist() == [False, False]
    assert scene.test_occlusions(rays, tnear=1.0, tfar=1.0).tolist() == [True, False]


def test_list_intersections_keys_and_crossing_records():
    v, t = unit_cube()
    scene = raycast.RaycastingScene()
    scene.add_triangles(v, t)
    rays = np.array([[0.5, 0.25, -1, 0, 0, 1], [0.5, 0.5, 0.5, 0, 0, 1], [10, 10, 10, 1, 0, 0]],
                    np.float32)
    ans = scene.list_intersections(rays)
    assert set(ans) == {"ray_splits", "ray_ids", "t_hit", "geometry_ids", "primitive_ids",
                        "primitive_uvs"}
    assert ans["ray_splits"].tolist() == [0, 2, 3, 3] and ans["ray_splits"].dtype == np.uint32
    assert ans["ray_ids"].tolist() == [0, 0, 1] and ans["ray_ids"].dtype == np.uint32
    np.testing.assert_allclose(ans["t_hit"], [1, 2, 0.5])
    # The (u, v) of each crossing in its triangle rebuild the crossing's point.
    tri = t[ans["primitive_ids"]]
    uv = ans["primitive_uvs"].astype(np.float64)
    p = ((1 - uv.sum(1))[:, None] * v[tri[:, 0]] + uv[:, :1] * v[tri[:, 1]]
         + uv[:, 1:] * v[tri[:, 2]])
    r = rays[ans["ray_ids"]]
    np.testing.assert_allclose(p, r[:, :3] + ans["t_hit"][:, None] * r[:, 3:], atol=1e-6)


def test_closest_points_answer_triangle_uvs_and_normals(rng):
    v, t = icosphere(2)
    scene = raycast.RaycastingScene()
    scene.add_triangles(v, t)
    q = rng.uniform(-2, 2, (500, 3))
    ans = scene.compute_closest_points(q, dtype=np.float64)
    assert list(ans) == ["points", "geometry_ids", "primitive_ids", "primitive_uvs",
                         "primitive_normals"]
    tri = v[t[ans["primitive_ids"]]]
    uv = ans["primitive_uvs"]
    p = (1 - uv.sum(1))[:, None] * tri[:, 0] + uv[:, :1] * tri[:, 1] + uv[:, 1:] * tri[:, 2]
    np.testing.assert_allclose(p, ans["points"], atol=1e-7)
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    np.testing.assert_allclose(ans["primitive_normals"], n / np.linalg.norm(n, axis=1)[:, None])
    np.testing.assert_allclose(np.linalg.norm(ans["points"] - q, axis=1),
                               scene.compute_distance(q, dtype=np.float64))


def test_distances_and_occupancy_of_the_unit_cube():
    v, t = unit_cube()
    scene = raycast.RaycastingScene()
    scene.add_triangles(v, t)
    q = np.array([[0.5, 0.5, 0.5], [-0.5, -0.5, -0.5], [0, 0, 0]], np.float32)
    d = scene.compute_distance(q)
    assert d.dtype == np.float32
    np.testing.assert_allclose(d, [0.5, np.sqrt(0.75), 0], rtol=1e-6)
    for nsamples in (1, 3, 9):
        np.testing.assert_allclose(scene.compute_signed_distance(q, nsamples=nsamples),
                                   [-0.5, np.sqrt(0.75), 0], rtol=1e-6)
        assert scene.compute_occupancy(q, nsamples=nsamples).tolist() == [1, 0, 1]
    assert scene.compute_occupancy(q).dtype == np.float32


def test_pinhole_fov_form_follows_open3d_camera_frame():
    rays = raycast.RaycastingScene.create_rays_pinhole(
        fov_deg=90, center=[0, 0, 1], eye=[0, 0, 0], up=[0, 1, 0], width_px=4, height_px=2)
    assert rays.shape == (2, 4, 6) and rays.dtype == np.float32
    assert np.all(rays[..., :3] == 0)
    # focal = 0.5 * 4 / tan(45 deg) = 2; camera x = up x forward = +x, camera y = +y.
    x = (np.arange(4) + 0.5 - 2) / 2
    y = (np.arange(2) + 0.5 - 1) / 2
    np.testing.assert_allclose(rays[0, :, 3], x, atol=1e-7)
    np.testing.assert_allclose(rays[:, 0, 4], y, atol=1e-7)
    np.testing.assert_allclose(rays[..., 5], 1)


def test_pinhole_intrinsic_form_places_the_camera_centre():
    k = np.array([[100, 0, 32], [0, 100, 24], [0, 0, 1.0]])
    e = np.eye(4)
    e[:3, 3] = [1, 2, 3]  # world-to-camera translation: centre at -t
    rays = raycast.RaycastingScene.create_rays_pinhole(FakeTensor(k), e, 64, 48)
    np.testing.assert_allclose(rays[..., :3], np.broadcast_to([-1, -2, -3], (48, 64, 3)))
    np.testing.assert_allclose(rays[24, 32, 3:], [0.005, 0.005, 1], atol=1e-7)
    same = raycast.RaycastingScene.create_rays_pinhole(intrinsic_matrix=k, extrinsic_matrix=e,
                                                       width_px=64, height_px=48)
    np.testing.assert_array_equal(rays, same)


def test_answers_answer_open3d_tensor_methods():
    scene = raycast.RaycastingScene()
    scene.add_triangles(TRIANGLE_V, TRIANGLE_T)
    ans = scene.cast_rays(np.array([[0.2, 0.1, 1, 0, 0, -1]], np.float32))
    t = ans["t_hit"]
    assert type(t.numpy()) is np.ndarray and t.cpu() is t
    assert t.to(np.float64).dtype == np.float64
    assert t.to("Float64").dtype == np.float64  # str(open3d.core.float64)
    assert ans["geometry_ids"].to("Int64").dtype == np.int64
    assert t[0].cpu().item() == 1.0 and t[0].ndim == 0
    with pytest.raises(TypeError, match="dtype"):
        t.to("not a dtype")


def test_scene_pickles_as_its_meshes():
    v, t = unit_cube()
    scene = raycast.RaycastingScene()
    scene.add_triangles(v, t)
    copy = pickle.loads(pickle.dumps(scene))
    q = np.array([[0.5, 0.5, 2.0]])
    assert copy.compute_distance(q)[0] == scene.compute_distance(q)[0] == 1.0


@pytest.mark.parametrize("kwargs, match", [
    ({"device": "CUDA:0"}, "CPU"), ({"nthreads": -1}, "nthreads"), ({"nthreads": 1.5}, "nthreads")])
def test_constructor_rejects_what_it_cannot_do(kwargs, match):
    with pytest.raises(ValueError, match=match):
        raycast.RaycastingScene(**kwargs)


def test_bad_inputs_name_what_was_expected():
    scene = raycast.RaycastingScene()
    with pytest.raises(TypeError, match="triangle mesh"):
        scene.add_triangles(object())
    with pytest.raises(TypeError, match="vertex_positions"):
        scene.add_triangles("vertices", TRIANGLE_T)
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        scene.add_triangles(np.zeros((3, 2), np.float32), TRIANGLE_T)
    with pytest.raises(ValueError, match="out of range"):
        scene.add_triangles(TRIANGLE_V, -TRIANGLE_T.astype(np.int64) - 1)
    scene.add_triangles(TRIANGLE_V, TRIANGLE_T)
    with pytest.raises(ValueError, match=r"\(\.\.\., 6\)"):
        scene.cast_rays(np.zeros((2, 5), np.float32))
    with pytest.raises(TypeError, match="rays"):
        scene.cast_rays(None)
    with pytest.raises(TypeError, match="rays"):
        scene.cast_rays([[0, 0, 1], [0]])
    with pytest.raises(ValueError, match="int64 array"):
        scene.cast_rays(np.zeros((1, 6), np.int64))  # an integer array is not converted
    assert scene.cast_rays([[0.5, 0.25, 1, 0, 0, -1]])["t_hit"][0] == 1.0  # a list of numbers
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        scene.compute_distance(np.zeros((2, 4), np.float32))
    with pytest.raises(ValueError, match="nsamples"):
        scene.compute_occupancy(np.zeros((1, 3)), nsamples=0)
    with pytest.raises(ValueError, match="width_px"):
        raycast.RaycastingScene.create_rays_pinhole(60, [0, 0, 1], [0, 0, 0], [0, 1, 0], 0, 4)
    with pytest.raises(ValueError, match="camera frame"):
        raycast.RaycastingScene.create_rays_pinhole(60, [0, 0, 0], [0, 0, 0], [0, 1, 0], 4, 4)
