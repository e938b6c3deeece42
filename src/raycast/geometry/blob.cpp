#include "geometry/blob.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/crossing_list.h"
#include "math/polynomial_solver.h"

namespace raycast {

namespace {

using Part = Blob::Part;
using Node = Blob::Node;
using Data = Blob::Data;

constexpr std::uint32_t kLeafSize = 4;
// Median splits halve the parts at every level: kMaxBlobComponents parts stay below this depth.
constexpr int kStackSize = 64;

// Where a piece's d^2 is measured from: the sphere about a, the cylinder's body (distance to
// the axis line), the sphere about b (the cylinder's far end).
enum class PieceKind : std::uint8_t { kAboutA, kBody, kAboutB };

// One quadratic piece of a component's d^2 along the line: t in [lo, hi], the line in the
// component's space.
struct Piece {
  double lo, hi;
  Vec3 o, d;
  std::uint32_t part;
  PieceKind kind;
};

struct Event {
  double t;
  std::uint32_t piece;
  bool start;
};

// Per-thread buffers of the sweep: a blob query allocates only while they grow.
struct Scratch {
  std::vector<Piece> pieces;
  std::vector<Event> events;
  std::vector<std::uint32_t> active;
  std::vector<CurveCrossing> crossings;
};

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

Aabb part_box(const Part& p) {
  const double r = p.c.radius;
  Aabb b{p.c.a - Vec3{r, r, r}, p.c.a + Vec3{r, r, r}};
  if (p.c.cylinder) b.grow(Aabb{p.c.b - Vec3{r, r, r}, p.c.b + Vec3{r, r, r}});
  return p.c.xf ? transform_bounds(*p.c.xf, b) : b;
}

// Median split on the longest axis of the centres, leaves of at most kLeafSize parts.
void build_node(Data& d, const std::vector<Aabb>& boxes, std::uint32_t index, std::uint32_t first,
                std::uint32_t count) {
  Aabb box, centres;
  for (std::uint32_t i = first; i < first + count; ++i) {
    box.grow(boxes[d.order[i]]);
    centres.grow(boxes[d.order[i]].centre());
  }
  d.nodes[index].box = box;
  if (count <= kLeafSize) {
    d.nodes[index].first = first;
    d.nodes[index].count = count;
    return;
  }
  const Vec3 e = centres.extent();
  const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
  const std::uint32_t half = count / 2;
  std::nth_element(d.order.begin() + first, d.order.begin() + first + half,
                   d.order.begin() + first + count, [&](std::uint32_t a, std::uint32_t b) {
                     return boxes[a].centre()[axis] < boxes[b].centre()[axis];
                   });
  const auto child = static_cast<std::uint32_t>(d.nodes.size());
  d.nodes[index].first = child;
  d.nodes[index].count = 0;
  d.nodes.resize(d.nodes.size() + 2);
  build_node(d, boxes, child, first, half);
  build_node(d, boxes, child + 1, first + half, count - half);
}

// Calls visit(part) for every part whose box the test accepts (a node test on boxes).
template <class BoxTest, class Visit>
void walk(const Data& d, const BoxTest& test, const Visit& visit) {
  std::uint32_t stack[kStackSize];
  int top = 0;
  if (!test(d.nodes[0].box)) return;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = d.nodes[stack[--top]];
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) visit(d.order[i]);
      continue;
    }
    for (std::uint32_t c = n.first; c < n.first + 2; ++c)
      if (test(d.nodes[c].box)) stack[top++] = c;
  }
}

// [lo, hi] where |o + t d - c|^2 <= r2 (o, d in the component's space); false when empty.
bool ball_interval(const Vec3& c, double r2, const Vec3& o, const Vec3& d, double& lo, double& hi) {
  const Vec3 q = o - c;
  const double dd = dot(d, d);
  const double tc = -dot(q, d) / dd;
  const Vec3 p = q + tc * d;
  const double h2 = (r2 - dot(p, p)) / dd;
  if (!(h2 > 0)) return false;
  const double h = std::sqrt(h2);
  lo = tc - h;
  hi = tc + h;
  return true;
}

// The line's t where the axial coordinate s = s0 + t sd is <= at (below) or >= at.
void clip_axial(double s0, double sd, double at, bool below, double& lo, double& hi) {
  if (sd == 0) {
    if (below ? !(s0 <= at) : !(s0 >= at)) lo = kInfinity, hi = -kInfinity;
    return;
  }
  const double t = (at - s0) / sd;
  if ((sd > 0) == below)
    hi = std::min(hi, t);
  else
    lo = std::max(lo, t);
}

