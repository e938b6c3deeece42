"""Ray queries against the CLI's answers and against brute force."""
import os
import threading

import numpy as np
import pytest

import raycast
from conftest import SOURCE_DIR, cli_cast, cube_mesh, icosphere, random_rays

SCENES = ["sphere.yaml", "box.yaml", "torus.yaml", "csg.yaml", "quadrics.yaml", "triangle.yaml"]


def brute_force(vertices, triangles, rays):
    """Nearest t and triangle per ray by Moller-Trumbore over every triangle, in float64."""
    o, d = rays[:, None, :3], rays[:, None, 3:]
    a, b, c = (vertices[triangles[:, k]][None] for k in range(3))
    e1, e2 = b - a, c - a
    p = np.cross(d, e2)
    det = np.sum(e1 * p, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        s = o - a
        u = np.sum(s * p, axis=-1) * inv
        q = np.cross(s, e1)
        v = np.sum(d * q, axis=-1) * inv
        t = np.sum(e2 * q, axis=-1) * inv
    ok = (u >= 0) & (v >= 0) & (u + v <= 1) & (t >= 0) & (det != 0)
    t = np.where(ok, t, np.inf)
    return t.min(axis=1), t.argmin(axis=1)


@pytest.mark.parametrize("name", SCENES)
def test_cast_rays_equals_cli(name, rng):
    path = os.path.join(SOURCE_DIR, "scenes", name)
    scene = raycast.Scene.load(path)
    rays = random_rays(rng, 200, spread=8, target=2)
    ans = scene.cast_rays(rays)
    cli = np.array(cli_cast(path, rays))
    np.testing.assert_array_equal(ans["t_hit"], cli[:, 0])
    hit = np.isfinite(cli[:, 0])
    np.testing.assert_array_equal(ans["points"][hit], cli[hit, 1:4])
    np.testing.assert_array_equal(ans["primitive_normals"][hit], cli[hit, 4:7])
    np.testing.assert_array_equal(ans["primitive_uvs"][hit], cli[hit, 7:9])
    ids = np.where(hit, cli[:, 9], raycast.INVALID_ID).astype(np.uint32)
    np.testing.assert_array_equal(ans["geometry_ids"], ids)


@pytest.mark.parametrize("name", SCENES)
def test_occlusions_and_all_hits_equal_cli(name, rng):
    path = os.path.join(SOURCE_DIR, "scenes", name)
    scene = raycast.Scene.load(path)
    rays = random_rays(rng, 100, spread=8, target=2)
    any_cli = np.array(cli_cast(path, rays, "--any"))[:, 0]
    np.testing.assert_array_equal(scene.test_occlusions(rays), any_cli == 1)
    all_cli = cli_cast(path, rays, "--all")
    counts = scene.count_intersections(rays)
    np.testing.assert_array_equal(counts, [int(line[0]) for line in all_cli])
    lists = scene.list_intersections(rays)
    np.testing.assert_array_equal(np.diff(lists["ray_splits"]), counts)
    for i, line in enumerate(all_cli):
        lo, hi = lists["ray_splits"][i], lists["ray_splits"][i + 1]
        expect = np.array(line[1:]).reshape(-1, 5)
        np.testing.assert_array_equal(lists["t_hit"][lo:hi], expect[:, 0])
        np.testing.assert_array_equal(lists["primitive_normals"][lo:hi], expect[:, 1:4])
        np.testing.assert_array_equal(lists["geometry_ids"][lo:hi], expect[:, 4])
        np.testing.assert_array_equal(lists["ray_ids"][lo:hi], i)


def test_cast_rays_mesh_equals_brute_force(rng):
    v, f = icosphere(2)
    scene = raycast.Scene()
    gid = scene.add_triangles(v, f)
    scene.commit()
    rays = random_rays(rng, 500, spread=3, target=1.2)
    ans = scene.cast_rays(rays)
    t, prim = brute_force(v.astype(np.float32).astype(np.float64), f, rays)
    hit = np.isfinite(t)
    # Rays grazing an edge may pick either triangle: compare t to its float rounding.
    np.testing.assert_array_equal(np.isfinite(ans["t_hit"]), hit)
    np.testing.assert_allclose(ans["t_hit"][hit], t[hit], rtol=1e-6)
    assert np.mean(ans["primitive_ids"][hit] == prim[hit]) > 0.99
    assert np.all(ans["geometry_ids"][hit] == gid)


def test_float32_and_float64_rays_agree(rng):
    v, f = cube_mesh()
    scene = raycast.Scene()
    scene.add_triangles(v, f)
    scene.commit()
    rays = random_rays(rng, 300).astype(np.float32)
    a = scene.cast_rays(rays)
    b = scene.cast_rays(rays.astype(np.float64))
    np.testing.assert_array_equal(a["t_hit"], b["t_hit"])


def test_any_leading_shape_and_strides(rng):
    scene = raycast.Scene()
    scene.add_sphere((0, 0, 0), 1)
    scene.commit()
    rays = random_rays(rng, 24)
    flat = scene.cast_rays(rays)["t_hit"]
    grid = scene.cast_rays(rays.reshape(2, 3, 4, 6))["t_hit"]
    assert grid.shape == (2, 3, 4)
    np.testing.assert_array_equal(grid.reshape(-1), flat)
    wide = np.zeros((24, 12))
    wide[:, ::2] = rays  # non-contiguous components
    np.testing.assert_array_equal(scene.cast_rays(wide[:, ::2])["t_hit"], flat)
    fortran = np.asfortranarray(rays)
    np.testing.assert_array_equal(scene.cast_rays(fortran)["t_hit"], flat)
    swapped = rays.reshape(4, 6, 6).transpose(1, 0, 2)  # leading axes that do not collapse
    np.testing.assert_array_equal(scene.cast_rays(swapped)["t_hit"],
                                  flat.reshape(4, 6).T)
    one = scene.cast_rays(rays[0])["t_hit"]
    assert one.shape == () and one == flat[0]


def test_occlusion_interval(rng):
    scene = raycast.Scene()
    scene.add_sphere((0, 0, 0), 1)
    scene.commit()
    ray = np.array([[0, 0, -5, 0, 0, 1]], np.float64)
    assert scene.test_occlusions(ray, tnear=0, tfar=4)[0]  # closed interval: t = 4 counts
    assert not scene.test_occlusions(ray, tnear=0, tfar=3.999)[0]
    assert scene.test_occlusions(ray, tnear=5, tfar=6)[0]
    assert not scene.test_occlusions(ray, tnear=6.5, tfar=np.inf)[0]


def test_bad_rays_answer_nothing():
    scene = raycast.Scene()
    scene.add_sphere((0, 0, 0), 1)
    scene.commit()
    rays = np.array([[0, 0, -5, 0, 0, 0], [np.nan, 0, -5, 0, 0, 1], [0, 0, -5, np.inf, 0, 1]])
    ans = scene.cast_rays(rays)
    assert np.all(np.isinf(ans["t_hit"]))
    assert np.all(ans["geometry_ids"] == raycast.INVALID_ID)
    assert not scene.test_occlusions(rays).any()
    assert not scene.count_intersections(rays).any()


def test_many_threads_on_one_scene(rng):
    v, f = icosphere(3)
    scene = raycast.Scene()
    scene.add_triangles(v, f)
    scene.add_torus(2.0, 0.3)
    scene.commit()
    rays = random_rays(rng, 2000, spread=5, target=2)
    expect = scene.cast_rays(rays)["t_hit"]
    expect_d = scene.compute_distance(rays[:, :3])
    results = [None] * 8

    def work(k):
        results[k] = (scene.cast_rays(rays)["t_hit"], scene.compute_distance(rays[:, :3]))

    threads = [threading.Thread(target=work, args=(k,)) for k in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for t_hit, dist in results:
        np.testing.assert_array_equal(t_hit, expect)
        np.testing.assert_array_equal(dist, expect_d)


def test_pinhole_rays_hit_depth():
    scene = raycast.Scene()
    scene.add_plane((0, 0, 1), (0, 0, 0))
    scene.commit()
    rays = raycast.create_rays_pinhole(90, [0, 0, 0], [0, 0, -3], [0, 1, 0], 8, 6)
    assert rays.shape == (6, 8, 6) and rays.dtype == np.float32
    t = scene.cast_rays(rays)["t_hit"]
    np.testing.assert_allclose(t, 3.0, rtol=1e-6)  # directions have unit depth


def test_render_matches_integrator_shapes():
    scene = raycast.Scene()
    s = scene.add_sphere((0, 0, 0), 1)
    red = scene.add_material(color=(1, 0, 0))
    scene.set_material(s, red)
    scene.add_point_light((0, 0, -5))
    scene.set_camera(position=(0, 0, -5), look_at=(0, 0, 0), fov=40)
    scene.commit()
    img = scene.render(width=40, height=30)
    assert img.shape == (30, 40, 3) and img.dtype == np.float32
    assert img[15, 20, 0] > 0.5 and img[15, 20, 1] == 0  # red in the middle
    assert np.all(img[0, 0] == 0)  # black background
    depth = scene.render(width=40, height=30, integrator="depth",
                         camera=dict(position=(0, 0, -4), look_at=(0, 0, 0)))
    assert depth.shape == (30, 40, 3)
