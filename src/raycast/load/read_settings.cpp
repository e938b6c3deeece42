#include "load/read_settings.h"

#include <map>
#include <string>

#include "load/read_atmosphere.h"

namespace raycast {

namespace {

// render.antialias: {method, threshold, depth} (docs/scene-format.md).
void read_antialias(const SourceContext& ctx, const YamlNode& node, AntialiasSettings& aa) {
  Fields f(ctx, node, "render.antialias");
  const std::string method = f.string("method");
  if (method == "none")
    aa.method = AntialiasMethod::kNone;
  else if (method == "1" || method == "neighbour")
    aa.method = AntialiasMethod::kNeighbour;
  else if (method == "2" || method == "subdivide")
    aa.method = AntialiasMethod::kSubdivide;
  else if (method == "variance")
    aa.method = AntialiasMethod::kVariance;
  else
    f.fail("method",
           "render.antialias.method must be none, 1 (neighbour), 2 (subdivide) or "
           "variance, got " +
               method);
  aa.threshold = f.non_negative("threshold", aa.threshold);
  aa.depth = f.integer("depth", aa.depth, 1, 16);
  f.finish();
}

// The lens types of camera.type beside perspective and orthographic.
const std::map<std::string, CameraType>& camera_lenses() {
  static const std::map<std::string, CameraType> lenses = {
      {"fisheye", CameraType::kFisheye},   {"ultra_wide_angle", CameraType::kUltraWideAngle},
      {"omnimax", CameraType::kOmnimax},   {"panoramic", CameraType::kPanoramic},
      {"cylinder", CameraType::kCylinder}, {"spherical", CameraType::kSpherical}};
  return lenses;
}

}  // namespace

Color read_color(Fields& f, const std::string& key, const Color& fallback) {
  if (!f.has(key)) return fallback;
  const Color c = f.vec3(key);
  if (c.x < 0 || c.y < 0 || c.z < 0) f.fail(key, f.name(key) + " must be >= 0 in every channel");
  return c;
}

CameraDesc read_camera(const SourceContext& ctx, const YamlNode& node) {
  Fields f(ctx, node, "camera");
  CameraDesc c;
  const std::string type = f.string("type", "perspective");
  c.position = f.vec3("position", c.position);
  c.look_at = f.vec3("look_at", c.look_at);
  c.up = f.direction("up", c.up);
  if (type == "perspective") {
    c.type = CameraType::kPerspective;
    c.fov = f.number("fov", c.fov);
    if (!(c.fov > 0 && c.fov < 180)) f.fail("fov", "camera.fov must be in (0, 180) degrees");
  } else if (type == "orthographic") {
    c.type = CameraType::kOrthographic;
    c.height = f.positive("height", c.height);
  } else if (const auto lens = camera_lenses().find(type); lens != camera_lenses().end()) {
    c.type = lens->second;
    c.angle = f.number("angle", c.angle);
    if (!(c.angle > 0 && c.angle <= 360))
      f.fail("angle", "camera.angle must be in (0, 360] degrees");
    if (c.type == CameraType::kSpherical) {
      c.vertical_angle = f.number("vertical_angle", 0.5 * c.angle);
      if (!(c.vertical_angle > 0 && c.vertical_angle <= 360))
        f.fail("vertical_angle", "camera.vertical_angle must be in (0, 360] degrees");
    }
    if (c.type == CameraType::kCylinder) c.cylinder = f.integer("cylinder", c.cylinder, 1, 4);
  } else {
    f.fail("type",
           "camera.type must be perspective, orthographic, fisheye, ultra_wide_angle, omnimax, "
           "panoramic, cylinder or spherical, got " +
               type);
  }
  if (f.has("direction") || f.has("right")) {
    // POV-Ray's own vectors: both or neither.
    CameraFrame frame;
    frame.direction = f.direction("direction");
    frame.right = f.direction("right");
    frame.up = c.up;
    if (length_squared(cross(frame.right, frame.up)) == 0)
      f.fail("right", "camera.right must not be parallel to camera.up");
    c.frame = frame;
  }
  f.finish();
  if (length_squared(c.look_at - c.position) == 0)
    fail_at(ctx, node, "camera.look_at must differ from camera.position");
  if (length_squared(cross(c.look_at - c.position, c.up)) == 0)
    fail_at(ctx, node, "camera.up must not be parallel to the viewing direction");
  return c;
}

ImageSettings read_image(const SourceContext& ctx, const YamlNode& node) {
  Fields f(ctx, node, "image");
  ImageSettings image;
  image.width = f.integer("width", image.width, 1, kMaxImageSide);
  image.height = f.integer("height", image.height, 1, kMaxImageSide);
  image.samples = f.integer("samples", image.samples, 1, 1 << 16);
  f.finish();
  if (static_cast<long long>(image.width) * image.height > kMaxImagePixels)
    fail_at(ctx, node,
            "image.width * image.height must be at most " + std::to_string(kMaxImagePixels) +
                " pixels, got " + std::to_string(image.width) + " x " +
                std::to_string(image.height));
  return image;
}

RenderSettings read_render(const SourceContext& ctx, const YamlNode& node) {
  Fields f(ctx, node, "render");
  RenderSettings r;
  const std::string integrator = f.string("integrator", "whitted");
  if (const std::optional<RenderMode> mode = integrator_named(integrator))
    r.integrator = *mode;
  else
    f.fail("integrator",
           std::string("render.integrator must be ") + kIntegratorNames + ", got " + integrator);
  r.max_depth = f.integer("max_depth", r.max_depth, 0, 1000);
  r.bailout = f.non_negative("bailout", r.bailout);
  r.background = read_color(f, "background", r.background);
  r.ambient = read_color(f, "ambient", r.ambient);
  r.atmosphere = read_atmosphere(f);
  r.seed = static_cast<unsigned>(f.integer("seed", 0, 0, 2147483647));
  if (f.has("antialias")) read_antialias(ctx, f.required("antialias"), r.antialias);
  f.finish();
  return r;
}

}  // namespace raycast
