"""Occupancy by span parity and distances against closed forms and brute force."""
import numpy as np
import pytest

import raycast
from conftest import cube_mesh, icosphere


def mesh_scene(v, f):
    s = raycast.Scene()
    s.add_triangles(v, f)
    s.commit()
    return s


def test_occupancy_of_cube_mesh_on_vertices_edges_faces():
    s = mesh_scene(*cube_mesh())
    grid = np.array([[x, y, z] for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1)], float)
    # Every point of the 3x3x3 grid is a vertex, an edge midpoint, a face centre or the centre.
    assert np.all(s.compute_occupancy(grid) == 1)
    # Within the mesh's float event resolution (16 float ulps of the coordinates) a point counts
    # as on the surface; beyond it parity decides.
    outside = grid * (1 + 32 * np.finfo(np.float32).eps)
    outside = outside[np.any(grid != 0, axis=1)]
    assert np.all(s.compute_occupancy(outside) == 0)
    for scale in (0.9999999, 1 - 32 * np.finfo(np.float32).eps, 0.999):
        assert np.all(s.compute_occupancy(grid * scale) == 1)


def test_occupancy_equals_inside_oracle(rng):
    v, f = icosphere(3)
    s = mesh_scene(v, f)
    p = rng.uniform(-1.2, 1.2, size=(3000, 3))
    r = np.linalg.norm(p, axis=1)
    occ = s.compute_occupancy(p)
    # The polyhedron lies between the inscribed radius and the unit sphere.
    inner = np.cos(np.pi / 10) ** 2  # a safe lower bound of the inscribed radius at 3 subdivisions
    assert np.all(occ[r < inner * 0.9] == 1)
    assert np.all(occ[r > 1.0] == 0)


def test_occupancy_of_csg_and_analytic():
    s = raycast.Scene()
    box = s.add_box((-1, -1, -1), (1, 1, 1))
    ball = s.add_sphere((0, 0, 0), 1.2)
    s.add_csg("difference", [box, ball])
    s.add_torus(5, 1)
    s.commit()
    pts = np.array([[0, 0, 0], [0.95, 0.95, 0.95], [5, 0, 0], [0, 5, 0.5], [0, 0, 5], [1.5, 0, 0]])
    np.testing.assert_array_equal(s.compute_occupancy(pts), [0, 1, 1, 1, 0, 0])


def test_distances_to_closed_forms(rng):
    p = rng.uniform(-4, 4, size=(500, 3))
    cases = []
    s = raycast.Scene()
    s.add_sphere((0.5, 0, 0), 1.5)
    s.commit()
    c = np.array([0.5, 0, 0])
    cases.append((s, np.abs(np.linalg.norm(p - c, axis=1) - 1.5)))
    s = raycast.Scene()
    s.add_plane((0, 0, 2), (0, 0, 1))
    s.commit()
    cases.append((s, np.abs(p[:, 2] - 1)))
    s = raycast.Scene()
    s.add_box((-1, -2, -3), (1, 2, 3))
    s.commit()
    hi = np.array([1, 2, 3])
    q = np.abs(p) - hi
    box_d = np.where(np.all(q <= 0, axis=1), -np.max(q, axis=1),
                     np.linalg.norm(np.maximum(q, 0), axis=1))
    cases.append((s, box_d))
    s = raycast.Scene()
    s.add_torus(2, 0.5)
    s.commit()
    rho = np.hypot(p[:, 0], p[:, 1])
    cases.append((s, np.abs(np.hypot(rho - 2, p[:, 2]) - 0.5)))
    s = raycast.Scene()
    s.add_cylinder((0, 0, -1), (0, 0, 1), 1.5)
    s.commit()
    dr, dz = rho - 1.5, np.abs(p[:, 2]) - 1
    cyl = np.where((dr <= 0) & (dz <= 0), np.minimum(-dr, -dz),
                   np.hypot(np.maximum(dr, 0), np.maximum(dz, 0)))
    cases.append((s, cyl))
    for scene, expect in cases:
        np.testing.assert_allclose(scene.compute_distance(p), expect, rtol=1e-12, atol=1e-12)


