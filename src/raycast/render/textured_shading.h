#pragma once
// The shading of a material with a texture (Material::texture, docs/textures.md): where the hit
// is in texture space, what the texture looks like there, and POV-Ray's finish terms.
#include <algorithm>
#include <cmath>

#include "render/optics.h"
#include "scene/scene.h"
#include "texture/texture_stack.h"

namespace raycast {

/// The texture of material m at a hit on `object`: evaluated at the object-space hit point moved
/// by m.texture_transform, with `n` (the unit world normal facing the viewer) perturbed by the
/// texture's normals.
texture::SurfaceLook look_at(const Object& object, const Material& m, const Ray& ray,
                             const SceneHit& hit, const SurfaceInfo& si, const Vec3& n);

/// The texture-space point of a hit (what look_at evaluates at).
Vec3 texture_point(const Object& object, const Material& m, const Ray& ray, const SceneHit& hit);

/// One light's diffuse and highlight parts before the light's colour: diffuse * (N.L)^brilliance,
/// phong * (R.V)^phong_size + specular * (N.H)^(1/roughness), the highlight tinted by the
/// pigment by the metallic fraction. nl > 0; rv = R.V.
inline void finish_terms(const texture::SurfaceLook& look, const Vec3& n, const Vec3& l,
                         const Vec3& v, double nl, double rv, Color& diffuse, Color& highlight) {
  const texture::Finish& f = look.finish;
  diffuse = (f.brilliance == 1 ? nl : std::pow(nl, f.brilliance)) * look.diffuse;
  double h = 0;
  if (f.phong > 0 && rv > 0) h += f.phong * std::pow(rv, f.phong_size);
  if (f.specular > 0) {
    const Vec3 half = l + v;
    const double hl = length(half);
    const double nh = hl > 0 ? dot(n, half) / hl : 0;
    if (nh > 0) h += f.specular * std::pow(nh, 1 / std::max(f.roughness, 1e-6));
  }
  const Color white{1, 1, 1};
  highlight = f.metallic > 0 ? h * (white + f.metallic * (look.pigment - white)) : h * white;
}

/// The mirror weight of a finish seen at cos_i (the cosine between the normal and the viewer):
/// reflection_min facing, reflection_max grazing, between them by the Fresnel reflectance for
/// the interior's ior or by (1 - cos_i)^falloff.
inline double reflection_weight(const texture::Finish& f, double cos_i, double ior) {
  if (f.reflection_max == f.reflection_min) return f.reflection_max;
  const double c = std::clamp(cos_i, 0.0, 1.0);
  const double t =
      f.reflection_fresnel ? fresnel_dielectric(c, 1, ior) : std::pow(1 - c, f.reflection_falloff);
  return f.reflection_min + (f.reflection_max - f.reflection_min) * t;
}

}  // namespace raycast
