#include "render/explain.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "render/camera.h"
#include "render/integrator.h"
#include "render/renderer.h"

namespace raycast {

namespace {

/// Builds the tree from the integrator's calls: a stack of the rays begun and not yet ended.
class TreeRecorder final : public RayRecorder {
 public:
  explicit TreeRecorder(ExplainedRay& root) : root_(root) {}

  void child(RayKind kind, double weight, const Color& tint) override {
    next_kind_ = kind;
    next_weight_ = weight;
    next_tint_ = tint;
  }
  void begin_ray(const Ray& ray, int depth) override {
    ExplainedRay* node = &root_;
    if (!open_.empty()) {
      open_.back()->children.emplace_back();
      node = &open_.back()->children.back();
    }
    node->kind = open_.empty() ? RayKind::kCamera : next_kind_;
    node->weight = open_.empty() ? 1 : next_weight_;
    node->tint = open_.empty() ? Color{1, 1, 1} : next_tint_;
    node->ray = ray;
    node->depth = depth;
    open_.push_back(node);
  }
  void miss(const Color&) override {}
  void hit(const SceneHit& hit, const SurfaceInfo& si, std::size_t material, bool outside,
           const Vec3& n) override {
    ExplainedHit& h = open_.back()->hit.emplace();
    h.hit = hit;
    h.si = si;
    h.material = material;
    h.outside = outside;
    h.n = n;
  }
  void ambient(const Color& term) override { open_.back()->hit->ambient = term; }
  void light(const LightSample& sample) override {
    open_.back()->hit->lights.push_back({sample, -1, 0, {}, {}});
  }
  void split(double w_reflect, double w_refract, bool tir, double fresnel,
             double bailout) override {
    ExplainedRay& r = *open_.back();
    r.split = true;
    r.w_reflect = w_reflect;
    r.w_refract = w_refract;
    r.tir = tir;
    r.fresnel = fresnel;
    r.bailout = bailout;
  }
  void stop(RayStop why) override { open_.back()->stop = why; }
  void end_ray(const Color& radiance) override {
    open_.back()->radiance = radiance;
    open_.pop_back();
  }

 private:
  ExplainedRay& root_;
  std::vector<ExplainedRay*> open_;
  RayKind next_kind_ = RayKind::kCamera;
  double next_weight_ = 1;
  Color next_tint_{1, 1, 1};
};

/// Completes the tree: each hit's (u, v), and what each shadow segment met: the nearest opaque
/// object on it (the blocker when the light was cut off) and the transmissive objects it crosses.
void complete_tree(const Scene& scene, ExplainedRay& ray) {
  if (ray.hit) {
    // The integrator asks for (u, v) only where an image texture needs them.
    const SurfaceInfo full = scene.surface(ray.ray, ray.hit->hit);
    ray.hit->si.u = full.u;
    ray.hit->si.v = full.v;
    for (ExplainedLight& light : ray.hit->lights) {
      if (!light.sample.shadow_ray) continue;
      std::vector<Crossing> crossings;
      scene.intersect_all(light.sample.shadow, crossings);
      for (const Crossing& c : crossings) {
        const Material& m = scene.material_of({c.local, c.object});
        if (m.transmission > 0) {
          if (std::find(light.filters.begin(), light.filters.end(), c.object) ==
              light.filters.end())
            light.filters.push_back(c.object);
        } else if (light.blocker < 0) {
          light.blocker = c.object;
          light.blocker_t = c.t;
          light.blocker_n = scene.surface(light.sample.shadow, {c.local, c.object}).n;
        }
      }
    }
  }
  for (ExplainedRay& child : ray.children) complete_tree(scene, child);
}

Color sum_lights(const ExplainedRay& ray, bool diffuse) {
  Color sum{0, 0, 0};
  if (!ray.hit) return sum;
  for (const ExplainedLight& light : ray.hit->lights)
    if (light.sample.shadow_ray)
      sum += mul(light.sample.visibility, diffuse ? light.sample.diffuse : light.sample.specular);
  return sum;
}

Color sum_children(const ExplainedRay& ray, RayKind kind) {
  Color sum{0, 0, 0};
  for (const ExplainedRay& child : ray.children)
    if (child.kind == kind) sum += child.weight * mul(child.tint, child.radiance);
  return sum;
}

}  // namespace

Color ExplainedRay::diffuse() const { return sum_lights(*this, true); }
Color ExplainedRay::specular() const { return sum_lights(*this, false); }
Color ExplainedRay::reflection() const { return sum_children(*this, RayKind::kReflection); }
Color ExplainedRay::refraction() const { return sum_children(*this, RayKind::kRefraction); }

const char* ray_kind_name(RayKind kind) {
  switch (kind) {
    case RayKind::kCamera:
      return "camera";
    case RayKind::kReflection:
      return "reflection";
    case RayKind::kRefraction:
      return "refraction";
  }
  return "camera";
}

Explanation explain_pixel(const Scene& scene, const ExplainOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Explanation e;
  e.width = options.width > 0 ? options.width : scene.image.width;
  e.height = options.height > 0 ? options.height : scene.image.height;
  e.spp = options.spp > 0 ? options.spp : scene.image.samples;
  e.x = options.x;
  e.y = options.y;
  e.sample = options.sample;
  if (e.width <= 0 || e.height <= 0 || e.spp <= 0)
    throw std::invalid_argument("explain: image width, height and samples must be positive");
  if (e.x < 0 || e.y < 0 || e.x >= e.width || e.y >= e.height)
    throw std::invalid_argument(
        "explain: pixel (" + std::to_string(e.x) + ", " + std::to_string(e.y) +
        ") is outside the " + std::to_string(e.width) + "x" + std::to_string(e.height) + " image");
  if (e.sample < 0 || e.sample >= e.spp)
    throw std::invalid_argument("explain: --sample must be in [0, " + std::to_string(e.spp) +
                                "), got " + std::to_string(e.sample));
  const Camera camera(options.camera.value_or(camera_or_default(scene)), e.width, e.height);
  const Integrator integrator(scene, RenderMode::kWhitted);
  TreeRecorder recorder(e.root);
  // The renderer's fixed-sample loop for one pixel (render/renderer.cpp).
  SampleState state{Rng::for_pixel(e.x, e.y, scene.render.seed), 0};
  for (int k = 0; k <= e.sample; ++k) {
    double ox = 0.5, oy = 0.5;
    if (e.spp > 1) {
      const double jx = state.rng.uniform();
      const double jy = state.rng.uniform();
      sample_offset(k, e.spp, jx, jy, ox, oy);
    }
    const Ray ray = camera.ray(e.x + ox, e.y + oy);
    if (k < e.sample) {
      integrator.li(ray, state);
      continue;
    }
    state.rays = 0;
    state.recorder = &recorder;
    e.color = integrator.whitted(ray, 0, state);
    state.recorder = nullptr;
  }
  e.rays = state.rays;
  complete_tree(scene, e.root);
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

}  // namespace raycast
