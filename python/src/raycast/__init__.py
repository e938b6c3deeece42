"""raycast: exact ray casting, distances and rendering over meshes, analytic shapes and CSG.

`raycast.Scene` is the engine's own API; `raycast.RaycastingScene` is Open3D's
`open3d.t.geometry.RaycastingScene` API over the same engine (docs/python.md).
"""
from ._raycast import INVALID_ID, Scene, SceneError, __version__, create_rays_pinhole
from .answers import Tensor
from .image import Image
from .open3d_scene import RaycastingScene

__all__ = ["INVALID_ID", "Image", "RaycastingScene", "Scene", "SceneError", "Tensor",
           "__version__", "create_rays_pinhole"]