// Appends the pieces of part i on the line o + t d (blob space) that meet [tlo, thi].
void add_pieces(const Data& data, std::uint32_t i, const Vec3& bo, const Vec3& bd, double tlo,
                double thi, std::vector<Piece>& out) {
  const Part& p = data.parts[i];
  const Vec3 o = p.c.xf ? p.c.xf->inverse_point(bo) : bo;
  const Vec3 d = p.c.xf ? p.c.xf->inverse_vector(bd) : bd;
  const auto push = [&](double lo, double hi, PieceKind kind) {
    if (lo < hi && hi >= tlo && lo <= thi) out.push_back({lo, hi, o, d, i, kind});
  };
  double lo, hi;
  if (!p.c.cylinder) {
    if (ball_interval(p.c.a, p.r2, o, d, lo, hi)) push(lo, hi, PieceKind::kAboutA);
    return;
  }
  const double s0 = dot(o - p.c.a, p.axis), sd = dot(d, p.axis);
  if (ball_interval(p.c.a, p.r2, o, d, lo, hi)) {
    clip_axial(s0, sd, 0, true, lo, hi);
    push(lo, hi, PieceKind::kAboutA);
  }
  if (ball_interval(p.c.b, p.r2, o, d, lo, hi)) {
    clip_axial(s0, sd, p.length, false, lo, hi);
    push(lo, hi, PieceKind::kAboutB);
  }
  // The body: within the infinite cylinder (the line's part across the axis, e, is what moves
  // it off the axis), and 0 <= s <= length.
  const Vec3 w = (o - p.c.a) - s0 * p.axis;
  const Vec3 e = d - sd * p.axis;
  const double ee = dot(e, e);
  if (ee > 0) {
    const double tc = -dot(w, e) / ee;
    const Vec3 wc = w + tc * e;
    const double h2 = (p.r2 - dot(wc, wc)) / ee;
    if (!(h2 > 0)) return;
    const double h = std::sqrt(h2);
    lo = tc - h, hi = tc + h;
  } else {
    if (!(dot(w, w) < p.r2)) return;
    lo = -kInfinity, hi = kInfinity;
  }
  clip_axial(s0, sd, 0, false, lo, hi);
  clip_axial(s0, sd, p.length, true, lo, hi);
  push(lo, hi, PieceKind::kBody);
}

// Collects the pieces of every part on the line that meet [tlo, thi], and their ends as events
// sorted by t.
void gather(const Data& data, const Ray& ray, double tlo, double thi, Scratch& s) {
  s.pieces.clear();
  s.events.clear();
  const Vec3 inv_d = reciprocal(ray.d);
  const auto test = [&](const Aabb& b) {
    double t;
    return intersect_slabs(b, ray.o, inv_d, tlo, thi, t);
  };
  walk(data, test, [&](std::uint32_t i) { add_pieces(data, i, ray.o, ray.d, tlo, thi, s.pieces); });
  for (std::uint32_t i = 0; i < s.pieces.size(); ++i) {
    s.events.push_back({s.pieces[i].lo, i, true});
    s.events.push_back({s.pieces[i].hi, i, false});
  }
  std::sort(s.events.begin(), s.events.end(),
            [](const Event& a, const Event& b) { return a.t < b.t; });
}

// k (r2 - d^2)^2 of one piece as a quartic in u = t - m, added to sum.
void add_field(const Data& data, const Piece& pc, double m, Polynomial& sum) {
  const Part& p = data.parts[pc.part];
  const Vec3 c = pc.kind == PieceKind::kAboutB ? p.c.b : p.c.a;
  Vec3 q = pc.o + m * pc.d - c;
  Vec3 d = pc.d;
  if (pc.kind == PieceKind::kBody) {
    q -= dot(q, p.axis) * p.axis;
    d -= dot(d, p.axis) * p.axis;
  }
  // d^2 = A u^2 + 2 B u + C, so r2 - d^2 = a2 u^2 + a1 u + a0.
  const double a2 = -dot(d, d), a1 = -2 * dot(q, d), a0 = p.r2 - dot(q, q);
  sum.c[4] += p.k * (a2 * a2);
  sum.c[3] += p.k * (2 * a2 * a1);
  sum.c[2] += p.k * (a1 * a1 + 2 * a2 * a0);
  sum.c[1] += p.k * (2 * a1 * a0);
  sum.c[0] += p.k * (a0 * a0);
}

// The quartic of the field minus the threshold on a stretch where `active` pieces apply, in
// u = t - m; false when the field cannot reach the threshold there (the positive strengths of
// the active parts sum below it).
bool stretch_quartic(const Data& data, const Scratch& s, double m, Polynomial& p) {
  double most = 0;
  for (const std::uint32_t i : s.active)
    most += std::max(0.0, data.parts[s.pieces[i].part].c.strength);
  if (!(most > data.threshold)) return false;
  p = Polynomial{};
  p.degree = 4;
  for (const std::uint32_t i : s.active) add_field(data, s.pieces[i], m, p);
  p.c[0] -= data.threshold;
  return true;
}

