// Materials and lights of raycast.Scene (docs/python.md "Building").
#include "bindings.h"

namespace raycast::python {

void bind_appearance(py::class_<Scene>& scene) {
  scene
      .def(
          "add_material",
          [](Scene& s, const py::object& color, double ambient, double diffuse, double specular,
             double shininess, double reflection, double transmission, double ior) {
            Material mat;
            mat.color = vec3(color, "color");
            mat.ambient = ambient;
            mat.diffuse = diffuse;
            mat.specular = specular;
            mat.shininess = shininess;
            mat.reflection = reflection;
            mat.transmission = transmission;
            mat.ior = ior;
            return s.add_material(mat);
          },
          py::arg("color") = py::make_tuple(0.8, 0.8, 0.8), py::arg("ambient") = 1.0,
          py::arg("diffuse") = 0.8, py::arg("specular") = 0.0, py::arg("shininess") = 32.0,
          py::arg("reflection") = 0.0, py::arg("transmission") = 0.0, py::arg("ior") = 1.0)
      .def("set_material", &Scene::set_material, py::arg("object"), py::arg("material"))
      .def(
          "add_point_light",
          [](Scene& s, const py::object& position, const py::object& color, double intensity) {
            Light l;
            l.position = vec3(position, "position");
            l.color = vec3(color, "color");
            l.intensity = intensity;
            s.add_light(l);
          },
          py::arg("position"), py::arg("color") = py::make_tuple(1, 1, 1),
          py::arg("intensity") = 1.0)
      .def(
          "add_directional_light",
          [](Scene& s, const py::object& direction, const py::object& color, double intensity) {
            Light l;
            l.type = Light::Type::kDirectional;
            l.direction = vec3(direction, "direction");
            l.color = vec3(color, "color");
            l.intensity = intensity;
            s.add_light(l);
          },
          py::arg("direction"), py::arg("color") = py::make_tuple(1, 1, 1),
          py::arg("intensity") = 1.0);
}

}  // namespace raycast::python
