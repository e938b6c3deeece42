// Scene.set_camera and Scene.render: the renderer's image as a raycast.Image, an ndarray that
// notebooks display (python/raycast/image.py).
#include "bindings.h"

namespace raycast::python {

namespace {

Camera camera_from(const py::dict& d) {
  Camera c;
  for (const auto& [k, val] : d) {
    const std::string key = py::str(k);
    if (key == "position")
      c.position = vec3(val, "camera position");
    else if (key == "look_at")
      c.look_at = vec3(val, "camera look_at");
    else if (key == "up")
      c.up = vec3(val, "camera up");
    else if (key == "fov")
      c.fov = val.cast<double>();
    else if (key == "height")
      c.height = val.cast<double>();
    else if (key == "type")
      c.orthographic = val.cast<std::string>() == "orthographic";
    else
      throw py::value_error("unknown camera key '" + key +
                            "' (position, look_at, up, fov, height, type)");
  }
  return c;
}

}  // namespace

void bind_render(py::class_<Scene>& scene) {
  scene.def("set_camera", [](Scene& s, const py::kwargs& kw) { s.set_camera(camera_from(kw)); });
  scene.def(
      "render",
      [](Scene& s, int width, int height, int samples, const std::string& integrator,
         const py::object& camera) {
        ensure_committed(s);
        RenderOptions o;
        o.width = width;
        o.height = height;
        o.samples = samples;
        o.integrator = integrator;
        Camera c;
        const bool has_camera = !camera.is_none();
        if (has_camera) c = camera_from(camera.cast<py::dict>());
        Image img;
        {
          py::gil_scoped_release release;
          img = s.render(has_camera ? &c : nullptr, o);
        }
        py::array_t<float> out({static_cast<py::ssize_t>(img.height),
                                static_cast<py::ssize_t>(img.width), py::ssize_t{3}});
        std::copy(img.rgb.begin(), img.rgb.end(), out.mutable_data());
        return py::module_::import("raycast.image").attr("Image")(out);
      },
      py::arg("width") = 0, py::arg("height") = 0, py::arg("samples") = 0,
      py::arg("integrator") = "", py::arg("camera") = py::none(),
      "Renders into a raycast.Image: a (height, width, 3) float32 ndarray of linear RGB that "
      "notebooks display.");
}

}  // namespace raycast::python