void apply(Scratch& s, const Event& e) {
  if (e.start) {
    s.active.push_back(e.piece);
    return;
  }
  const auto it = std::find(s.active.begin(), s.active.end(), e.piece);
  if (it != s.active.end()) {
    *it = s.active.back();
    s.active.pop_back();
  }
}

double part_field(const Part& p, const Vec3& blob_p) {
  const Vec3 q = p.c.xf ? p.c.xf->inverse_point(blob_p) : blob_p;
  Vec3 r = q - p.c.a;
  if (p.c.cylinder) r -= std::clamp(dot(r, p.axis), 0.0, p.length) * p.axis;
  const double g = p.r2 - dot(r, r);
  return g > 0 ? p.k * g * g : 0;
}

// The part whose field is the strongest at t among the active pieces (the hit's `part`), or 0
// when no component has a material of its own (nothing asks).
std::int32_t strongest(const Data& data, const Scratch& s, const Ray& ray, double t) {
  if (!data.materials) return 0;
  const Vec3 p = ray.at(t);
  std::int32_t best = 0;
  double most = -kInfinity;
  for (const std::uint32_t i : s.active) {
    const std::uint32_t part = s.pieces[i].part;
    const double f = part_field(data.parts[part], p);
    if (f > most) most = f, best = static_cast<std::int32_t>(part);
  }
  return best;
}

// Sweeps the stretches between consecutive events in increasing t, calling
// stretch(a, b, quartic in t - m, m) on those that meet [tlo, thi] where the field may reach the
// threshold; stops when it returns true or the stretches pass thi.
template <class Stretch>
void sweep(const Data& data, Scratch& s, double tlo, double thi, const Stretch& stretch) {
  s.active.clear();
  for (std::size_t k = 0; k + 1 < s.events.size(); ++k) {
    apply(s, s.events[k]);
    const double a = s.events[k].t, b = s.events[k + 1].t;
    if (a > thi) return;
    if (!(a < b) || b < tlo || s.active.empty()) continue;
    const double m = 0.5 * (a + b);
    Polynomial p;
    if (!stretch_quartic(data, s, m, p)) continue;
    if (stretch(a, b, p, m)) return;
  }
}

// The field's gradient at p (blob space).
Vec3 field_gradient(const Data& data, const Vec3& p) {
  Vec3 grad;
  walk(
      data, [&](const Aabb& b) { return b.contains(p); },
      [&](std::uint32_t i) {
        const Part& part = data.parts[i];
        const Vec3 q = part.c.xf ? part.c.xf->inverse_point(p) : p;
        Vec3 r = q - part.c.a;
        if (part.c.cylinder) r -= std::clamp(dot(r, part.axis), 0.0, part.length) * part.axis;
        const double g = part.r2 - dot(r, r);
        if (!(g > 0)) return;
        const Vec3 local = (-4 * part.k * g) * r;  // d/dq of k (r2 - |r|^2)^2
        grad += part.c.xf ? part.c.xf->normal(local) : local;
      });
  return grad;
}

Part make_part(const BlobComponent& c, std::size_t index) {
  const std::string which = "component " + std::to_string(index) + ": ";
  if (!(c.radius > 0) || !std::isfinite(c.radius))
    throw std::invalid_argument(which + "radius must be > 0 and finite");
  if (!std::isfinite(c.strength)) throw std::invalid_argument(which + "strength must be finite");
  if (!is_finite(c.a) || !is_finite(c.b))
    throw std::invalid_argument(which + "points must be finite");
  Part p;
  p.c = c;
  p.r2 = c.radius * c.radius;
  p.k = c.strength / (p.r2 * p.r2);
  if (c.cylinder) {
    p.length = length(c.b - c.a);
    if (p.length > 0)
      p.axis = (c.b - c.a) / p.length;
    else
      p.c.cylinder = false;
  }
  return p;
}

}  // namespace

Blob make_blob(double threshold, std::vector<BlobComponent> components) {
  if (!(threshold > 0) || !std::isfinite(threshold))
    throw std::invalid_argument("threshold must be > 0 and finite");
  if (components.empty()) throw std::invalid_argument("a blob needs at least one component");
  if (components.size() > kMaxBlobComponents)
    throw std::invalid_argument("at most " + std::to_string(kMaxBlobComponents) + " components");
  auto data = std::make_shared<Data>();
  data->threshold = threshold;
  std::vector<Aabb> boxes;
  for (std::size_t i = 0; i < components.size(); ++i) {
    if (components[i].strength == 0) continue;  // adds nothing anywhere
    data->parts.push_back(make_part(components[i], i));
    boxes.push_back(part_box(data->parts.back()));
    if (components[i].strength > 0) data->box.grow(boxes.back());
    data->materials = data->materials || components[i].material >= 0;
  }
  double extents = 0;
  for (const Aabb& b : boxes) extents += std::max({b.extent().x, b.extent().y, b.extent().z});
  if (data->box.is_empty())
    throw std::invalid_argument("a blob needs a component of positive strength");
  // At most 64 windows cross the box, whatever the spread of the parts' sizes.
  const Vec3 e = data->box.extent();
  data->window =
      std::max(4 * extents / static_cast<double>(boxes.size()), std::max({e.x, e.y, e.z}) / 64);
  data->order.resize(data->parts.size());
  for (std::uint32_t i = 0; i < data->order.size(); ++i) data->order[i] = i;
  data->nodes.resize(1);
  build_node(*data, boxes, 0, 0, static_cast<std::uint32_t>(data->parts.size()));
  return Blob{std::move(data)};
}

