#include "serve/camera_request.h"

#include <cmath>
#include <sstream>

#include "io/scene_error.h"
#include "load/yaml_reader.h"
#include "serve/json_text.h"

namespace raycast::serve {

namespace {

void check_bounded(Fields& f, const char* key, const Vec3& v) {
  if (!(std::fabs(v.x) <= kMaxCoordinate && std::fabs(v.y) <= kMaxCoordinate &&
        std::fabs(v.z) <= kMaxCoordinate))
    f.fail(key, f.name(key) + " must have coordinates of magnitude at most 1e9");
}

}  // namespace

CameraDesc parse_camera_request(const std::string& body, const CameraDesc& current) {
  const YamlDocument request = parse_request_object(body, 4096);
  const SourceContext ctx{"request", "."};
  Fields f(ctx, request.root(), "camera");
  CameraDesc c = current;
  const std::string type =
      f.string("type", current.type == CameraType::kOrthographic ? "orthographic" : "perspective");
  c.position = f.vec3("position", c.position);
  c.look_at = f.vec3("look_at", c.look_at);
  c.up = f.direction("up", c.up);
  check_bounded(f, "position", c.position);
  check_bounded(f, "look_at", c.look_at);
  check_bounded(f, "up", c.up);
  if (type == "perspective") {
    c.type = CameraType::kPerspective;
    c.fov = f.number("fov", c.fov);
    if (!(c.fov > 0 && c.fov < 180)) f.fail("fov", "camera.fov must be in (0, 180) degrees");
    f.optional("height");  // the page sends both; only the type's own field counts
  } else if (type == "orthographic") {
    c.type = CameraType::kOrthographic;
    c.height = f.positive("height", c.height);
    if (!(c.height <= kMaxCoordinate)) f.fail("height", "camera.height must be at most 1e9");
    f.optional("fov");
  } else {
    f.fail("type", "camera.type must be perspective or orthographic, got " + type);
  }
  f.finish();
  if (length_squared(c.look_at - c.position) == 0)
    throw SceneError("request", 0, 0, "camera.look_at must differ from camera.position");
  if (length_squared(cross(c.look_at - c.position, c.up)) == 0)
    throw SceneError("request", 0, 0, "camera.up must not be parallel to the viewing direction");
  return c;
}

std::string camera_json(const CameraDesc& c) {
  std::ostringstream out;
  out << "{\"type\":"
      << (c.type == CameraType::kOrthographic ? "\"orthographic\"" : "\"perspective\"")
      << ",\"position\":" << json_vec3(c.position) << ",\"look_at\":" << json_vec3(c.look_at)
      << ",\"up\":" << json_vec3(c.up) << ",\"fov\":" << json_number(c.fov)
      << ",\"height\":" << json_number(c.height) << "}";
  return out.str();
}

}  // namespace raycast::serve
