// Scene.set_camera and Scene.render: the renderer's image as a raycast.Image, an ndarray that
// notebooks display (python/raycast/image.py).
#include <algorithm>

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

// Rows per band of a render with a progress bar: the renderer's tile height, or more so that a
// tall image takes at most about 64 bands (each band is one engine call).
int band_rows(int height) { return std::max(16, (height + 63) / 64); }

py::object render(Scene& s, int width, int height, int samples, const std::string& integrator,
                  const py::object& camera, const py::object& progress) {
  ensure_committed(s);
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.samples = samples;
  o.integrator = integrator;
  Camera c;
  const bool has_camera = !camera.is_none();
  if (has_camera) c = camera_from(camera.cast<py::dict>());
  const int w = width > 0 ? width : s.image_size()[0];
  const int h = height > 0 ? height : s.image_size()[1];
  const py::object bar =
      py::module_::import("raycast.progress").attr("render_progress")(progress, h);
  py::array_t<float> out;
  // Band by band when there is a bar (each band's pixels equal the whole render's); the first
  // band also checks the image size before the whole image is allocated.
  const int band = bar.is_none() ? std::max(h, 1) : band_rows(h);
  for (int y0 = 0; y0 < std::max(h, 1); y0 += band) {
    if (!bar.is_none()) o.region = std::array<int, 4>{0, y0, w, std::min(h, y0 + band)};
    Image img;
    {
      py::gil_scoped_release release;
      img = s.render(has_camera ? &c : nullptr, o);
    }
    if (y0 == 0)
      out = py::array_t<float>({static_cast<py::ssize_t>(h > 0 ? h : img.height),
                                static_cast<py::ssize_t>(img.width), py::ssize_t{3}});
    std::copy(img.rgb.begin(), img.rgb.end(), out.mutable_data() + std::size_t(3) * y0 * img.width);
    if (!bar.is_none()) bar(y0 + img.height);
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C between bands
  }
  return py::module_::import("raycast.image").attr("Image")(out);
}

}  // namespace

void bind_render(py::class_<Scene>& scene) {
  scene.def("set_camera", [](Scene& s, const py::kwargs& kw) { s.set_camera(camera_from(kw)); });
  scene.def("render", &render, py::arg("width") = 0, py::arg("height") = 0, py::arg("samples") = 0,
            py::arg("integrator") = "", py::arg("camera") = py::none(),
            py::arg("progress") = py::none(),
            "Renders into a raycast.Image: a (height, width, 3) float32 ndarray of linear RGB that "
            "notebooks display. progress: True shows a bar on stderr, None (the default) shows it "
            "once the render has taken a second, False never.");
}

}  // namespace raycast::python
