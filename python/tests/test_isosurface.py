"""Iso-surfaces built from numpy arrays (Scene.add_isosurface) answer as the CLI does on the same
data read from files (docs/iso-surfaces.md, docs/python.md)."""
import json
import os

import numpy as np
import pytest

import raycast
from conftest import SOURCE_DIR, cli_cast, random_rays

DATA = os.path.join(SOURCE_DIR, "tests", "volume", "data")


def raw_grid(name):
    """A raw float32 grid of tests/volume/data as an array indexed [i, j, k], its origin and
    spacing (from the JSON sidecar)."""
    with open(os.path.join(DATA, name + ".json")) as f:
        meta = json.load(f)
    n = meta["dims"]
    values = np.fromfile(os.path.join(DATA, name + ".raw"), np.float32)
    grid = values.reshape(n[2], n[1], n[0]).transpose(2, 1, 0)  # file: x fastest
    lo, hi = np.array(meta["min"]), np.array(meta["max"])
    return grid, lo, (hi - lo) / (np.array(n) - 1)


def write_scene(tmp_path, shape_yaml):
    path = tmp_path / "scene.yaml"
    path.write_text("objects:\n  - isosurface: " + shape_yaml + "\n")
    return str(path)


def assert_same_answers(scene, path, rays):
    ans = scene.cast_rays(rays)
    cli = np.array(cli_cast(path, rays))
    np.testing.assert_array_equal(ans["t_hit"], cli[:, 0])
    hit = np.isfinite(cli[:, 0])
    assert hit.sum() > len(rays) // 8  # the rays do meet the surface
    np.testing.assert_array_equal(ans["primitive_normals"][hit], cli[hit, 4:7])
    counts = scene.count_intersections(rays)
    np.testing.assert_array_equal(counts, [int(line[0]) for line in cli_cast(path, rays, "--all")])


@pytest.mark.parametrize("name,iso", [("sphere_sdf", 0.0), ("gaussians", 0.5)])
def test_grid_equals_cli_on_the_file(name, iso, tmp_path, rng):
    grid, origin, spacing = raw_grid(name)
    scene = raycast.Scene()
    assert scene.add_isosurface(grid=grid, iso=iso, origin=origin, spacing=spacing) == 0
    scene.commit()
    path = write_scene(tmp_path, f"{{grid: {os.path.join(DATA, name + '.raw')}, iso: {iso}}}")
    assert_same_answers(scene, path, random_rays(rng, 300, spread=4, target=1.2))
    # Any memory layout and dtype of the same values gives the same surface.
    again = raycast.Scene()
    again.add_isosurface(grid=np.ascontiguousarray(grid, np.float64), iso=iso, origin=origin,
                         spacing=spacing)
    again.commit()
    rays = random_rays(rng, 200, spread=4, target=1.2)
    np.testing.assert_array_equal(again.cast_rays(rays)["t_hit"], scene.cast_rays(rays)["t_hit"])


def test_grid_reference_roots():
    """The committed high-precision roots of the trilinear interpolant (tests/volume/data)."""
    grid, origin, spacing = raw_grid("sphere_sdf")
    scene = raycast.Scene()
    scene.add_isosurface(grid=grid, iso=0.0, origin=origin, spacing=spacing)
    scene.commit()
    rows = [line.split() for line in open(os.path.join(DATA, "sphere_sdf_rays.txt"))
            if line.strip() and not line.startswith(("#", "iso"))]
    ref = np.array(rows, np.float64)
    t = scene.cast_rays(ref[:, :6])["t_hit"]
    np.testing.assert_array_equal(np.isinf(t), np.isinf(ref[:, 6]))
    fin = np.isfinite(ref[:, 6])
    np.testing.assert_allclose(t[fin], ref[fin, 6], rtol=1e-6)


def test_particles_equal_cli_on_the_file(tmp_path, rng):
    particles = rng.normal(scale=0.15, size=(400, 3))
    particles[:200, 0] += 0.4  # two blobs
    xyz = tmp_path / "drops.xyz"
    xyz.write_text("".join(f"{p[0]!r} {p[1]!r} {p[2]!r}\n" for p in particles))
    scene = raycast.Scene()
    scene.add_isosurface(particles, smoothing_length=0.08, iso=200.0)
    scene.commit()
    path = write_scene(tmp_path, f"{{particles: {xyz}, smoothing_length: 0.08, iso: 200}}")
    assert_same_answers(scene, path, random_rays(rng, 300, spread=2, target=0.3))


