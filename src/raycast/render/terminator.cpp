#include "render/terminator.h"

#include <variant>

#include "math/float_error.h"

namespace raycast {

bool has_terminator_origin(const Object& o) {
  const auto* shape = std::get_if<MeshShape>(&o.shape);
  return shape && shape->mesh && !shape->mesh->normals.empty();
}

SurfaceInfo terminator_origin(const Object& o, const LocalHit& hit, const SurfaceInfo& si) {
  if (!has_terminator_origin(o) || hit.part < 0) return si;
  const Mesh& m = *std::get<MeshShape>(o.shape).mesh;
  const auto tri = static_cast<std::size_t>(hit.part);
  if (tri >= m.triangles.size()) return si;
  const auto& t = m.triangles[tri];
  const Vec3 v[3] = {Vec3(m.positions[t[0]]), Vec3(m.positions[t[1]]), Vec3(m.positions[t[2]])};
  Vec3 n[3] = {Vec3(m.normals[t[0]]), Vec3(m.normals[t[1]]), Vec3(m.normals[t[2]])};
  const double b[3] = {1 - hit.a - hit.b, hit.a, hit.b};
  // The object-space geometric normal and the interpolated one; mesh surface() turns the
  // shading normal to the geometric normal's side, so the vertex normals turn with it.
  const Vec3 ng = cross(v[1] - v[0], v[2] - v[0]);
  const Vec3 ns = b[0] * n[0] + b[1] * n[1] + b[2] * n[2];
  if (dot(ns, ng) < 0)
    for (Vec3& ni : n) ni = -ni;
  const Vec3 p = b[0] * v[0] + b[1] * v[1] + b[2] * v[2];
  Vec3 delta{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const double below = dot(p - v[i], n[i]);  // < 0: p lies under the tangent plane at v_i
    if (below < 0) delta -= (b[i] * below) * n[i];
  }
  if (!(dot(delta, ng) > 0) || !is_finite(delta)) return si;
  const Vec3 moved = o.xf ? o.xf->vector(delta) : delta;
  if (hit.flip || !is_finite(moved)) return si;
  SurfaceInfo out = si;
  out.p = si.p + moved;
  // The rounding of the sum, and a generous bound on the rounding of the move itself (it only
  // needs to keep p' on the outer side, which the move's own size does).
  out.p_error = si.p_error + gamma(1) * abs(out.p) + gamma(16) * abs(moved);
  return out;
}

}  // namespace raycast
