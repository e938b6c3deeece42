// The extension module `raycast._raycast`: raycast::Scene for numpy (docs/python.md). The
// package `raycast` (python/raycast/) re-exports it and adds the pure-Python layers
// (RaycastingScene, answer arrays, images, Dask). Every batch releases the GIL.
#include "bindings.h"

namespace raycast::python {

PYBIND11_MODULE(_raycast, m) {
  m.doc() =
      "raycast: exact ray casting, distances and rendering over meshes, analytic shapes "
      "and CSG (docs/python.md)";
  m.attr("__version__") = RAYCAST_VERSION_STRING;
  m.attr("INVALID_ID") = kInvalidId;
  bind_errors(m);
  bind_rays(m);

  py::class_<Scene> scene(m, "Scene",
                          "A scene: build (add_*) or load, then query; the first query commits.");
  scene.def(py::init<>());
  bind_building(scene);
  bind_isosurface(scene);
  bind_appearance(scene);
  bind_queries(scene);
  bind_render(scene);
  bind_explain(scene);
}

}  // namespace raycast::python
