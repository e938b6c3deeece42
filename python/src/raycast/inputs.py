"""Array and mesh inputs from any library, without importing it: numpy arrays, objects with
`.numpy()` (Open3D and PyTorch CPU tensors), `__dlpack__`, `__array__` or the buffer protocol,
and meshes in Open3D's tensor and legacy forms or anything with vertices and faces."""
import numpy as np


def as_numpy(value, what, expected, real=False):
    """`value` as a numpy array, a view where the source allows. Raises TypeError naming `what`
    and the `expected` shape and dtype for anything that is not array-like. With `real`, a
    Python list or tuple of integers becomes float64 (as written coordinates are meant)."""
    if isinstance(value, np.ndarray):
        return value
    numpy_method = getattr(value, "numpy", None)
    if callable(numpy_method):
        array = numpy_method()
        if isinstance(array, np.ndarray):
            return array
    if hasattr(value, "__dlpack__"):
        return np.from_dlpack(value)
    if isinstance(value, (str, bytes, dict)) or value is None:
        raise TypeError(f"{what} must be an array {expected}, got {type(value).__name__}")
    try:
        array = np.asarray(value)
    except (TypeError, ValueError) as error:
        raise TypeError(f"{what} must be an array {expected}, got {type(value).__name__}: "
                        f"{error}") from None
    if array.dtype == object:
        raise TypeError(f"{what} must be an array {expected}, got {type(value).__name__} that "
                        "numpy reads as objects")
    if real and isinstance(value, (list, tuple)) and array.dtype.kind in "iub":
        array = array.astype(np.float64)
    return array


RAYS = "shaped (..., 6) of float32 or float64 ([ox, oy, oz, dx, dy, dz] per ray)"
POINTS = "shaped (..., 3) of float32 or float64 ([x, y, z] per point)"
VERTICES = "shaped (n, 3) of float32 or float64"
TRIANGLES = "shaped (m, 3) of integer vertex indices"


def rays_array(value):
    """Rays as a numpy array; the engine checks their shape and dtype."""
    return as_numpy(value, "rays", RAYS, real=True)


def points_array(value):
    """Query points as a numpy array; the engine checks their shape and dtype."""
    return as_numpy(value, "query_points", POINTS, real=True)


def _attribute(owner, *names):
    """The first of owner's attributes (or mapping keys) named in `names`, else None."""
    for name in names:
        try:
            return getattr(owner, name)
        except (AttributeError, KeyError):
            pass
        try:
            return owner[name]
        except (TypeError, KeyError, IndexError, AttributeError, RuntimeError):
            pass
    return None


def mesh_arrays(mesh):
    """(vertices, triangles) of a mesh object: Open3D's t.geometry.TriangleMesh
    (`vertex.positions`, `triangle.indices`), its legacy geometry.TriangleMesh (`vertices`,
    `triangles`), or any object with `vertices` and `faces` (trimesh). TypeError otherwise."""
    vertex, triangle = getattr(mesh, "vertex", None), getattr(mesh, "triangle", None)
    if vertex is not None and triangle is not None:
        vertices = _attribute(vertex, "positions")
        triangles = _attribute(triangle, "indices")
    else:
        vertices = getattr(mesh, "vertices", None)
        triangles = getattr(mesh, "triangles", None)
        if triangles is None:
            triangles = getattr(mesh, "faces", None)
    if vertices is None or triangles is None:
        raise TypeError("add_triangles(mesh) expects a triangle mesh with vertex positions and "
                        "triangle indices (open3d.t.geometry.TriangleMesh, "
                        "open3d.geometry.TriangleMesh or an object with vertices and faces), "
                        f"got {type(mesh).__name__}")
    return (as_numpy(vertices, "mesh vertices", VERTICES, real=True),
            as_numpy(triangles, "mesh triangles", TRIANGLES))
