#pragma once
// Radiance along one ray: the Whitted integrator (docs/rendering.md "Shading") and the simple
// diagnostic integrators (raycast, depth, normal, id) and the albedo AOV.
#include <cstdint>
#include <memory>
#include <vector>

#include "render/atmosphere.h"
#include "render/ray_recorder.h"
#include "render/rng.h"
#include "render/texture.h"
#include "render/textured_shading.h"
#include "scene/scene.h"

namespace raycast {

/// The mutable state of one sample: its random numbers and its ray count (every intersect or
/// occluded query on the scene counts one ray: primary, secondary and shadow rays alike), and
/// the observer of the Whitted integrator's work (render/ray_recorder.h; null: none, the render's
/// case).
struct SampleState {
  Rng rng;
  std::uint64_t rays = 0;
  RayRecorder* recorder = nullptr;
  // The spectral position (render/dispersion.h) of the ray being traced once a dispersive
  // surface has split it, -1 for white light.
  double band = -1;
  // Whether the ray being traced is a mirrored one (for objects hidden from reflections).
  bool mirrored = false;
};

/// A stable colour for a top-level object entry (the `id` integrator): a hash of the index,
/// each channel in [0.15, 1] so that no entry is black like the background.
Color id_color(int entry);

class Integrator {
 public:
  /// Loads the scene's image textures (throws SceneError when one cannot be read). The scene
  /// must outlive the integrator.
  Integrator(const Scene& scene, RenderMode mode);

  /// The value seen along a primary ray (unit direction for `depth` to be a distance).
  Color li(const Ray& ray, SampleState& state) const {
    if (!(ray.tmin <= ray.tmax)) return {0, 0, 0};  // a lens's pixel that sees nothing
    // Inline: the Whitted case without the frame of the diagnostic modes.
    if (mode_ == RenderMode::kWhitted) return whitted(ray, 0, state);
    return li_diagnostic(ray, state);
  }

  /// li() for a primary ray whose nearest hit the caller found: `found` and `hit` as
  /// scene.intersect(ray, hit) gives them. The same value and ray count as li(ray, state)
  /// (camera-ray packets, render/camera_packets.h).
  Color li_hit(const Ray& ray, bool found, const SceneHit& hit, SampleState& state) const;

  /// How the Whitted recursion runs: kPlain without a recorder (a render: no trace of the
  /// recorder in its code), kCount keeping only state.recorder->counts (RayRecorder::events
  /// false), kRecord also calling the recorder's hooks.
  enum TraceMode { kPlain, kCount, kRecord };

  /// Whitted radiance along a ray `depth` secondary bounces deep (primary rays: 0) whose
  /// radiance reaches the pixel multiplied by `weight` (primary rays: 1); its reflected and
  /// refracted rays are traced only when their weight is at least render.bailout.
  Color whitted(const Ray& ray, int depth, SampleState& state, double weight = 1) const;

  /// The fraction of light that reaches `from` (a surface point, already offset) from `to` along
  /// the straight segment between them: 0 when an opaque object blocks it, else the product of
  /// transmission * C over the transmissive objects on it, each object counted once. With
  /// `to_infinity`, `to` is a direction and the segment is a half-line.
  Color shadow(const Vec3& from, const Vec3& to, bool to_infinity, SampleState& state) const;

