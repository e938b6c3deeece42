#pragma once
// Blobs (POV-Ray's blob): the iso-surface of a sum of smooth, compactly supported fields of
// spheres and cylinders, intersected exactly piece by piece along the ray.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "math/transform.h"

namespace raycast {

/// The most components a blob may have (its hierarchy's depth and the per-ray work stay bounded).
inline constexpr std::size_t kMaxBlobComponents = 1000000;

/// One source of the field. At distance d from its centre `a` (a sphere) or from its axis segment
/// [a, b] (a cylinder, so its ends are hemispheres) it adds strength * (1 - (d / radius)^2)^2
/// for d < radius and nothing beyond. `xf` places it in the blob (component -> blob space),
/// absent for the identity; d is measured in the component's own space, so a scale makes an
/// ellipsoidal field. The strength may be negative.
struct BlobComponent {
  Vec3 a, b;
  double radius = 1;
  double strength = 1;
  bool cylinder = false;
  std::optional<Transform> xf;
  int material = -1;  // the scene's material where this component's field is the strongest; -1:
                      // the object's
};

/// The solid where the summed field exceeds `threshold` (> 0, so it lies within the components
/// of positive strength). Along a line each component's d^2 is quadratic in t (a sphere, a
/// cylinder's body, each end's hemisphere: a cylinder gives up to three pieces), so the field is
/// a quartic on each stretch between the pieces' ends; each stretch's quartic, written about its
/// midpoint, is solved by the isolating solver (math/polynomial_solver.h). A median-split box
/// hierarchy over the components finds those a ray meets. The normal is the field's gradient,
/// reversed; (u, v) are 0 (POV-Ray gives blobs no surface parameters). A hit's `part` is its
/// strongest component (the one whose material it takes) when some component has a material.
struct Blob {
  static constexpr const char* kName = "blob";
  struct Part {
    BlobComponent c;
    Vec3 axis;          // cylinder: unit direction from a to b
    double length = 0;  // cylinder: |b - a|
    double r2 = 1;      // radius^2
    double k = 1;       // strength / radius^4: the field is k (r2 - d^2)^2
  };
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // a leaf's parts order[first .. first + count); else its children
    std::uint32_t count = 0;  // first and first + 1
  };
  struct Data {
    double threshold = 1;
    std::vector<Part> parts;
    std::vector<Node> nodes;  // nodes[0] is the root
    std::vector<std::uint32_t> order;
    Aabb box;                // the parts of positive strength: the solid lies inside
    bool materials = false;  // some component has a material of its own
    double window = 0;       // intersect's step along the ray (blob space units)
  };
  std::shared_ptr<const Data> data;
};

/// A validated blob: threshold > 0 and finite; 1 to kMaxBlobComponents components, each with a
/// finite radius > 0 and finite strength, at least one positive; a cylinder whose ends coincide
/// is a sphere. Throws std::invalid_argument naming the cause (with the component's index).
Blob make_blob(double threshold, std::vector<BlobComponent> components);

Aabb bounds(const Blob& s);
bool intersect(const Blob& s, const Ray& ray, LocalHit& hit);
void spans(const Blob& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Blob& s, const Ray& ray, const LocalHit& hit);
bool contains(const Blob& s, const Vec3& p);
inline bool is_closed(const Blob&) { return true; }

/// The material of a hit (of intersect or spans): its strongest component's, or -1 (the
/// object's). POV-Ray blends the components' textures by their fields; raycast takes the
/// strongest one's.
int blob_material(const Blob& s, const LocalHit& hit);

/// The summed field at p (blob space); the solid is where it exceeds the threshold.
double blob_field(const Blob& s, const Vec3& p);

}  // namespace raycast
