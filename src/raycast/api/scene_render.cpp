// Rendering a raycast::api::Scene into an image buffer.
#include <stdexcept>
#include <string>

#include "api/impl.h"
#include "io/scene_error.h"
#include "render/renderer.h"

namespace raycast::api {

namespace {

raycast::RenderMode integrator(const std::string& name) {
  if (const std::optional<raycast::RenderMode> mode = raycast::integrator_named(name)) return *mode;
  const std::string message =
      std::string("integrator must be ") + raycast::kIntegratorNames + ", got " + name;
  throw SceneError("render: " + message, "render", 0, 0, message);
}

}  // namespace

Image Scene::render(const Camera* camera, const RenderOptions& options) const {
  const raycast::Scene& scene = ready().scene;
  raycast::RenderOptions o;
  o.width = options.width;
  o.height = options.height;
  o.spp = options.samples;
  o.threads = options.threads;
  o.progress = false;
  if (!options.integrator.empty()) o.integrator = integrator(options.integrator);
  if (options.width < 0 || options.height < 0 || options.samples < 0)
    throw std::invalid_argument("render: width, height and samples must be >= 0");
  const int w = options.width > 0 ? options.width : scene.image.width;
  const int h = options.height > 0 ? options.height : scene.image.height;
  if (w > raycast::kMaxImageSide || h > raycast::kMaxImageSide ||
      static_cast<long long>(w) * h > raycast::kMaxImagePixels)
    throw std::invalid_argument(
        "render: the image is larger than raycast renders (see "
        "docs/robustness.md)");
  if (options.region) {
    const auto [x0, y0, x1, y1] = *options.region;
    if (x0 < 0 || y0 < 0 || x1 > w || y1 > h || x0 >= x1 || y0 >= y1)
      throw std::invalid_argument("render: region must be {x0, y0, x1, y1} with 0 <= x0 < x1 <= " +
                                  std::to_string(w) + " and 0 <= y0 < y1 <= " + std::to_string(h));
    o.region = raycast::PixelRect{x0, y0, x1, y1};
  }
  raycast::Image image;
  try {
    if (camera) {
      // The engine renders a scene's own camera: a copy of the scene (object handles and the
      // top-level BVH; meshes and CSG trees are shared) carries the one asked for.
      Scene tmp;
      tmp.set_camera(*camera);
      raycast::Scene copy = scene;
      copy.camera = tmp.impl_->scene.camera;
      image = raycast::render(copy, o);
    } else {
      image = raycast::render(scene, o);
    }
  } catch (const raycast::SceneError& e) {
    rethrow_scene_error(e);
  }
  return {image.width, image.height, std::move(image.rgb)};
}

std::array<int, 2> Scene::image_size() const {
  const raycast::Scene& scene = ready().scene;
  return {scene.image.width, scene.image.height};
}

}  // namespace raycast::api
