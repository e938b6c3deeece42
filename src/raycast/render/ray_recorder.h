#pragma once
// What the Whitted integrator tells an observer while it traces one sample: every ray it casts,
// what the ray hit, the shading terms and how the recursion went on or stopped. `raycast
// explain` builds the ray tree from it, the statistics and term outputs sum it up per pixel. The
// integrator calls a recorder only through SampleState::recorder, which is null in an ordinary
// render: then each hook costs one predicted branch.
#include <cstddef>
#include <cstdint>

#include "geometry/hit.h"
#include "geometry/ray.h"
#include "math/vec3.h"
#include "scene/material.h"

namespace raycast {

struct SceneHit;

/// Why a ray was cast (shadow rays are announced through RayRecorder::light instead).
enum class RayKind { kCamera, kReflection, kRefraction };

/// Why a ray's recursion ended where it did.
enum class RayStop {
  kNone,      // it went on (children were traced, or the surface reflects and refracts nothing)
  kMaxDepth,  // render.max_depth was reached: no secondary rays
  kMiss,      // nothing was hit: the background
};

/// One light's part of the direct term at a hit, as the integrator computed it.
struct LightSample {
  std::size_t light = 0;    // index in Scene::lights
  Vec3 l;                   // unit direction from the hit towards the light
  double n_dot_l = 0;       // with the normal facing the viewer
  Color diffuse;            // E * diffuse * C * N.L, before visibility
  Color specular;           // E * specular * max(0, R.V)^shininess, before visibility
  bool shadow_ray = false;  // false: no shadow ray (N.L <= 0 or a zero term)
  Ray shadow;               // the shadow segment: o + t d, t in [0, 1] (or [0, inf) to infinity)
  Color visibility;         // what reached the hit through the segment: 0 blocked, 1 free
};

/// Rays cast by kind (shadow rays: those actually cast, one per light term above 0).
struct RayCounts {
  std::uint64_t camera = 0, reflection = 0, refraction = 0, shadow = 0;
  int max_depth = 0;  // the deepest secondary ray
  std::uint64_t total() const { return camera + reflection + refraction + shadow; }
};

/// The observer's hooks, in the order the integrator calls them for one ray:
/// begin_ray; then miss, or hit, ambient, light (once per light term), split, and for each
/// traced secondary ray a nested begin_ray ... end_ray after `child`; then end_ray.
class RayRecorder {
 public:
  virtual ~RayRecorder() = default;
  /// Kept by the integrator itself while the recorder is attached.
  RayCounts counts;
  /// false: only `counts` is kept and no hook is called (the integrator's cheaper counting mode).
  bool events = true;
  /// true: hooks only for the camera ray; its secondary rays report begin_ray and end_ray (so
  /// their radiance reaches the camera ray's terms) and are traced below in the counting mode.
  bool camera_ray_only = false;
  /// The next begin_ray is a secondary ray of this kind carrying `weight` of its parent, its
  /// radiance tinted by `tint` (white but behind a coloured filter or for a dispersed band).
  virtual void child(RayKind kind, double weight, const Color& tint) = 0;
  /// A ray is cast (the first of a sample is a camera ray).
  virtual void begin_ray(const Ray& ray, int depth) = 0;
  virtual void miss(const Color& background) = 0;
  /// Its nearest hit: the surface record, the material index, whether the ray arrived from the
  /// outside of the surface and the normal facing the viewer.
  virtual void hit(const SceneHit& hit, const SurfaceInfo& si, std::size_t material, bool outside,
                   const Vec3& n) = 0;
  virtual void ambient(const Color& term) = 0;
  virtual void light(const LightSample& sample) = 0;
  /// The split between the mirror and the refracted ray: the weights after Fresnel and total
  /// internal reflection (`tir`), the Fresnel reflectance (-1 without fresnel), and the render's
  /// bailout below which a weighted ray is not traced.
  virtual void split(double w_reflect, double w_refract, bool tir, double fresnel,
                     double bailout) = 0;
  virtual void stop(RayStop why) = 0;
  /// The ray's radiance (its children's already weighted in).
  virtual void end_ray(const Color& radiance) = 0;
};

}  // namespace raycast
