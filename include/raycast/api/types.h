#pragma once
// The plain value types of raycast's public API (docs/library.md). They hold no internal type:
// the engine behind them is reached only through raycast::Scene (include/raycast/api/scene.h).
// Users include <raycast/raycast.h>, which names these types in namespace raycast.
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace raycast::api {

using Vec3d = std::array<double, 3>;

/// An object of a scene: the index of its top-level entry (the `objects` entry of a scene file, or
/// the order of add_* calls), as `raycast cast` reports it.
using ObjectId = std::int32_t;
inline constexpr ObjectId kNoObject = -1;

/// The ray origin + t * direction with t in the closed interval [tmin, tmax]. The direction need
/// not be unit length and t is measured in units of it.
struct Ray {
  Vec3d origin{0, 0, 0};
  Vec3d direction{0, 0, 1};
  double tmin = 0;
  double tmax = std::numeric_limits<double>::infinity();
};

/// The nearest hit of a ray, in world space. A miss has object == kNoObject, t = +inf and NaN in
/// every other number.
struct SurfaceInfo {
  double t = std::numeric_limits<double>::infinity();
  Vec3d point{};
  Vec3d normal{};  // unit, out of the solid (for open surfaces see docs/scene-format.md)
  std::array<double, 2> uv{};
  ObjectId object = kNoObject;
  std::int32_t primitive = -1;  // triangle index of a mesh (input order), else -1
  bool hit() const { return object != kNoObject; }
};

/// One boundary crossing along a ray (intersect_all): its t, the unit outward normal there and
/// the object it belongs to.
struct Crossing {
  double t = 0;
  Vec3d normal{};
  ObjectId object = kNoObject;
};

/// Rays stored as six numbers each, [ox, oy, oz, dx, dy, dz], of float or double, in any strided
/// layout: component k of ray i is at byte offset i * ray_stride + k * component_stride from
/// data. Interleaved arrays and structures of arrays are both views of this kind. tmin/tmax apply
/// to every ray.
struct RayArray {
  enum class Type { kFloat32, kFloat64 };
  const void* data = nullptr;
  Type type = Type::kFloat64;
  std::size_t count = 0;
  std::ptrdiff_t ray_stride = 0;        // bytes between rays
  std::ptrdiff_t component_stride = 0;  // bytes between the six numbers of one ray
  double tmin = 0;
  double tmax = std::numeric_limits<double>::infinity();

  /// n rays of 6 contiguous doubles each.
  static RayArray interleaved(const double* rays, std::size_t n);
  /// n rays of 6 contiguous floats each.
  static RayArray interleaved(const float* rays, std::size_t n);
  /// Six arrays of n doubles one after the other (ox[0..n), oy[0..n), ...).
  static RayArray soa(const double* components, std::size_t n);
};

/// Where batch intersect writes its answers, one entry per ray; a null pointer skips that output
/// (and skips computing the surface record when point, normal and uv are all null). Misses get
/// t = +inf, object = kNoObject, primitive = -1 and NaN elsewhere.
struct HitColumns {
  double* t = nullptr;                // n
  ObjectId* object = nullptr;         // n
  std::int32_t* primitive = nullptr;  // n
  double* point = nullptr;            // 3n
  double* normal = nullptr;           // 3n
  double* uv = nullptr;               // 2n
};

/// An affine object-to-world transform as a 4x4 row-major matrix (translation in the last
/// column). The last row must be [0, 0, 0, 1] and the matrix invertible.
struct Transform {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  static Transform translate(const Vec3d& t);
  static Transform scale(const Vec3d& s);
  /// A rotation by `degrees` about `axis` (right-hand rule).
  static Transform rotate(const Vec3d& axis, double degrees);
  /// This transform applied after `inner`: (a * b)(p) = a(b(p)).
  friend Transform operator*(const Transform& a, const Transform& b);
};

/// Surface appearance for rendering (docs/rendering.md); colours are linear RGB.
/// SPH particles as an iso-surface (docs/iso-surfaces.md, the `isosurface` scene key with
/// `particles`): the density rho = sum V rest_density W(r, h) (cubic spline kernel) is splatted
/// to a grid and the solid is {rho > iso}. Unset fields take the scene format's defaults.
struct ParticleSurface {
  double smoothing_length = 0;                   // h, > 0 (required)
  double rest_density = 1000;                    // > 0
  std::optional<double> particle_volume;         // V, default (h / 1.3)^3
  std::optional<double> iso;                     // >= 0, default rest_density / 2
  std::optional<std::array<Vec3d, 2>> domain;    // min, max; default: particles' box + 2h
  std::optional<std::array<int, 3>> resolution;  // nodes per axis (>= 2) over the domain
  std::optional<double> cell_size;               // default h / 2 (without resolution)
};

/// A scalar grid as an iso-surface (the `isosurface` scene key with `grid`): node (i, j, k) at
/// origin + (i, j, k) * spacing holds values[i + nx * (j + ny * k)] (x fastest), trilinear in
/// each cell, 0 outside the grid; the solid is {field > iso}.
struct GridSurface {
  std::array<int, 3> counts{};  // nodes per axis, >= 2
  Vec3d origin{0, 0, 0};
  Vec3d spacing{1, 1, 1};  // > 0
  double iso = 0;          // >= 0
};

struct Material {
  Vec3d color{0.8, 0.8, 0.8};
  double ambient = 1, diffuse = 0.8, specular = 0, shininess = 32;
  double reflection = 0, transmission = 0, ior = 1;
  bool fresnel = false;
  bool checker = false;  // a checkerboard of checker_colors with cells of checker_scale
  std::array<Vec3d, 2> checker_colors{Vec3d{0.9, 0.9, 0.9}, Vec3d{0.2, 0.2, 0.2}};
  double checker_scale = 1;
};
using MaterialId = std::int32_t;  // 0 is the default material

struct Light {
  enum class Type { kPoint, kDirectional, kSpot, kSphere };
  Type type = Type::kPoint;
  Vec3d color{1, 1, 1};
  double intensity = 1;
  Vec3d position{0, 0, 0};         // point, spot, sphere (centre)
  Vec3d direction{0, -1, 0};       // directional, spot
  double angle = 30, falloff = 5;  // spot, degrees
  double radius = 0;               // sphere
  int samples = 16;                // sphere
  bool inverse_square = false;     // attenuation
};

struct Camera {
  bool orthographic = false;
  Vec3d position{0, 0, 1};
  Vec3d look_at{0, 0, 0};
  Vec3d up{0, 1, 0};
  double fov = 40;    // perspective: vertical field of view in degrees, in (0, 180)
  double height = 2;  // orthographic: full view height
};

struct RenderOptions {
  int width = 0;           // 0: the scene's image.width (640 unless the file says otherwise)
  int height = 0;          // 0: the scene's
  int samples = 0;         // samples per pixel; 0: the scene's
  std::string integrator;  // whitted, raycast, depth, normal or id; empty: the scene's
  int threads = 0;         // > 0 caps the worker threads
  /// Only the pixels [x0, x1) x [y0, y1) of the full image, as {x0, y0, x1, y1}: the image is
  /// the rectangle's size and each of its pixels equals the whole render's. Unset: all.
  std::optional<std::array<int, 4>> region;
};

/// A linear-light RGB image, row-major, top row first: rgb[3 * (y * width + x) + c].
struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;
};

/// Bad user input (a scene file, a shape's parameters): where it is and what was expected.
/// file is a path, or the name of the call for scenes built in code; line and column are
/// 1-based, 0 when unknown.
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& what, std::string file, int line, int column, std::string message)
      : std::runtime_error(what),
        file_(std::move(file)),
        line_(line),
        column_(column),
        message_(std::move(message)) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_, column_;
  std::string message_;
};

/// A query the scene's shape cannot answer (a distance to a shape without a closed form).
class NotImplementedError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace raycast::api
