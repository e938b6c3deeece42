#pragma once
// The pieces of the extension module `raycast._raycast` (docs/python.md), one function per
// feature so that module.cpp reads as the list of what the module offers.
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arrays.h"

namespace raycast::python {

/// Open3D's "no geometry / no primitive" id (RaycastingScene.INVALID_ID).
inline constexpr std::uint32_t kInvalidId = 0xFFFFFFFFu;

/// Three numbers (a list, tuple or array of 3); ValueError "<what> must be 3 numbers" otherwise.
Vec3d vec3(const py::handle& h, const char* what);
/// A 4x4 object-to-world matrix; ValueError naming `what` otherwise.
Transform matrix4(const py::handle& h, const char* what);
/// FileNotFoundError naming the path when it does not exist.
void require_file(const std::string& path);
/// Commits the scene unless it is already committed: a query commits, and commit() may be
/// called any number of times. The build runs without the GIL, one scene build at a time.
void ensure_committed(Scene& scene);

/// raycast.SceneError and the translation of the engine's exceptions to Python's.
void bind_errors(py::module_& m);
/// Module-level helpers: create_rays_pinhole and the benchmark's timing hook.
void bind_rays(py::module_& m);
/// Scene.load, Scene.from_yaml and the add_* calls for meshes, files and shapes.
void bind_building(py::class_<Scene>& scene);
/// add_isosurface (particles or a grid).
void bind_isosurface(py::class_<Scene>& scene);
/// Materials, lights, camera and transforms.
void bind_appearance(py::class_<Scene>& scene);
/// commit, the read-only properties and the batch queries (rays and points).
void bind_queries(py::class_<Scene>& scene);
/// Scene.render into a raycast.Image.
void bind_render(py::class_<Scene>& scene);
/// Scene.explain: a pixel's ray tree as a dict (explain_binding.cpp).
void bind_explain(py::class_<Scene>& scene);

}  // namespace raycast::python
