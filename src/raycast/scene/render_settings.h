#pragma once
#include "math/vec3.h"
#include "scene/render_mode.h"

namespace raycast {

enum class CameraType { kPerspective, kOrthographic };

struct CameraDesc {
  CameraType type = CameraType::kPerspective;
  Vec3 position{0, 0, 1};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov = 40;    // perspective: vertical field of view, degrees, in (0, 180)
  double height = 2;  // orthographic: full view height in scene units
};

struct ImageSettings {
  int width = 640;
  int height = 480;
  int samples = 1;
};

/// The largest image raycast renders: width * height at most 2^28 pixels (3 GiB of float RGB);
/// each side is at most 2^16. Larger requests are refused before anything is allocated.
inline constexpr long long kMaxImagePixels = 1LL << 28;
inline constexpr int kMaxImageSide = 1 << 16;

/// Adaptive antialiasing (docs/rendering.md "Adaptive antialiasing"): none (the image's fixed
/// `samples`), POV-Ray's method 1 (neighbour-threshold supersampling), method 2 (recursive
/// subdivision of the pixel from its corners) or a variance-driven sampler.
enum class AntialiasMethod { kNone, kNeighbour, kSubdivide, kVariance };

struct AntialiasSettings {
  AntialiasMethod method = AntialiasMethod::kNone;
  double threshold = 0.3;  // colour distance (sum of |channel difference|) that triggers refining
  int depth = 3;           // method 1 and variance: depth x depth samples at most; method 2: levels
};

struct RenderSettings {
  RenderMode integrator = RenderMode::kWhitted;  // never kAlbedo (not an integrator)
  int max_depth = 5;
  double bailout = 1.0 / 255;  // secondary rays of accumulated weight below this are not traced
  Vec3 background{0, 0, 0};
  Vec3 ambient{0, 0, 0};
  unsigned seed = 0;
  AntialiasSettings antialias;
};

}  // namespace raycast
