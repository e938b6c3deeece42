#pragma once
// Text: a string's letters, each a prism (its outline swept along z).
#include <vector>

#include "geometry/prism.h"
#include "geometry/shape.h"

namespace raycast {

/// The letters of a string as solids: each letter is a linear prism of its font outline (the
/// even-odd rule, which fonts' outer and inner contours follow), with its own box, so a ray tests
/// only the letters whose boxes it meets. The solid is their union. Hits carry the letter's index
/// in `prim`; (u, v) are the letter prism's.
struct Text {
  static constexpr const char* kName = "text";
  std::vector<Prism> letters;
  Aabb box;
};

/// The text of the given letters; throws std::invalid_argument when there are none (a string of
/// spaces draws nothing).
Text make_text(std::vector<Prism> letters);

Aabb bounds(const Text& s);
bool intersect(const Text& s, const Ray& ray, LocalHit& hit);
bool occluded(const Text& s, const Ray& ray);
void spans(const Text& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Text& s, const Ray& ray, const LocalHit& hit);
bool contains(const Text& s, const Vec3& p);
inline bool is_closed(const Text&) { return true; }

}  // namespace raycast
