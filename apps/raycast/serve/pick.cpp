#include "serve/pick.h"

#include <sstream>

#include "render/camera.h"
#include "serve/json_text.h"

namespace raycast::serve {

std::string pick_json(const Scene& scene, const CameraDesc& camera, int width, int height, double x,
                      double y) {
  const Camera cam(camera, width, height);
  const Ray ray = cam.ray(x, y);
  SceneHit hit;
  std::ostringstream out;
  out << "{\"x\":" << json_number(x) << ",\"y\":" << json_number(y);
  if (!scene.intersect(ray, hit)) {
    out << ",\"hit\":false}";
    return out.str();
  }
  const SurfaceInfo si = scene.surface(ray, hit);
  const Object& object = scene.objects[std::size_t(hit.object)];
  const Material& material = scene.material_of(hit);
  SourceMark mark;
  if (object.entry >= 0 && std::size_t(object.entry) < scene.marks.entries.size())
    mark = scene.marks.entries[std::size_t(object.entry)];
  out << ",\"hit\":true,\"t\":" << json_number(hit.local.t) << ",\"point\":" << json_vec3(si.p)
      << ",\"normal\":" << json_vec3(si.n) << ",\"object\":{\"index\":" << hit.object
      << ",\"entry\":" << object.entry << ",\"shape\":" << json_string(shape_name(object))
      << ",\"line\":" << mark.line << ",\"column\":" << mark.column
      << "},\"material\":" << json_string(material.name.empty() ? "default" : material.name) << "}";
  return out.str();
}

}  // namespace raycast::serve