def test_ellipsoid_closest_points_satisfy_the_lagrange_condition(rng):
    radii = np.array([3.0, 1.0, 0.5])
    s = raycast.Scene()
    s.add_ellipsoid((0, 0, 0), radii)
    s.commit()
    p = rng.uniform(-4, 4, size=(400, 3))
    p[:50] *= 0.1  # deep inside, where the nearest point is hardest
    ans = s.compute_closest_points(p)
    q = ans["points"]
    np.testing.assert_allclose(np.sum((q / radii) ** 2, axis=1), 1, atol=1e-12)
    n = q / radii ** 2  # the normal direction at q
    resid = np.linalg.norm(np.cross(p - q, n), axis=1) / np.linalg.norm(n, axis=1)
    assert np.all(resid <= 1e-9 * (1 + np.linalg.norm(p - q, axis=1)))
    # No surface sample is nearer than the answer.
    th, ph = rng.uniform(0, np.pi, 4000), rng.uniform(0, 2 * np.pi, 4000)
    samples = radii * np.stack([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)], 1)
    brute = np.min(np.linalg.norm(p[:, None] - samples[None], axis=2), axis=1)
    assert np.all(ans["distances"] <= brute + 1e-12)


def point_triangle_distances(p, a, b, c):
    """Exact distances (points x triangles): to the plane when the projection falls inside the
    triangle, else to the nearest of the three edges."""
    p = p[:, None]
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    height = np.sum((p - a) * n, axis=2)
    q = p - height[..., None] * n
    inside = np.ones(height.shape, bool)
    for u, v in ((a, b), (b, c), (c, a)):
        inside &= np.sum(np.cross(v - u, q - u) * n, axis=2) >= 0
    best = np.where(inside, np.abs(height), np.inf)
    for u, v in ((a, b), (b, c), (c, a)):
        e = v - u
        t = np.clip(np.sum((p - u) * e, axis=2) / np.sum(e * e, axis=1), 0, 1)
        best = np.minimum(best, np.linalg.norm(p - (u + t[..., None] * e), axis=2))
    return best


def test_mesh_distance_equals_brute_force(rng):
    v, f = icosphere(2)
    s = mesh_scene(v, f)
    p = rng.uniform(-2, 2, size=(300, 3))
    ans = s.compute_closest_points(p)
    vf = v.astype(np.float32).astype(np.float64)
    brute = point_triangle_distances(p, vf[f[:, 0]], vf[f[:, 1]], vf[f[:, 2]])
    np.testing.assert_allclose(ans["distances"], brute.min(axis=1), rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(ans["points"] - p, axis=1), ans["distances"])
    assert np.all(ans["geometry_ids"] == 0)
    np.testing.assert_allclose(brute[np.arange(len(p)), ans["primitive_ids"]], ans["distances"],
                               rtol=1e-9, atol=1e-12)


def test_signed_distance_sign_is_occupancy(rng):
    v, f = icosphere(2)
    s = raycast.Scene()
    s.add_triangles(v, f)
    s.add_sphere((3, 0, 0), 0.5)
    s.commit()
    p = rng.uniform(-2, 4, size=(1000, 3))
    sd = s.compute_signed_distance(p)
    d = s.compute_distance(p)
    occ = s.compute_occupancy(p)
    np.testing.assert_array_equal(np.abs(sd), d)
    np.testing.assert_array_equal(sd < 0, (occ == 1) & (d > 0))


def test_transformed_sphere_distance():
    s = raycast.Scene()
    sid = s.add_sphere((0, 0, 0), 1)
    m = np.eye(4)
    m[:3, :3] *= 2
    m[:3, 3] = (5, 0, 0)
    s.set_transform(sid, m)
    s.commit()
    np.testing.assert_allclose(s.compute_distance(np.array([[5.0, 0, 0], [10.0, 0, 0]])), [2, 3])
    s2 = raycast.Scene()
    e = s2.add_sphere((0, 0, 0), 1)
    m = np.diag([1.0, 2.0, 1.0, 1.0])
    s2.set_transform(e, m)
    s2.commit()
    with pytest.raises(NotImplementedError, match="non-uniform"):
        s2.compute_distance(np.zeros((1, 3)))
