"""Open3D's pinhole camera rays (RaycastingScene.create_rays_pinhole): pixel (x, y) looks
through its centre (x + 0.5, y + 0.5); the ray starts at the camera centre C = -R^T t and has
direction R^T K^-1 (x + 0.5, y + 0.5, 1), so its depth along the optical axis is 1 per unit t."""
import numpy as np

from .inputs import as_numpy


def _size(name, value):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value <= 0:
        raise ValueError(f"{name} must be a positive integer, got {value!r}")
    return int(value)


def _matrix(value, name, shape):
    m = np.asarray(as_numpy(value, name, f"shaped {shape}"), np.float64)
    if m.shape != shape or not np.all(np.isfinite(m)):
        raise ValueError(f"{name} must be a finite matrix shaped {shape}, got shape {m.shape}")
    return m


def _vector(value, name):
    return _matrix(value, name, (3,))


def pinhole_rays_intrinsic(intrinsic_matrix, extrinsic_matrix, width_px, height_px):
    """Rays (height, width, 6) float32 for intrinsics K (3x3) and a world-to-camera extrinsic
    matrix [R t; 0 1] (4x4)."""
    k = _matrix(intrinsic_matrix, "intrinsic_matrix", (3, 3))
    e = _matrix(extrinsic_matrix, "extrinsic_matrix", (4, 4))
    width, height = _size("width_px", width_px), _size("height_px", height_px)
    if abs(np.linalg.det(k)) == 0:
        raise ValueError("intrinsic_matrix must be invertible")
    rotation_t, translation = e[:3, :3].T, e[:3, 3]
    x, y = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    pixels = np.stack([x, y, np.ones_like(x)], -1)
    directions = pixels @ (rotation_t @ np.linalg.inv(k)).T
    rays = np.empty((height, width, 6), np.float32)
    rays[..., :3] = -rotation_t @ translation
    rays[..., 3:] = directions
    return rays


def pinhole_rays_fov(fov_deg, center, eye, up, width_px, height_px):
    """Rays (height, width, 6) float32 of a camera at `eye` looking at `center` with `up`
    defining Open3D's camera y axis; fov_deg is the horizontal field of view in degrees."""
    if not 0 < float(fov_deg) < 180:
        raise ValueError(f"fov_deg must be in (0, 180), got {fov_deg!r}")
    width, height = _size("width_px", width_px), _size("height_px", height_px)
    c, o, u = _vector(center, "center"), _vector(eye, "eye"), _vector(up, "up")
    focal = 0.5 * width / np.tan(0.5 * np.radians(float(fov_deg)))
    k = np.array([[focal, 0, 0.5 * width], [0, focal, 0.5 * height], [0, 0, 1]])
    # Rows of R: x = y' x z, y = z x x, z = the unit viewing direction, y' = the unit up.
    with np.errstate(divide="ignore", invalid="ignore"):
        z = (c - o) / np.linalg.norm(c - o)
        x = np.cross(u / np.linalg.norm(u), z)
        x /= np.linalg.norm(x)
    if not (np.all(np.isfinite(z)) and np.all(np.isfinite(x))):
        raise ValueError("create_rays_pinhole: eye, center and up must span a camera frame "
                         "(eye != center, up not along the view)")
    rotation = np.stack([x, np.cross(z, x), z])
    extrinsic = np.eye(4)
    extrinsic[:3, :3] = rotation
    extrinsic[:3, 3] = -rotation @ o
    return pinhole_rays_intrinsic(k, extrinsic, width, height)
