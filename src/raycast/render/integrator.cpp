#include "render/integrator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <utility>

#include "geometry/spawn.h"
#include "objects/csg_tree.h"
#include "objects/prototype.h"
#include "render/area_light_adaptive.h"
#include "render/dispersion.h"
#include "render/light_falloff.h"
#include "render/optics.h"
#include "render/terminator.h"

// trace, whitted_hit and direct: their render mode is instantiated here.
#include "render/whitted_trace.inl"

namespace raycast {

namespace {

/// A shadow segment crossing more surfaces of transmissive objects than this is treated as
/// blocked: a bound on the work per shadow ray, far beyond what a Whitted scene needs.
constexpr int kMaxShadowCrossings = 64;

/// The Phong exponent as an integer when it is one in [1, 4096] (the common case), else 0.
unsigned integer_exponent(double shininess) {
  return shininess >= 1 && shininess <= 4096 && shininess == std::floor(shininess)
             ? static_cast<unsigned>(shininess)
             : 0;
}

/// The value material_of(o, hit) takes for every hit on o, when it is one value: o.material for
/// a plain shape; for a CSG object or an instance, the same answer from every part (and from a
/// hit outside the parts, which gives o.material). Else nullopt (also for a blob whose components
/// have materials of their own).
std::optional<int> sole_material(const Object& o) {
  if (const auto* b = std::get_if<Blob>(&o.shape); b && b->data->materials) return std::nullopt;
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
    any_transmissive_ |= m.transmission > 0 || (m.texture && m.texture->may_transmit());
    filters_.push_back(m.transmission * m.color);
    exponents_.push_back(integer_exponent(m.shininess));
  }
  for (const Light& light : scene.lights) emitted_.push_back(light.emitted());
  if (const Atmosphere* a = scene.render.atmosphere.get(); a && !a->empty()) {
    atmosphere_ = a;
    veils_ = a->veils();
  }
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
      if (m.texture)
        f.shadow = m.texture->may_transmit() ? ObjectFacts::kWalk : ObjectFacts::kOpaque;
      else
        f.shadow = !(m.transmission > 0) ? ObjectFacts::kOpaque
                   : textured            ? ObjectFacts::kWalk
                                         : ObjectFacts::kFilter;
    }
    if (!o.casts_shadow) f.shadow = ObjectFacts::kPass;  // shadow rays walk past it (passes())
    if (f.hit_material >= 0 && std::size_t(f.hit_material) < scene.materials.size() &&
        (f.shadow == ObjectFacts::kFilter || f.shadow == ObjectFacts::kWalk) &&
        fades(scene.materials[std::size_t(f.hit_material)]))
      f.fade = &scene.materials[std::size_t(f.hit_material)];
    any_transmissive_ |= !o.casts_shadow;
    f.hidden_from_camera = !o.seen_by_camera;
    f.hidden_from_reflections = !o.seen_in_reflections;
    any_hidden_ |= f.hidden_from_camera || f.hidden_from_reflections;
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

// The recording modes are compiled in integrator_record.cpp: with them in this file GCC stopped
// inlining offset_ray_origin into the render's mode (3 % more instructions on
// bench/scenes/glass.yaml under bench/render_instructions.sh).
extern template Color Integrator::trace<Integrator::kCount>(const Ray& ray, int depth,
                                                            SampleState& state, double weight,
                                                            const Material* medium) const;
extern template Color Integrator::trace<Integrator::kRecord>(const Ray& ray, int depth,
                                                             SampleState& state, double weight,
                                                             const Material* medium) const;

Color Integrator::whitted(const Ray& ray, int depth, SampleState& state, double weight) const {
  if (state.recorder) [[unlikely]]
    return state.recorder->events ? trace<kRecord>(ray, depth, state, weight)
                                  : trace<kCount>(ray, depth, state, weight);
  // trace<false>'s body, here rather than called: a call per camera ray cost 0.5 % more
  // instructions on bench/scenes/whitted.yaml.
  ++state.rays;
  SceneHit hit;
  if (!scene_.intersect(ray, hit) || (any_hidden_ && !seen(ray, hit, depth == 0, state)))
    return missed(ray);
  return fogged(ray, hit.local.t, whitted_hit<kPlain>(ray, hit, depth, state, weight));
}

bool Integrator::seen(const Ray& ray, SceneHit& hit, bool camera, const SampleState& state) const {
  Ray beyond = ray;
  for (int k = 0; k < kMaxHiddenSkips; ++k) {
    const ObjectFacts& f = objects_[std::size_t(hit.object)];
    if (!(camera ? f.hidden_from_camera : state.mirrored && f.hidden_from_reflections)) return true;
    beyond.tmin = std::nextafter(hit.local.t, kInfinity);
    if (!(beyond.tmin <= beyond.tmax) || !scene_.intersect(beyond, hit)) return false;
  }
  return false;
}

Color Integrator::li_hit(const Ray& ray, bool found, const SceneHit& hit,
                         SampleState& state) const {
  if (!(ray.tmin <= ray.tmax)) return {0, 0, 0};  // a lens's pixel that sees nothing
  ++state.rays;
  if (mode_ != RenderMode::kWhitted) return diagnostic_hit(ray, found, hit);
  if (found && any_hidden_) [[unlikely]] {
    SceneHit visible = hit;
    return seen(ray, visible, true, state)
               ? fogged(ray, visible.local.t, whitted_hit<kPlain>(ray, visible, 0, state, 1))
               : missed(ray);
  }
  return found ? fogged(ray, hit.local.t, whitted_hit<kPlain>(ray, hit, 0, state, 1)) : missed(ray);
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
  if (facts.shadow == ObjectFacts::kPass) return true;
  if (facts.fade) [[unlikely]]
    return passes_fading(index, segment, through);
  if (facts.shadow == ObjectFacts::kFilter) {
    if (!crosses(index, segment)) return true;
    through = mul(through, filters_[std::size_t(facts.material)]);
    return max_component(through) > 0;
  }
  return passes_walk(index, segment, through);
}

bool Integrator::passes_fading(std::uint32_t index, const Ray& segment, Color& through) const {
  const ObjectFacts& facts = objects_[index];
  if (facts.shadow == ObjectFacts::kFilter) {
    if (crosses(index, segment)) through = mul(through, filters_[std::size_t(facts.material)]);
  } else if (!passes_walk(index, segment, through)) {
    return false;
  }
  // The length inside: the solid's spans over the whole line, cut to the segment.
  SpanList inside;
  spans(scene_.objects[index], segment, inside);
  double length_inside = 0;
  for (const Span& s : inside) {
    const double from = std::max(s.in.t, segment.tmin), to = std::min(s.out.t, segment.tmax);
    if (to > from) length_inside += to - from;
  }
  if (length_inside > 0)
    through = mul(through, interior_fade(*facts.fade, length_inside * length(segment.d)));
  return max_component(through) > 0;
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
    if (m.texture) {
      // A texture's filter and transmit vary over the surface: what it lets through here.
      if (!m.texture->may_transmit()) return false;
      if (!counted)
        through = mul(through,
                      texture::transmittance(*m.texture, texture_point(object, m, segment, hit)));
      if (!(max_component(through) > 0)) return false;
      counted = true;
      if (!composite) return true;
      r.tmin = interval_detail::up(h.t);
      continue;
    }
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