 private:
  /// whitted() in one mode for the whole recursion (TraceMode).
  /// `medium`: the fading interior the ray starts in (its radiance is attenuated by the distance
  /// to its hit, interior_fade), or nullptr.
  template <TraceMode M>
  Color trace(const Ray& ray, int depth, SampleState& state, double weight,
              const Material* medium = nullptr) const;
  /// What a ray that hits nothing brings: the background, or the sky sphere across the fogs.
  Color missed(const Ray& ray) const {
    return atmosphere_ ? miss_color(*atmosphere_, scene_.render.background, ray)
                       : scene_.render.background;
  }
  /// Radiance c leaving a hit at ray parameter t, as it arrives across the rainbows and fogs.
  Color fogged(const Ray& ray, double t, const Color& c) const {
    return veils_ ? veiled(*atmosphere_, ray, t * length(ray.d), c) : c;
  }
  /// trace() for a reflected or refracted ray: in kRecord with RayRecorder::camera_ray_only, the
  /// ray is announced and its subtree traced in kCount.
  template <TraceMode M>
  /// `mirrored`: whether the ray is a mirrored one (SampleState::mirrored, for the ray's
  /// subtree).
  [[gnu::always_inline]] Color trace_child(const Ray& ray, int depth, SampleState& state,
                                           double weight, const Material* medium,
                                           bool mirrored) const;
  /// li() for the modes other than kWhitted.
  Color li_diagnostic(const Ray& ray, SampleState& state) const;
  /// li_diagnostic() after its query (found, hit: scene.intersect's answer); counts no ray.
  Color diagnostic_hit(const Ray& ray, bool found, const SceneHit& hit) const;
  /// whitted() after its query, for a ray that hit (hit: scene.intersect's answer); counts no
  /// ray for it (its shadow and secondary rays are counted). Inlined into whitted() and li_hit()
  /// (as a call it cost whitted 1% more instructions).
  template <TraceMode M>
  [[gnu::always_inline]] Color whitted_hit(const Ray& ray, const SceneHit& hit, int depth,
                                           SampleState& state, double weight) const;
  /// The shadow segment's passage through object `index`: false when an opaque part of it
  /// crosses the segment; else true, with `through` multiplied by the object's filter when the
  /// segment crosses it (once per object).
  bool passes(std::uint32_t index, const Ray& segment, Color& through) const;
  /// passes() for an object with materials per part or a textured transmissive one: a walk of
  /// its crossings.
  bool passes_walk(std::uint32_t index, const Ray& segment, Color& through) const;
  /// passes() for an object whose interior fades light: the filter of its kind, then the fade
  /// over the length of the segment inside it.
  bool passes_fading(std::uint32_t index, const Ray& segment, Color& through) const;
  /// Whether the segment crosses object `index` (occluded(), with planes and spheres called
  /// directly).
  bool crosses(std::uint32_t index, const Ray& segment) const;
  /// (u, v) only for a material with an image texture.
  SurfaceNeeds needs(const SceneHit& hit) const { return needs(material_index(hit)); }
  SurfaceNeeds needs(std::size_t material) const;
  /// The index in scene.materials of the part hit (as Scene::material_of).
  std::size_t material_index(const SceneHit& hit) const;
  /// The lights' direct term at si; shadow rays on the shading normal's side leave from `lit`
  /// (render/terminator.h), the others from si. `exponent`: m.shininess as an integer (0: not
  /// one, std::pow). Adds the lights' sum to `result` in one addition (`result += sum`).
  /// With kTextured, the terms come from `look` (a textured material's point: finish_terms) and
  /// m, exponent and c are not used.
  template <TraceMode M, bool kTextured = false>
  void direct(const SurfaceInfo& si, const SurfaceInfo& lit, const Vec3& n, const Vec3& v,
              const Material& m, unsigned exponent, const Color& c, SampleState& state,
              Color& result, const texture::SurfaceLook* look = nullptr) const;
  /// whitted_hit() for a material with a texture (Material::texture): the texture's colour,
  /// normal and finish at the hit, its reflection (min, max, Fresnel or falloff) and what it lets
  /// through. Kept out of whitted_hit so that plain materials keep their code.
  template <TraceMode M>
  Color textured_hit(const Ray& ray, const SceneHit& hit, std::size_t material, int depth,
                     SampleState& state, double weight) const;
  /// The refracted light at a dispersive surface: one ray per band of m's spectrum, each bent by
  /// its band's index (a band bent past the critical angle is reflected), their radiances in
  /// their shares of white, the whole times w_refract and tint.
  template <TraceMode M>
  Color dispersed(const SurfaceInfo& si, const Vec3& wi, const Vec3& n, const Material& m,
                  bool outside, int depth, SampleState& state, double weight, double w_refract,
                  const Color& tint) const;
  /// direct()'s light term (sample: its light, l, N.L, diffuse and specular parts) in the
  /// counting and recording modes: when `term` is above 0, the render's shadow query for it from
  /// `o`, counted, and the term added to `sum` when visible; the sample (with its shadow ray) told
  /// to the recorder (kRecord).
  template <TraceMode M>
  void light_recorded(LightSample sample, const Vec3& o, const Vec3& target, bool at_infinity,
                      const DirectionLists* lists, const Color& term, SampleState& state,
                      Color& sum) const;
  /// shadow() for a scene with no transmissive material: whether an object blocks the segment
  /// (visibility 0) or not (1).
  bool blocked(const Vec3& from, const Vec3& to, bool to_infinity, SampleState& state) const;
  /// blocked() for a segment to the apex of `lists` (a point or spot light's direction lists,
  /// ObjectSet::any_along_to): the same answer from fewer ball tests.
  bool blocked_to(const Vec3& from, const DirectionLists& lists, SampleState& state) const;
  /// shadow() for a scene with transmissive materials, without the call: false when the segment
  /// is blocked, else true with `through` (given as {1, 1, 1}) multiplied by the filters of the
  /// transmissive objects crossed (then some channel is above 0).
  bool filters(const Vec3& from, const Vec3& to, bool to_infinity, SampleState& state,
               Color& through) const;
  /// filters() for a segment to the apex of `lists`, as blocked_to.
  bool filters_to(const Vec3& from, const DirectionLists& lists, SampleState& state,
                  Color& through) const;

