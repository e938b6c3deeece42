"""Scenes built in code answer as the same scene loaded from YAML."""
import numpy as np

import raycast
from conftest import random_rays

YAML = """
objects:
  - sphere: {center: [0, 0, 0], radius: 1}
  - box: {min: [2, -1, -1], max: [3, 1, 1]}
  - cylinder: {from: [-3, 0, -1], to: [-3, 0, 1], radius: 0.5}
  - cone: {from: [0, 3, 0], to: [0, 4, 0], radius_from: 0.5, radius_to: 0}
  - torus: {major_radius: 2, minor_radius: 0.25}
  - ellipsoid: {center: [0, -3, 0], radii: [1, 0.5, 0.25]}
  - difference:
      - box: {min: [-1, -1, 4], max: [1, 1, 6]}
      - sphere: {center: [0, 0, 5], radius: 1.2}
  - implicit: {function: "x^2 + y^2 + (z + 5)^2 - 1", bounds: {min: [-2, -2, -7], max: [2, 2, -3]}}
"""


def test_code_built_scene_equals_yaml(rng):
    a = raycast.Scene.from_yaml(YAML)
    b = raycast.Scene()
    b.add_sphere((0, 0, 0), 1)
    b.add_box((2, -1, -1), (3, 1, 1))
    b.add_cylinder((-3, 0, -1), (-3, 0, 1), 0.5)
    b.add_cone((0, 3, 0), (0, 4, 0), 0.5, 0)
    b.add_torus(2, 0.25)
    b.add_ellipsoid((0, -3, 0), (1, 0.5, 0.25))
    box = b.add_box((-1, -1, 4), (1, 1, 6))
    ball = b.add_sphere((0, 0, 5), 1.2)
    csg = b.add_csg("difference", [box, ball])
    b.add_implicit("x^2 + y^2 + (z + 5)^2 - 1", (-2, -2, -7), (2, 2, -3))
    b.commit()
    rays = random_rays(rng, 2000, spread=10, target=5)
    ra, rb = a.cast_rays(rays), b.cast_rays(rays)
    np.testing.assert_array_equal(ra["t_hit"], rb["t_hit"])
    np.testing.assert_array_equal(ra["primitive_normals"], rb["primitive_normals"])
    # Ids count add_* calls, so the CSG operands' ids are skipped.
    remap = {0: 0, 1: 1, 2: 2, 3: 3, 4: 4, 5: 5, 6: csg, 7: csg + 1}
    expect = np.array([remap.get(int(g), g) for g in ra["geometry_ids"]], np.uint32)
    expect[ra["geometry_ids"] == raycast.INVALID_ID] = raycast.INVALID_ID
    np.testing.assert_array_equal(rb["geometry_ids"], expect)
    np.testing.assert_array_equal(a.count_intersections(rays), b.count_intersections(rays))
    assert b.shape_name(csg) == "csg"


def test_instances_and_add_shape(rng):
    s = raycast.Scene()
    part = s.add_shape("revolution", {"profile": [[0, 0], [1, 0], [1, 1], [0, 1]]})
    proto = s.add_prototype([part])
    for k in range(3):
        m = np.eye(4)
        m[0, 3] = 3 * k
        s.add_instance(proto, m)
    s.commit()
    rays = np.array([[3 * k, 0, -5, 0, 0, 1] for k in range(3)], float)
    t = s.cast_rays(rays)["t_hit"]
    assert np.all(np.isfinite(t))
    np.testing.assert_array_equal(t, t[0])
