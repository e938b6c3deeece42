"""raycast.dask on a LocalCluster of 2 worker processes: answers equal the direct query, and
each worker builds the scene once however many chunks it runs."""
import os

import numpy as np
import pytest

import raycast
from conftest import SOURCE_DIR, cube_mesh, random_rays

da = pytest.importorskip("dask.array")
distributed = pytest.importorskip("dask.distributed")
import raycast.dask as rd  # noqa: E402  (needs dask)


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as c:
        yield c


def test_scene_file_cast_and_distance_equal_direct_queries(client, rng, tmp_path):
    path = str(tmp_path / "scene.yaml")
    with open(path, "w") as f:
        f.write("objects:\n  - sphere: {center: [0, 0, 0], radius: 1}\n"
                "  - box: {min: [1, -1, -1], max: [2, 1, 1]}\n")
    rays = random_rays(rng, 4000, spread=8, target=2)
    points = rng.uniform(-3, 3, (4000, 3))
    t = rd.cast_rays(path, da.from_array(rays, chunks=(500, 6)), key="t_hit")
    normals = rd.cast_rays(path, da.from_array(rays, chunks=(500, 6)), key="primitive_normals")
    d = rd.compute_distance(path, da.from_array(points, chunks=(1000, 3)))
    assert t.dtype == np.float64 and normals.shape == (4000, 3)
    t, normals, d = client.compute([t, normals, d], sync=True)
    direct = raycast.Scene.load(path)
    ans = direct.cast_rays(rays)
    np.testing.assert_array_equal(t, ans["t_hit"])
    np.testing.assert_array_equal(normals, ans["primitive_normals"])
    np.testing.assert_array_equal(d, direct.compute_distance(points))
    builds = client.run(rd.builds_in_this_process)
    assert len(builds) == 2 and all(n <= 1 for n in builds.values()) and sum(builds.values()) >= 1


def test_pickled_raycasting_scene_gives_open3d_dtypes(client, rng):
    scene = raycast.RaycastingScene()
    scene.add_triangles(*cube_mesh())
    points = rng.uniform(-2, 2, (6, 7, 3))
    inside = rd.compute_occupancy(scene, da.from_array(points, chunks=(2, 7, 3)))
    sdf = rd.compute_signed_distance(scene, da.from_array(points, chunks=(3, 7, 3)))
    assert inside.shape == (6, 7) and sdf.dtype == np.float32
    inside, sdf = client.compute([inside, sdf], sync=True)
    np.testing.assert_array_equal(inside, scene.compute_occupancy(points))
    np.testing.assert_array_equal(sdf, scene.compute_signed_distance(points))


def test_bad_arguments_name_what_was_expected():
    rays = da.zeros((4, 6), chunks=2)
    with pytest.raises(TypeError, match="path"):
        rd.cast_rays(raycast.Scene(), rays)
    with pytest.raises(ValueError, match="key"):
        rd.query("scene.yaml", rays, "cast_rays")
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        rd.compute_distance("scene.yaml", rays)
    with pytest.raises(ValueError, match="method"):
        rd.query("scene.yaml", rays, "render")
