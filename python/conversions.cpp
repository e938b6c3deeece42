// Small Python-to-engine conversions shared by the bindings (bindings.h).
#include <filesystem>
#include <mutex>

#include "bindings.h"

namespace raycast::python {

Vec3d vec3(const py::handle& h, const char* what) {
  try {
    const auto v = h.cast<std::vector<double>>();
    if (v.size() == 3) return {v[0], v[1], v[2]};
  } catch (const py::cast_error&) {
  }
  throw py::value_error(std::string(what) + " must be 3 numbers");
}

Transform matrix4(const py::handle& h, const char* what) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
  if (!a || a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
    throw py::value_error(std::string(what) + " must be a 4x4 matrix (object to world)");
  Transform t;
  for (int i = 0; i < 16; ++i) t.m[i] = a.data()[i];
  return t;
}

void require_file(const std::string& path) {
  if (!std::filesystem::exists(path)) {
    PyErr_SetString(PyExc_FileNotFoundError, ("no such file: '" + path + "'").c_str());
    throw py::error_already_set();
  }
}

void ensure_committed(Scene& scene) {
  // One mutex for every scene: builds are rare next to queries, and the check itself must not
  // race with a build running in another Python thread (the GIL is released during it).
  static std::mutex build;
  py::gil_scoped_release release;
  const std::lock_guard lock(build);
  if (!scene.committed()) scene.commit();
}

}  // namespace raycast::python