def test_occupancy_agrees_with_cli_spans(tmp_path, rng):
    grid, origin, spacing = raw_grid("gaussians")
    scene = raycast.Scene()
    scene.add_isosurface(grid=grid, iso=0.5, origin=origin, spacing=spacing)
    scene.commit()
    path = write_scene(tmp_path, f"{{grid: {os.path.join(DATA, 'gaussians.raw')}, iso: 0.5}}")
    rays = random_rays(rng, 400, spread=4, target=0.8)
    inside, outside = [], []
    for ray, line in zip(rays, cli_cast(path, rays, "--all")):
        ts = np.array(line[1:]).reshape(-1, 5)[:, 0]
        if len(ts):  # before the first crossing and after the last
            outside += [ray[:3] + 0.5 * ts[0] * ray[3:], ray[:3] + (ts[-1] + 0.1) * ray[3:]]
        for k in range(len(ts) - 1):  # crossings alternate: in, out, in, ...
            if ts[k + 1] - ts[k] > 1e-6:
                (inside if k % 2 == 0 else outside).append(ray[:3] + 0.5 * (ts[k] + ts[k + 1]) *
                                                           ray[3:])
    assert len(inside) > 50 and len(outside) > 50, (len(inside), len(outside))
    np.testing.assert_array_equal(scene.compute_occupancy(np.array(inside)), 1)
    np.testing.assert_array_equal(scene.compute_occupancy(np.array(outside)), 0)


def test_occupancy_of_one_particle_matches_the_kernel_radius():
    """One particle: rho(r) = V rho0 W(r, h), so the solid is the ball where W > iso / (V rho0)."""
    h, rho0 = 0.1, 1000.0
    volume = (h / 1.3) ** 3
    scene = raycast.Scene()
    scene.add_isosurface(np.zeros((1, 3)), smoothing_length=h, cell_size=h / 64, iso=0.25 * rho0 *
                         volume / (np.pi * h ** 3))  # W = 0.25 / (pi h^3): f(q) = 0.25, q = 1
    scene.commit()
    r = np.linspace(0.5 * h, 1.5 * h, 41)
    pts = np.stack([r, 0 * r, 0 * r], 1)
    occ = scene.compute_occupancy(pts)
    np.testing.assert_array_equal(occ[r < 0.97 * h], 1)
    np.testing.assert_array_equal(occ[r > 1.03 * h], 0)


def test_iso_surface_errors():
    s = raycast.Scene()
    with pytest.raises(ValueError, match="exactly one of particles"):
        s.add_isosurface()
    with pytest.raises(ValueError, match="exactly one of particles"):
        s.add_isosurface(np.zeros((1, 3)), grid=np.zeros((2, 2, 2)), iso=0)
    with pytest.raises(ValueError, match=r"shaped \(n, 3\)"):
        s.add_isosurface(np.zeros((4, 2)), smoothing_length=0.1)
    with pytest.raises(ValueError, match="smoothing_length="):
        s.add_isosurface(np.zeros((4, 3)))
    with pytest.raises(ValueError, match="3D numpy array"):
        s.add_isosurface(grid=np.zeros((4, 4)), iso=0)
    with pytest.raises(ValueError, match="iso="):
        s.add_isosurface(grid=np.zeros((4, 4, 4)))
    with pytest.raises(ValueError, match="particles only"):
        s.add_isosurface(grid=np.zeros((4, 4, 4)), iso=0, smoothing_length=1)
    with pytest.raises(raycast.SceneError, match="at least 2 nodes"):
        s.add_isosurface(grid=np.zeros((1, 4, 4)), iso=0)
    with pytest.raises(raycast.SceneError, match="spacing"):
        s.add_isosurface(grid=np.zeros((2, 2, 2)), iso=0, spacing=(1, 0, 1))
    with pytest.raises(raycast.SceneError, match="iso"):
        s.add_isosurface(grid=np.zeros((2, 2, 2)), iso=-1)
    with pytest.raises(raycast.SceneError, match="needs .* bytes"):  # refused before allocating
        s.add_isosurface(np.zeros((1, 3)), smoothing_length=1, resolution=[2000000, 2000000, 2])
    s.add_isosurface(grid=np.ones((2, 2, 2)), iso=0.5)
    s.commit()
    with pytest.raises(NotImplementedError, match="isosurface"):
        s.compute_distance(np.zeros((1, 3)))