Aabb bounds(const Blob& s) { return s.data->box; }

bool intersect(const Blob& s, const Ray& ray, LocalHit& hit) {
  const Data& data = *s.data;
  double t0, t1;
  if (!slab_interval(data.box, ray.o, reciprocal(ray.d), t0, t1)) return false;
  t0 = std::max(t0, ray.tmin);
  t1 = std::min(t1, ray.tmax);
  if (!(t0 <= t1)) return false;
  // The chord is taken in windows of a few components' size, nearest first: a hit near the
  // front spares gathering the components further along.
  const double window = data.window / length(ray.d);
  Scratch& sc = scratch();
  for (double lo = t0; lo <= t1;) {
    double hi = t1 - lo > window ? lo + window : t1;
    if (!(hi > lo)) hi = t1;  // a window below the rounding of t
    gather(data, ray, lo, hi, sc);
    bool found = false;
    sweep(data, sc, lo, hi, [&](double a, double b, const Polynomial& p, double m) {
      const auto in_range = [&](double u) {
        const double t = m + u;
        return t >= ray.tmin && t <= ray.tmax;
      };
      double u;
      if (!find_first_real_root(p, std::max(a, lo) - m, std::min(b, hi) - m, in_range, u))
        return false;
      hit = LocalHit{.t = m + u, .part = strongest(data, sc, ray, m + u)};
      found = true;
      return true;
    });
    if (found || hi >= t1) return found;
    lo = hi;
  }
  return false;
}

void spans(const Blob& s, const Ray& ray, SpanList& out) {
  const Data& data = *s.data;
  double t0, t1;
  if (!slab_interval(data.box, ray.o, reciprocal(ray.d), t0, t1)) return;
  Scratch& sc = scratch();
  gather(data, ray, -kInfinity, kInfinity, sc);
  sc.crossings.clear();
  sweep(data, sc, -kInfinity, kInfinity, [&](double a, double b, const Polynomial& p, double m) {
    double u[4];
    const int n = find_real_roots(p, a - m, b - m, u);
    for (int i = 0; i < n; ++i) {
      const double t = m + u[i];
      // A root on a stretch's end is found on both sides of it: once is enough.
      if (sc.crossings.empty() || t > sc.crossings.back().t)
        sc.crossings.push_back({t, strongest(data, sc, ray, t), 0});
    }
    return false;
  });
  spans_from_crossings(
      sc.crossings.data(), static_cast<int>(sc.crossings.size()), ray, true,
      [&](const Vec3& p) { return blob_field(s, p) > data.threshold; }, out);
}

SurfaceInfo surface(const Blob& s, const Ray& ray, const LocalHit& hit) {
  const Data& data = *s.data;
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  Vec3 g = field_gradient(data, p);
  const double gl = length(g);
  if (gl > 0 && std::isfinite(gl)) {
    // One Newton step along the gradient puts p back on the surface.
    p += ((data.threshold - blob_field(s, p)) / (gl * gl)) * g;
    si.n = normalize(-g);
  } else {
    si.n = -normalize(ray.d);
  }
  si.shading_n = si.n;
  si.p = p;
  const Vec3 e = data.box.extent();
  const double size = std::max({e.x, e.y, e.z});
  si.p_error = gamma(16) * (abs(p) + Vec3{size, size, size});
  return si;
}

double blob_field(const Blob& s, const Vec3& p) {
  const Data& data = *s.data;
  double f = 0;
  walk(
      data, [&](const Aabb& b) { return b.contains(p); },
      [&](std::uint32_t i) { f += part_field(data.parts[i], p); });
  return f;
}

int blob_material(const Blob& s, const LocalHit& hit) {
  const Data& data = *s.data;
  if (!data.materials || hit.part < 0 || static_cast<std::size_t>(hit.part) >= data.parts.size())
    return -1;
  return data.parts[static_cast<std::size_t>(hit.part)].c.material;
}

bool contains(const Blob& s, const Vec3& p) { return blob_field(s, p) > s.data->threshold; }

}  // namespace raycast
