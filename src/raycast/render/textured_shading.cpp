#include "render/textured_shading.h"

#include "render/texture.h"

namespace raycast {

Vec3 texture_point(const Object& object, const Material& m, const Ray& ray, const SceneHit& hit) {
  // The object-space point from the object-space ray, as the shape itself computed it.
  return m.texture_transform.point(to_object_space(object, ray).at(hit.local.t));
}

Color textured_albedo(const Object& object, const Material& m, const Ray& ray,
                      const SceneHit& hit) {
  return texture::pigment_color(*m.texture, texture_point(object, m, ray, hit));
}

texture::SurfaceLook look_at(const Object& object, const Material& m, const Ray& ray,
                             const SceneHit& hit, const SurfaceInfo& si, const Vec3& n) {
  texture::TextureContext ctx;
  ctx.p = texture_point(object, m, ray, hit);
  ctx.n = n;
  ctx.u = si.u;
  ctx.v = si.v;
  if (m.texture->has_normal()) {
    // The world axes in texture space: the normal's gradient is taken along them.
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; ++a) {
      const Vec3 o = object.xf ? object.xf->inverse_vector(axes[a]) : axes[a];
      ctx.axes[a] = m.texture_transform.vector(o);
    }
  }
  return texture::evaluate(*m.texture, ctx);
}

}  // namespace raycast
