"""Clear errors: shapes and dtypes, missing files, scene errors with their position."""
import numpy as np
import pytest

import raycast


@pytest.fixture
def scene():
    s = raycast.Scene()
    s.add_sphere((0, 0, 0), 1)
    s.commit()
    return s


@pytest.mark.parametrize("rays", [np.zeros((4, 5)), np.zeros((4, 6), np.int32),
                                  np.zeros((4, 6), np.float16), np.zeros(()), [[0] * 6]])
def test_bad_rays_raise_value_error_naming_shape_and_dtype(scene, rays):
    with pytest.raises(ValueError, match=r"\(\.\.\., 6\) of float32 or float64"):
        scene.cast_rays(rays)
    with pytest.raises(ValueError, match=r"\(\.\.\., 6\)"):
        scene.test_occlusions(rays)


def test_bad_points_raise_value_error(scene):
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        scene.compute_distance(np.zeros((4, 2)))
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        scene.compute_occupancy(np.zeros((4, 3), np.int64))


def test_bad_mesh_arrays():
    s = raycast.Scene()
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        s.add_triangles(np.zeros((4, 2)), np.zeros((1, 3), np.int32))
    with pytest.raises(ValueError, match="integer"):
        s.add_triangles(np.zeros((4, 3)), np.zeros((1, 3)))
    with pytest.raises(ValueError, match="out of range"):
        s.add_triangles(np.zeros((4, 3)), np.array([[0, 1, -1]]))
    with pytest.raises(raycast.SceneError, match="add_mesh"):
        s.add_triangles(np.zeros((3, 3)), np.array([[0, 1, 7]]))


def test_missing_file_raises_file_not_found():
    with pytest.raises(FileNotFoundError):
        raycast.Scene.load("/nonexistent/scene.yaml")
    with pytest.raises(FileNotFoundError):
        raycast.Scene().add_mesh_file("/nonexistent/mesh.ply")


def test_scene_error_carries_position():
    text = "objects:\n  - sphere: {radius: 1}\n  - box: {min: [0, 0, 0], max: [1, 1]}\n"
    with pytest.raises(raycast.SceneError) as e:
        raycast.Scene.from_yaml(text, "mine.yaml")
    assert (e.value.file, e.value.line) == ("mine.yaml", 3)
    assert e.value.column > 0
    assert str(e.value).startswith("mine.yaml:3:")
    assert isinstance(e.value, ValueError)


def test_bad_shape_parameters_name_the_call():
    s = raycast.Scene()
    with pytest.raises(raycast.SceneError, match="radius must be > 0"):
        s.add_sphere((0, 0, 0), -1)
    with pytest.raises(raycast.SceneError, match="unknown shape"):
        s.add_shape("blobby", {})
    with pytest.raises(ValueError, match="3 numbers"):
        s.add_sphere((0, 0), 1)
    with pytest.raises(raycast.SceneError, match="not a closed solid|open surface"):
        d = s.add_disk((0, 0, 0), (0, 0, 1), 1)
        b = s.add_box((0, 0, 0), (1, 1, 1))
        s.add_csg("union", [d, b])


def test_query_commits_and_build_after_raises(scene):
    s = raycast.Scene()
    s.add_sphere()
    assert not s.committed
    assert s.cast_rays(np.array([[0, 0, -5, 0, 0, 1.0]]))["t_hit"][0] == 4.0
    assert s.committed
    s.commit()  # idempotent
    with pytest.raises(RuntimeError, match="committed"):
        scene.add_sphere()


def test_distance_to_shape_without_closed_form_names_it():
    s = raycast.Scene()
    s.add_implicit("x^2 + y^2 + z^2 - 1", (-2, -2, -2), (2, 2, 2))
    s.commit()
    with pytest.raises(NotImplementedError, match="implicit"):
        s.compute_distance(np.zeros((1, 3)))
    with pytest.raises(NotImplementedError, match="implicit"):
        s.compute_signed_distance(np.zeros((1, 3)))
    assert s.compute_occupancy(np.zeros((1, 3)))[0] == 1
