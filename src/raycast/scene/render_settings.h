#pragma once
#include <memory>
#include <optional>

#include "math/vec3.h"
#include "scene/atmosphere.h"
#include "scene/render_mode.h"

namespace raycast {

/// The projections of docs/scene-format.md "Cameras": the pinhole and parallel ones, and
/// POV-Ray's fisheye, ultra-wide-angle, omnimax, panoramic, cylindrical and spherical lenses.
enum class CameraType {
  kPerspective,
  kOrthographic,
  kFisheye,
  kUltraWideAngle,
  kOmnimax,
  kPanoramic,
  kCylinder,
  kSpherical
};

/// A camera's own vectors as POV-Ray states them: the image's centre is `direction` away from
/// the camera, `right` and `up` span the whole image (their lengths are its size, their ratio
/// its aspect; they need not be perpendicular nor unit length).
struct CameraFrame {
  Vec3 direction{0, 0, -1};
  Vec3 right{4.0 / 3.0, 0, 0};
  Vec3 up{0, 1, 0};
};

struct CameraDesc {
  CameraType type = CameraType::kPerspective;
  Vec3 position{0, 0, 1};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov = 40;    // perspective: vertical field of view, degrees, in (0, 180)
  double height = 2;  // orthographic: full view height in scene units
  // The lenses: the horizontal field in degrees (fisheye: the circle's diameter), in (0, 360];
  // spherical also a vertical one (0: half the horizontal), cylinder its kind 1 to 4.
  double angle = 180;
  double vertical_angle = 0;
  int cylinder = 1;
  /// When set, the frame replaces look_at, up, fov and height (POV-Ray scenes): its vectors, as
  /// given, decide the view and the image's aspect, whatever the image's size.
  std::optional<CameraFrame> frame;
};

/// Whether every primary ray starts at the camera's position (all but the orthographic camera
/// and the cylinders whose viewpoint moves along the axis).
inline bool rays_share_origin(const CameraDesc& c) {
  return c.type != CameraType::kOrthographic &&
         !(c.type == CameraType::kCylinder && (c.cylinder == 3 || c.cylinder == 4));
}

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
  // The sky sphere and fogs (scene/atmosphere.h); null when the scene has neither, which keeps
  // the background's plain path.
  std::shared_ptr<const Atmosphere> atmosphere;
  Vec3 ambient{0, 0, 0};
  unsigned seed = 0;
  AntialiasSettings antialias;
};

}  // namespace raycast
