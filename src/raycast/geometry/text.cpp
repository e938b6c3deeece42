#include "geometry/text.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace raycast {

namespace {

bool meets_box(const Prism& p, const Ray& ray, const Vec3& inv_d) {
  double t0, t1;
  return slab_interval(p.box, ray.o, inv_d, t0, t1) && t1 >= ray.tmin && t0 <= ray.tmax;
}

}  // namespace

Text make_text(std::vector<Prism> letters) {
  if (letters.empty()) throw std::invalid_argument("the text has no letter to draw");
  Text t;
  for (const Prism& p : letters) {
    if (p.open) throw std::invalid_argument("a letter must be a closed prism");
    t.box.grow(p.box.lo);
    t.box.grow(p.box.hi);
  }
  t.letters = std::move(letters);
  return t;
}

Aabb bounds(const Text& s) { return s.box; }

bool intersect(const Text& s, const Ray& ray, LocalHit& hit) {
  const Vec3 inv_d = reciprocal(ray.d);
  Ray r = ray;
  bool found = false;
  for (std::size_t i = 0; i < s.letters.size(); ++i) {
    if (!meets_box(s.letters[i], r, inv_d)) continue;
    LocalHit h;
    if (!intersect(s.letters[i], r, h)) continue;
    h.prim = static_cast<std::int32_t>(i);
    hit = h;
    r.tmax = h.t;  // later letters must be nearer
    found = true;
  }
  return found;
}

bool occluded(const Text& s, const Ray& ray) {
  const Vec3 inv_d = reciprocal(ray.d);
  for (const Prism& p : s.letters) {
    LocalHit h;
    if (meets_box(p, ray, inv_d) && intersect(p, ray, h)) return true;
  }
  return false;
}

void spans(const Text& s, const Ray& ray, SpanList& out) {
  // Each letter's spans, tagged, then merged where letters overlap (tight kerning).
  const Vec3 inv_d = reciprocal(ray.d);
  Ray whole = ray;
  whole.tmin = -kInfinity;
  whole.tmax = kInfinity;
  SpanList all, one;
  for (std::size_t i = 0; i < s.letters.size(); ++i) {
    if (!meets_box(s.letters[i], whole, inv_d)) continue;
    one.clear();
    spans(s.letters[i], ray, one);
    for (Span sp : one) {
      sp.in.prim = sp.out.prim = static_cast<std::int32_t>(i);
      all.push_back(sp);
    }
  }
  std::sort(all.begin(), all.end(), [](const Span& a, const Span& b) { return a.in.t < b.in.t; });
  const std::size_t first = out.size();
  for (const Span& sp : all) {
    if (out.size() > first && sp.in.t <= out.back().out.t) {
      if (sp.out.t > out.back().out.t) out.back().out = sp.out;
    } else {
      out.push_back(sp);
    }
  }
}

SurfaceInfo surface(const Text& s, const Ray& ray, const LocalHit& hit) {
  return surface(s.letters[static_cast<std::size_t>(hit.prim)], ray, hit);
}

bool contains(const Text& s, const Vec3& p) {
  if (!s.box.contains(p)) return false;
  for (const Prism& l : s.letters)
    if (contains(l, p)) return true;
  return false;
}

}  // namespace raycast
