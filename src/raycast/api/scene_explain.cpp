// A pixel's ray tree for a raycast::api::Scene (render/explain.h).
#include "api/impl.h"
#include "render/explain.h"
#include "render/explain_format.h"

namespace raycast::api {

std::string Scene::explain_json(int x, int y, const RenderOptions& options, int sample) const {
  const raycast::Scene& scene = ready().scene;
  raycast::ExplainOptions o;
  o.x = x;
  o.y = y;
  o.sample = sample;
  o.width = options.width;
  o.height = options.height;
  o.spp = options.samples;
  try {
    return raycast::explain_json(scene, raycast::explain_pixel(scene, o));
  } catch (const raycast::SceneError& e) {
    rethrow_scene_error(e);
  }
}

}  // namespace raycast::api