  /// What the shading asks of each scene object, worked out once per frame (the same answers
  /// the per-hit look-ups would give).
  struct ObjectFacts {
    std::int32_t material = 0;  // its material index; -1 for CSG and instances (per part)
    // The material index of every hit on it (material_index), also for a composite whose parts
    // all resolve to one material; -1 where it depends on the part hit.
    std::int32_t hit_material = 0;
    bool terminator = false;  // has_terminator_origin: shadow rays may start from terminator_origin
    // passes()'s case; kPass: the object casts no shadow
    enum Shadow : std::uint8_t { kOpaque, kFilter, kWalk, kPass } shadow = kOpaque;
    // The shape when it is an untransformed plane or sphere (crosses() calls it directly).
    const Plane* plane = nullptr;
    const Sphere* sphere = nullptr;
    // Its material when light fading inside it (Material::fade_distance) dims shadow rays.
    const Material* fade = nullptr;
    bool hidden_from_camera = false, hidden_from_reflections = false;  // Object::seen_*
  };
  /// After the nearest hit of a camera ray (`camera`) or another ray: when the object hit is
  /// hidden from rays of its kind (Object::seen_by_camera, seen_in_reflections; a ray is mirrored
  /// when SampleState::mirrored), the ray is cast again from just beyond the hit, until a hit it
  /// may see (true, in `hit`) or none (false). Rays through more hidden surfaces than
  /// kMaxHiddenSkips see nothing.
  bool seen(const Ray& ray, SceneHit& hit, bool camera, const SampleState& state) const;
  static constexpr int kMaxHiddenSkips = 64;

  const Scene& scene_;
  RenderMode mode_;
  std::vector<std::shared_ptr<const ImageTexture>> textures_;
  std::vector<ObjectFacts> objects_;  // by index in scene.objects
  std::vector<Color> filters_;        // by material: transmission * color (shadow filter)
  std::vector<Color> emitted_;        // by light: Light::emitted()
  std::vector<unsigned> exponents_;   // by material: integer Phong exponent, 0 for std::pow
  bool any_transmissive_ = false;
  bool any_hidden_ = false;                 // an object hidden from camera or mirrored rays
  const Atmosphere* atmosphere_ = nullptr;  // null: neither sky sphere nor fog
  bool veils_ = false;                      // fogs or rainbows over every segment
  // By light: the scene's direction lists around it (ObjectSet::light_lists), or nullptr.
  std::vector<const DirectionLists*> light_lists_;
};

}  // namespace raycast
