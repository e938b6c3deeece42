#pragma once
#include <cstdint>

#include "math/float_error.h"
#include "math/vec3.h"

namespace raycast {

/// The cheap record of a ray crossing a surface, kept during traversal: the ray parameter, the
/// primitive (triangle index, or -1), which part of the shape (a box face, a cap; shape-defined)
/// and two shape-defined local coordinates (barycentrics, ...). `surface` expands it once, for
/// the hit finally kept. A crossing at t = +-inf with part kNoSurface marks the open end of an
/// unbounded solid's span. Composite objects use `leaf` (which of their flattened leaves made the
/// hit) and `flip` (the normal must be reversed: a subtracted solid's surface); instances use
/// `inner` (which object of their shared prototype made the hit).
struct LocalHit {
  double t = kInfinity;
  std::int32_t prim = -1;
  std::int32_t part = 0;
  double a = 0;
  double b = 0;
  std::int32_t leaf = -1;
  bool flip = false;
  std::int32_t inner = -1;  // instances: which object of the shared prototype made the hit
};

inline constexpr std::int32_t kNoSurface = -1;

/// The full surface record at a hit, in the space of the ray that produced it.
struct SurfaceInfo {
  Vec3 p;  // the hit point
  Vec3 n;  // unit geometric normal, out of the solid (docs/scene-format.md: open surfaces' sides)
  Vec3 shading_n;  // unit shading normal (interpolated for smooth meshes), same side as n
  double u = 0;    // surface parameters as docs/scene-format.md defines them per shape
  double v = 0;
  Vec3 p_error;  // absolute error bound on p per component, for offsetting secondary rays
};

}  // namespace raycast
