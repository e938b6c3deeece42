#include "render/integrator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "geometry/spawn.h"
#include "render/optics.h"
#include "render/terminator.h"
#include "scene/csg_tree.h"
#include "scene/prototype.h"

namespace raycast {

namespace {

/// A shadow segment crossing more surfaces of transmissive objects than this is treated as
/// blocked: a bound on the work per shadow ray, far beyond what a Whitted scene needs.
constexpr int kMaxShadowCrossings = 64;

constexpr double kDegrees = std::numbers::pi / 180;

/// The spot light's cone: 1 inside angle - falloff, 0 outside angle, a smoothstep between.
double spot_factor(const Light& light, const Vec3& from_light) {
  const double cos_theta = std::clamp(dot(light.direction, from_light), -1.0, 1.0);
  const double theta = std::acos(cos_theta) / kDegrees;
  if (theta >= light.angle) return 0;
  if (theta <= light.angle - light.falloff) return 1;
  const double x = (light.angle - theta) / light.falloff;
  return x * x * (3 - 2 * x);
}

/// The Phong exponent as an integer when it is one in [1, 4096] (the common case), else 0.
unsigned integer_exponent(double shininess) {
  return shininess >= 1 && shininess <= 4096 && shininess == std::floor(shininess)
             ? static_cast<unsigned>(shininess)
             : 0;
}

/// The value material_of(o, hit) takes for every hit on o, when it is one value: o.material for
/// a plain shape; for a CSG object or an instance, the same answer from every part (and from a
/// hit outside the parts, which gives o.material). Else nullopt.
std::optional<int> sole_material(const Object& o) {
  std::span<const Object> parts;
  if (const auto* c = std::get_if<CsgShape>(&o.shape)) parts = c->tree->leaves;
  if (const auto* i = std::get_if<InstanceShape>(&o.shape)) parts = i->proto->objects;
  for (const Object& part : parts) {
    const std::optional<int> m = sole_material(part);
    if (!m || (*m >= 0 ? *m : o.material) != o.material) return std::nullopt;
  }
  return o.material;
}

}  // namespace

Color id_color(int entry) {
  const std::uint64_t h = mix64(std::uint64_t(std::uint32_t(entry)) + 1);
  auto channel = [&](int shift) { return 0.15 + 0.85 * double((h >> shift) & 0xff) / 255.0; };
  return {channel(0), channel(8), channel(16)};
}

Integrator::Integrator(const Scene& scene, RenderMode mode)
    : scene_(scene), mode_(mode), textures_(load_textures(scene)) {
  for (const Material& m : scene.materials) {
    any_transmissive_ |= m.transmission > 0;
    filters_.push_back(m.transmission * m.color);
    exponents_.push_back(integer_exponent(m.shininess));
  }
  for (const Light& light : scene.lights) emitted_.push_back(light.emitted());
  for (std::size_t k = 0; k < scene.lights.size(); ++k)
    light_lists_.push_back(scene.object_set().light_lists(k));
  objects_.reserve(scene.objects.size());
  for (const Object& o : scene.objects) {
    ObjectFacts f;
    const bool composite =
        std::holds_alternative<CsgShape>(o.shape) || std::holds_alternative<InstanceShape>(o.shape);
    const std::size_t mi = std::size_t(std::max(o.material, 0));
    f.material = composite ? -1 : std::int32_t(mi);
    // Composites whose parts all resolve to the object's own material need no search per hit.
    const std::optional<int> sole = sole_material(o);
    f.hit_material = sole ? std::int32_t(std::max(*sole, 0)) : -1;
    f.terminator = has_terminator_origin(o);
    if (!o.xf) {
      f.plane = std::get_if<Plane>(&o.shape);
      f.sphere = std::get_if<Sphere>(&o.shape);
    }
    if (composite) {
      f.shadow = ObjectFacts::kWalk;
    } else if (mi < scene.materials.size()) {
      const Material& m = scene.materials[mi];
      const bool textured = m.has_checker || (mi < textures_.size() && textures_[mi]);
      f.shadow = !(m.transmission > 0) ? ObjectFacts::kOpaque
                 : textured            ? ObjectFacts::kWalk
                                       : ObjectFacts::kFilter;
    }
    objects_.push_back(f);
  }
}

std::size_t Integrator::material_index(const SceneHit& hit) const {
  const std::int32_t known = objects_[std::size_t(hit.object)].hit_material;
  if (known >= 0) return std::size_t(known);
  const int m = material_of(scene_.objects[hit.object], hit.local);
  return m >= 0 ? std::size_t(m) : 0;
}

SurfaceNeeds Integrator::needs(std::size_t material) const {
  return material < textures_.size() && textures_[material] ? SurfaceNeeds::kAll
                                                            : SurfaceNeeds::kGeometry;
}

Color Integrator::li_diagnostic(const Ray& ray, SampleState& state) const {
  ++state.rays;
  SceneHit hit;
  const bool found = scene_.intersect(ray, hit);
  return diagnostic_hit(ray, found, hit);
}

Color Integrator::diagnostic_hit(const Ray& ray, bool found, const SceneHit& hit) const {
  if (!found) {
    if (mode_ == RenderMode::kRaycast) return scene_.render.background;
    if (mode_ == RenderMode::kDepth) return {kInfinity, kInfinity, kInfinity};
    return {0, 0, 0};
  }
  const SurfaceInfo si = scene_.surface(ray, hit, needs(hit));
  switch (mode_) {
    case RenderMode::kRaycast: {
      const double facing = std::abs(dot(si.shading_n, normalize(ray.d)));
      return facing * albedo(scene_, textures_, ray, hit, si);
    }
    case RenderMode::kDepth: {
      const double distance = hit.local.t * length(ray.d);
      return {distance, distance, distance};
    }
    case RenderMode::kNormal:
      return 0.5 * si.n + Vec3{0.5, 0.5, 0.5};
    case RenderMode::kId:
      return id_color(scene_.objects[hit.object].entry);
    case RenderMode::kAlbedo:
      return albedo(scene_, textures_, ray, hit, si);
    case RenderMode::kWhitted:  // li() calls whitted() itself
      break;
  }
  return {0, 0, 0};
}

Color Integrator::whitted(const Ray& ray, int depth, SampleState& state, double weight) const {
  if (state.recorder) [[unlikely]]
    return whitted_recorded(ray, depth, state, weight);
  ++state.rays;
  SceneHit hit;
  if (!scene_.intersect(ray, hit)) return scene_.render.background;
  return whitted_hit(ray, hit, depth, state, weight);
}

Color Integrator::whitted_recorded(const Ray& ray, int depth, SampleState& state,
                                   double weight) const {
  RayRecorder& recorder = *state.recorder;
  recorder.begin_ray(ray, depth);
  ++state.rays;
  SceneHit hit;
  if (!scene_.intersect(ray, hit)) {
    recorder.miss(scene_.render.background);
    recorder.stop(RayStop::kMiss);
    recorder.end_ray(scene_.render.background);
    return scene_.render.background;
  }
  const Color radiance = whitted_hit(ray, hit, depth, state, weight);
  recorder.end_ray(radiance);
  return radiance;
}

inline Color Integrator::whitted_hit(const Ray& ray, const SceneHit& hit, int depth,
                                     SampleState& state, double weight) const {
  // The material is resolved once per hit (CSG and instances search their parts for it).
  const std::size_t mi = material_index(hit);
  const Object& object = scene_.objects[hit.object];
  const bool imaged = needs(mi) == SurfaceNeeds::kAll;
  const SurfaceInfo si = raycast::surface(object, ray, hit.local,
                                          imaged ? SurfaceNeeds::kAll : SurfaceNeeds::kGeometry);
  const Material& m = scene_.materials[mi];
  // A plain colour needs no look-up (albedo() would return it).
  const Color c = m.has_checker || imaged ? albedo(scene_, textures_, ray, hit, si, mi) : m.color;
  const Vec3 wi = normalize(ray.d);
  const bool outside = dot(wi, si.n) < 0;
  const Vec3 n = outside ? si.shading_n : -si.shading_n;  // faces the viewer
  const Vec3 v = -wi;
  // Shadow rays leaving on the shading normal's side of a smooth mesh start from Hanika's point
  // (a temporary at its own call: a std::optional here had GCC zero 120 bytes per hit).
  const unsigned exponent = exponents_[mi];
  Color result = m.ambient * mul(scene_.render.ambient, c);
  if (state.recorder) [[unlikely]] {
    state.recorder->hit(hit, si, mi, outside, n);
    state.recorder->ambient(result);
  }
  if (objects_[std::size_t(hit.object)].terminator)
    direct(si, terminator_origin(object, hit.local, si), n, v, m, exponent, c, state, result);
  else
    direct(si, si, n, v, m, exponent, c, state, result);
  if (depth >= scene_.render.max_depth) {
    if (state.recorder) [[unlikely]]
      state.recorder->stop(RayStop::kMaxDepth);
    return result;
  }

  // Split between the mirror and the refracted ray (fixed weights, or exact Fresnel).
  double w_reflect = m.reflection, w_refract = m.transmission;
  Vec3 t_dir;
  bool tir = false;
  double fresnel = -1;
  if (w_refract > 0) {
    const double eta_i = outside ? 1 : m.ior, eta_t = outside ? m.ior : 1;
    const bool refracted = refract(wi, n, eta_i / eta_t, t_dir);
    if (m.fresnel) {
      fresnel = fresnel_dielectric(dot(v, n), eta_i, eta_t);
      w_reflect += w_refract * fresnel;
      w_refract *= 1 - fresnel;
    }
    if (!refracted) {  // total internal reflection: the refracted weight goes to the mirror ray
      w_reflect += w_refract;
      w_refract = 0;
      tir = true;
    }
  }
  // Like POV-Ray's adc_bailout: a ray whose contribution to the pixel (the product of the
  // weights along its path) is below the cut-off is not traced (w > 0 keeps bailout 0 exact).
  const double cutoff = scene_.render.bailout;
  if (state.recorder) [[unlikely]]
    state.recorder->split(w_reflect, w_refract, tir, fresnel, cutoff / weight);
  if (w_reflect > 0 && weight * w_reflect >= cutoff) {
    const Vec3 m_dir = reflect(wi, n);
    if (state.recorder) [[unlikely]]
      state.recorder->child(RayKind::kReflection, w_reflect);
    result += w_reflect *
              whitted({offset_ray_origin(si, m_dir), m_dir}, depth + 1, state, weight * w_reflect);
  }
  if (w_refract > 0 && weight * w_refract >= cutoff) {
    if (state.recorder) [[unlikely]]
      state.recorder->child(RayKind::kRefraction, w_refract);
    result += w_refract *
              whitted({offset_ray_origin(si, t_dir), t_dir}, depth + 1, state, weight * w_refract);
  }
  return result;
}

Color Integrator::li_hit(const Ray& ray, bool found, const SceneHit& hit,
                         SampleState& state) const {
  ++state.rays;
  if (mode_ != RenderMode::kWhitted) return diagnostic_hit(ray, found, hit);
  return found ? whitted_hit(ray, hit, 0, state, 1) : scene_.render.background;
}

void Integrator::direct(const SurfaceInfo& si, const SurfaceInfo& lit, const Vec3& n, const Vec3& v,
                        const Material& m, unsigned exponent, const Color& c, SampleState& state,
                        Color& result) const {
  Color sum{0, 0, 0};
  if (m.diffuse <= 0 && m.specular <= 0) {
    result += sum;
    return;
  }
  // offset_ray_origin depends on the direction only through the side of the surface it points
  // to: every shadow ray that leaves the same point to the same side starts at one origin,
  // computed once (the side test is offset_ray_origin's own, NaN included).
  const SurfaceInfo* origin_from = nullptr;
  bool origin_inward = false;
  Vec3 origin;
  auto origin_towards = [&](const SurfaceInfo& from, const Vec3& l) -> const Vec3& {
    const bool inward = dot(l, from.n) < 0;
    if (origin_from != &from || origin_inward != inward) {
      origin = offset_ray_origin(from, l);
      origin_from = &from;
      origin_inward = inward;
    }
    return origin;
  };
  // The direction lists around the light of the loop below (nullptr for lights without: only
  // point and spot lights have them, and add's shadow rays to such a light end at it).
  const DirectionLists* lists = nullptr;
  // One light direction l towards `target` (a point, or a direction when at infinity).
  // The light of the loop below, for a recorder.
  std::size_t light_index = 0;
  auto add = [&](const Vec3& l, const Vec3& target, bool at_infinity, const Color& e)
      __attribute__((always_inline)) {
    const double nl = dot(n, l);
    // A light with no positive channel (e <= 0) gives a term <= 0: the test of the term below
    // drops it, without a test of e here for every light.
    if (!(nl > 0)) {
      if (state.recorder) [[unlikely]]
        state.recorder->light({light_index, l, nl, {}, {}, false, {}, {}});
      return;
    }
    // Diffuse and Phong highlight: e * (kd nl C + ks max(0, r.v)^shininess), r = l mirrored
    // about n. pow(0, shininess) is 0 for shininess > 0: no pow call when the lobe faces away.
    const Vec3 r = 2 * nl * n - l;
    const double rv = dot(r, v);
    const double highlight =
        m.specular > 0 && (rv > 0 || !(m.shininess > 0))
            ? m.specular * (exponent > 0 ? integer_power(std::max(0.0, rv), exponent)
                                         : std::pow(std::max(0.0, rv), m.shininess))
            : 0;
    const Color term = mul(e, m.diffuse * nl * c + Vec3{highlight, highlight, highlight});
    // The term is >= 0 in every channel; where it is exactly 0 (no diffuse part and the
    // highlight's lobe facing away, as on glass), visibility cannot matter: no shadow ray.
    if (state.recorder) [[unlikely]] {
      const Color diffuse = mul(e, m.diffuse * nl * c);
      const Color specular = highlight * e;
      if (!(max_component(term) > 0)) {
        state.recorder->light({light_index, l, nl, diffuse, specular, false, {}, {}});
        return;
      }
      const SurfaceInfo& from = &lit != &si && dot(l, si.shading_n) > 0 ? lit : si;
      const Vec3& o = origin_towards(from, l);
      const Ray segment = lists         ? Ray{o, lists->apex() - o, 0, 1}
                          : at_infinity ? Ray{o, target, 0, kInfinity}
                                        : Ray{o, target - o, 0, 1};
      // The same queries as below, in the same order.
      Color through{1, 1, 1};
      bool visible;
      if (!any_transmissive_)
        visible = !(lists ? blocked_to(o, *lists, state) : blocked(o, target, at_infinity, state));
      else
        visible = lists ? filters_to(o, *lists, state, through)
                        : filters(o, target, at_infinity, state, through);
      if (visible) sum += any_transmissive_ ? mul(through, term) : term;
      state.recorder->light(
          {light_index, l, nl, diffuse, specular, true, segment, visible ? through : Color{}});
      return;
    }
    if (!(max_component(term) > 0)) return;
    // (lit is si itself except on smooth meshes: then no side test.)
    const SurfaceInfo& from = &lit != &si && dot(l, si.shading_n) > 0 ? lit : si;
    if (!any_transmissive_) {
      // Visibility is 0 or 1: no colour to return and multiply (1 * term is term, bit for bit).
      const Vec3& o = origin_towards(from, l);
      if (!(lists ? blocked_to(o, *lists, state) : blocked(o, target, at_infinity, state)))
        sum += term;
      return;
    }
    // Unblocked, the filter product has a channel above 0 (passes() stops the walk otherwise).
    Color through{1, 1, 1};
    const Vec3& o = origin_towards(from, l);
    if (lists ? filters_to(o, *lists, state, through)
              : filters(o, target, at_infinity, state, through))
      sum += mul(through, term);
  };
  // The lights' bounds once (the shadow rays' calls would otherwise make them reloaded per light).
  const Light* const lights = scene_.lights.data();
  const Color* const emitted_by = emitted_.data();
  const std::size_t light_count = scene_.lights.size();
  for (std::size_t li = 0; li < light_count; ++li) {
    const Light& light = lights[li];
    const Color& emitted = emitted_by[li];
    lists = light_lists_[li];
    light_index = li;
    const bool inverse_square = light.attenuation == Attenuation::kInverseSquare;
    switch (light.type) {
      case LightType::kDirectional:
        add(-light.direction, -light.direction, true, emitted);
        break;
      case LightType::kPoint:
      case LightType::kSpot: {
        const Vec3 to = light.position - si.p;
        const double dist2 = length_squared(to);
        if (!(dist2 > 0)) break;
        const Vec3 l = to / std::sqrt(dist2);
        Color e = inverse_square ? emitted / dist2 : emitted;
        if (light.type == LightType::kSpot) {
          const double cone = spot_factor(light, -l);
          if (!(cone > 0)) break;  // outside the cone: no term
          e *= cone;
        }
        add(l, light.position, false, e);
        break;
      }
      case LightType::kSphere: {
        // Directions uniform in the cone the sphere subtends (pbrt-v4 6.2.4), each sample
        // carrying 1/samples of the light; inside the sphere it acts as a point at its centre.
        const Vec3 to = light.position - si.p;
        const double dist2 = length_squared(to);
        const double r2 = light.radius * light.radius;
        if (dist2 <= r2) {
          add(normalize(to), light.position, false, emitted);
          break;
        }
        const double dist = std::sqrt(dist2);
        const Vec3 w = to / dist;
        Vec3 s, t;
        make_frame(w, s, t);
        const double cos_max = std::sqrt(std::max(0.0, 1 - r2 / dist2));
        const Color share = emitted / double(light.samples);
        for (int k = 0; k < light.samples; ++k) {
          const double cos_theta = 1 - state.rng.uniform() * (1 - cos_max);
          const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
          const double phi = 2 * std::numbers::pi * state.rng.uniform();
          const Vec3 l =
              sin_theta * std::cos(phi) * s + sin_theta * std::sin(phi) * t + cos_theta * w;
          // The nearer crossing of the light's sphere along l (cancellation-free form).
          const double b = dot(l, to);
          const double disc = std::max(0.0, b * b - (dist2 - r2));
          const double q = b + std::sqrt(disc);
          const double along = q > 0 ? (dist2 - r2) / q : dist;
          add(l, si.p + along * l, false, inverse_square ? share / (along * along) : share);
        }
        break;
      }
    }
  }
  result += sum;
}

Color Integrator::shadow(const Vec3& from, const Vec3& to, bool to_infinity,
                         SampleState& state) const {
  if (!any_transmissive_)
    return blocked(from, to, to_infinity, state) ? Color{0, 0, 0} : Color{1, 1, 1};
  Color through{1, 1, 1};
  return filters(from, to, to_infinity, state, through) ? through : Color{0, 0, 0};
}

bool Integrator::blocked(const Vec3& from, const Vec3& to, bool to_infinity,
                         SampleState& state) const {
  const Ray segment{from, to_infinity ? to : to - from, 0, to_infinity ? kInfinity : 1};
  ++state.rays;
  // is_valid(segment) (tmin 0 and tmax 1 or inf are valid): the scene's queries answer nothing
  // for other rays. |d|^2 once for it and the walk's unit direction.
  const double dd = length_squared(segment.d);
  const bool valid = is_valid_extent(length_squared(segment.o), dd);
  const Vec3 e = segment.d * (1 / std::sqrt(dd));  // the unit direction, for the balls
  return valid && scene_.any_object_along(
                      segment, e, [&](std::uint32_t index) { return crosses(index, segment); });
}

inline bool Integrator::filters(const Vec3& from, const Vec3& to, bool to_infinity,
                                SampleState& state, Color& through) const {
  const Ray segment{from, to_infinity ? to : to - from, 0, to_infinity ? kInfinity : 1};
  ++state.rays;
  const double dd = length_squared(segment.d);
  const bool valid = is_valid_extent(length_squared(segment.o), dd);
  const Vec3 e = segment.d * (1 / std::sqrt(dd));
  // One pass over the objects on the segment (docs/rendering.md "Shadow rays"): each object is
  // asked on its own whether the segment crosses it (an any-hit query, or for a composite
  // object with materials per part, a walk of its own crossings); the first opaque crossing
  // ends the pass, each transmissive object crossed multiplies by its filter once.
  return !(valid && scene_.any_object_along(segment, e, [&](std::uint32_t index) {
    return !passes(index, segment, through);
  }));
}

[[gnu::noinline]] bool Integrator::blocked_to(const Vec3& from, const DirectionLists& lists,
                                              SampleState& state) const {
  const Ray segment{from, lists.apex() - from, 0, 1};
  ++state.rays;
  const double dd = length_squared(segment.d);
  const bool valid = is_valid_extent(length_squared(segment.o), dd);
  return valid && scene_.object_set().any_along_to(
                      lists, segment, [&](std::uint32_t index) { return crosses(index, segment); });
}

[[gnu::noinline]] bool Integrator::filters_to(const Vec3& from, const DirectionLists& lists,
                                              SampleState& state, Color& through) const {
  const Ray segment{from, lists.apex() - from, 0, 1};
  ++state.rays;
  const double dd = length_squared(segment.d);
  const bool valid = is_valid_extent(length_squared(segment.o), dd);
  return !(valid && scene_.object_set().any_along_to(lists, segment, [&](std::uint32_t index) {
    return !passes(index, segment, through);
  }));
}

inline bool Integrator::crosses(std::uint32_t index, const Ray& segment) const {
  const ObjectFacts& facts = objects_[index];
  if (facts.plane) return raycast::crosses(*facts.plane, segment);
  if (facts.sphere) return occluded(*facts.sphere, segment);
  return occluded(scene_.objects[index], segment);
}

inline bool Integrator::passes(std::uint32_t index, const Ray& segment, Color& through) const {
  const ObjectFacts& facts = objects_[index];
  // An opaque object blocks wherever it crosses; an untextured transmissive one filters by its
  // material's transmission * color once.
  if (facts.shadow == ObjectFacts::kOpaque) return !crosses(index, segment);
  if (facts.shadow == ObjectFacts::kFilter) {
    if (!crosses(index, segment)) return true;
    through = mul(through, filters_[std::size_t(facts.material)]);
    return max_component(through) > 0;
  }
  return passes_walk(index, segment, through);
}

bool Integrator::passes_walk(std::uint32_t index, const Ray& segment, Color& through) const {
  const Object& object = scene_.objects[index];
  const bool composite = objects_[index].material < 0;
  // The object's crossings in order: the first opaque one blocks; the first transmissive one
  // gives the filter colour (its albedo at that crossing).
  Ray r = segment;
  bool counted = false;
  for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
    LocalHit h;
    if (!intersect(object, r, h)) return true;
    const SceneHit hit{h, std::int32_t(index)};
    const Material& m = scene_.material_of(hit);
    if (!(m.transmission > 0)) return false;
    if (!counted) {
      const SurfaceInfo si = scene_.surface(segment, hit, needs(hit));
      through = mul(through, m.transmission * albedo(scene_, textures_, segment, hit, si));
      if (!(max_component(through) > 0)) return false;
      counted = true;
    }
    if (!composite) return true;  // one material: the rest of its crossings change nothing
    r.tmin = interval_detail::up(h.t);
  }
  return false;
}

}  // namespace raycast
