// Scene.explain(x, y): a pixel's ray tree as a dict (docs/explain.md), the same keys and values
// as `raycast explain --json`.
#include <string>

#include "bindings.h"

namespace raycast::python {

void bind_explain(py::class_<Scene>& scene) {
  scene.def(
      "explain",
      [](const Scene& s, int x, int y, int width, int height, int samples, int sample) {
        RenderOptions o;
        o.width = width;
        o.height = height;
        o.samples = samples;
        std::string text;
        {
          py::gil_scoped_release release;
          text = s.explain_json(x, y, o, sample);
        }
        return py::module_::import("json").attr("loads")(text);
      },
      py::arg("x"), py::arg("y"), py::arg("width") = 0, py::arg("height") = 0,
      py::arg("samples") = 0, py::arg("sample") = 0,
      "Pixel (x, y)'s ray tree (x from the left, y from the top) as a dict: pixel, color "
      "(linear RGB), ray (kind, origin, direction, depth, hit, children). width, height and "
      "samples override the scene's (0: the scene's); sample picks one of the pixel's samples.");
}

}  // namespace raycast::python
