// The Whitted recursion, written once for its three modes (Integrator::TraceMode): included by
// integrator.cpp (kPlain, the render's) and integrator_record.cpp (kCount and kRecord, for
// `raycast explain` and the recorded outputs), so that the render's translation unit is compiled
// and inlined as if there were one mode only.
// Needs, before it: render/integrator.h, geometry/spawn.h, render/light_falloff.h,
// render/area_light_adaptive.h, render/optics.h,
// render/terminator.h,
// <algorithm>, <cmath>, <numbers>.

namespace raycast {

namespace {

/// The interior a secondary ray travels in: m's when the ray goes into the object (`inward`: a
/// refracted ray from outside, a mirrored one from inside) and m fades, else none (nullptr).
/// Only the innermost interior is followed: a ray leaving an object is taken to be in air.
inline const Material* interior_after(const Material& m, bool inward) {
  return inward && fades(m) ? &m : nullptr;
}

constexpr Color kWhite{1, 1, 1};

// The index of refraction a ray meets at m: its band's once a dispersive surface split it.
inline double ior_seen(const Material& m, const SampleState& state) {
  return state.band >= 0 && disperses(m) ? band_ior(m.ior, m.dispersion, state.band) : m.ior;
}

/// The spot light's cone (render/light_falloff.h).
double spot_factor(const Light& light, const Vec3& from_light) {
  return spot_cone(light, from_light);
}

// One light's term e * (diffuse + highlight) at the hit. Plain materials: e * (kd nl C +
// ks max(0, r.v)^shininess), r = l mirrored about n (pow(0, shininess) is 0 for shininess > 0:
// no pow call when the lobe faces away), with `highlight` the scalar Phong part. Textured ones:
// finish_terms, with the two parts (times e) in diffuse_part and specular_part.
template <bool kTextured>
[[gnu::always_inline]] inline Color light_term(const Material& m, unsigned exponent, const Color& c,
                                               const texture::SurfaceLook* look, const Vec3& n,
                                               const Vec3& l, const Vec3& v, double nl,
                                               const Color& e, double& highlight,
                                               Color& diffuse_part, Color& specular_part) {
  const Vec3 r = 2 * nl * n - l;
  const double rv = dot(r, v);
  if constexpr (kTextured) {
    finish_terms(*look, n, l, v, nl, rv, diffuse_part, specular_part);
    diffuse_part = mul(e, diffuse_part);
    specular_part = mul(e, specular_part);
    return diffuse_part + specular_part;
  } else {
    highlight = m.specular > 0 && (rv > 0 || !(m.shininess > 0))
                    ? m.specular * (exponent > 0 ? integer_power(std::max(0.0, rv), exponent)
                                                 : std::pow(std::max(0.0, rv), m.shininess))
                    : 0;
    return mul(e, m.diffuse * nl * c + Vec3{highlight, highlight, highlight});
  }
}

// light_term without its highlight (a shadowless light's: POV-Ray's give none).
template <bool kTextured>
[[gnu::always_inline]] inline void drop_highlight(const Material& m, double nl, const Color& c,
                                                  const Color& e, Color& term, double& highlight,
                                                  Color& specular_part) {
  if constexpr (kTextured)
    term = term - specular_part;
  else
    term = mul(e, m.diffuse * nl * c);
  highlight = 0;
  specular_part = Color{0, 0, 0};
}

}  // namespace

template <Integrator::TraceMode M>
Color Integrator::trace(const Ray& ray, int depth, SampleState& state, double weight,
                        const Material* medium) const {
  if constexpr (M != kPlain) {
    RayCounts& counts = state.recorder->counts;
    if (depth == 0) ++counts.camera;  // secondary rays are counted where they are cast
    counts.max_depth = std::max(counts.max_depth, depth);
  }
  if constexpr (M == kRecord) state.recorder->begin_ray(ray, depth);
  ++state.rays;
  SceneHit hit;
  if (!scene_.intersect(ray, hit) || (any_hidden_ && !seen(ray, hit, depth == 0, state))) {
    // Inside a fading interior, light from beyond an open surface comes from infinitely far.
    const Color seen = medium ? mul(interior_fade(*medium, kInfinity), missed(ray)) : missed(ray);
    if constexpr (M == kRecord) {
      state.recorder->miss(seen);
      state.recorder->stop(RayStop::kMiss);
      state.recorder->end_ray(seen);
    }
    return seen;
  }
  Color radiance = whitted_hit<M>(ray, hit, depth, state, weight);
  // The light reaching the ray's origin travelled hit.t |d| inside the interior it starts in
  // (where, as in POV-Ray, there is no fog), or across the atmosphere.
  if (medium) [[unlikely]]
    radiance = mul(interior_fade(*medium, hit.local.t * length(ray.d)), radiance);
  else
    radiance = fogged(ray, hit.local.t, radiance);
  if constexpr (M == kRecord) state.recorder->end_ray(radiance);
  return radiance;
}

template <Integrator::TraceMode M>
inline Color Integrator::trace_child(const Ray& ray, int depth, SampleState& state, double weight,
                                     const Material* medium, bool mirrored) const {
  const bool parent_mirrored = std::exchange(state.mirrored, mirrored);
  Color radiance;
  if constexpr (M == kRecord) {
    if (state.recorder->camera_ray_only) {
      state.recorder->begin_ray(ray, depth);
      radiance = trace<kCount>(ray, depth, state, weight, medium);
      state.recorder->end_ray(radiance);
      state.mirrored = parent_mirrored;
      return radiance;
    }
  }
  radiance = trace<M>(ray, depth, state, weight, medium);
  state.mirrored = parent_mirrored;
  return radiance;
}

template <Integrator::TraceMode M>
inline Color Integrator::whitted_hit(const Ray& ray, const SceneHit& hit, int depth,
                                     SampleState& state, double weight) const {
  // The material is resolved once per hit (CSG and instances search their parts for it).
  const std::size_t mi = material_index(hit);
  // Patterned and layered textures take their own path: a plain material pays one test here.
  if (scene_.materials[mi].texture) [[unlikely]]
    return textured_hit<M>(ray, hit, mi, depth, state, weight);
  const Object& object = scene_.objects[hit.object];
  const bool imaged = needs(mi) == SurfaceNeeds::kAll;
  const SurfaceInfo si = raycast::surface(object, ray, hit.local,
                                          imaged ? SurfaceNeeds::kAll : SurfaceNeeds::kGeometry);
  const Material& m = scene_.materials[mi];
  // A plain colour needs no look-up (albedo() would return it).
  const Color c = m.has_checker || imaged ? albedo(scene_, textures_, ray, hit, si, mi) : m.color;
  const Vec3 wi = normalize(ray.d);
  const bool outside = dot(wi, si.n) < 0;
  const Vec3 n = outside ? si.shading_n : -si.shading_n;  // faces the viewer
  const Vec3 v = -wi;
  // Shadow rays leaving on the shading normal's side of a smooth mesh start from Hanika's point
  // (a temporary at its own call: a std::optional here had GCC zero 120 bytes per hit).
  const unsigned exponent = exponents_[mi];
  Color result = m.ambient * mul(scene_.render.ambient, c);
  if constexpr (M == kRecord) {
    state.recorder->hit(hit, si, mi, outside, n);
    state.recorder->ambient(result);
  }
  if (objects_[std::size_t(hit.object)].terminator)
    direct<M>(si, terminator_origin(object, hit.local, si), n, v, m, exponent, c, state, result);
  else
    direct<M>(si, si, n, v, m, exponent, c, state, result);
  if (depth >= scene_.render.max_depth) {
    if constexpr (M == kRecord) state.recorder->stop(RayStop::kMaxDepth);
    return result;
  }

  // Split between the mirror and the refracted ray (fixed weights, or exact Fresnel).
  double w_reflect = m.reflection, w_refract = m.transmission;
  Vec3 t_dir;
  bool tir = false;
  double fresnel = -1;
  if (w_refract > 0) {
    const double ior = ior_seen(m, state);
    const double eta_i = outside ? 1 : ior, eta_t = outside ? ior : 1;
    const bool refracted = refract(wi, n, eta_i / eta_t, t_dir);
    if (m.fresnel) {
      fresnel = fresnel_dielectric(dot(v, n), eta_i, eta_t);
      w_reflect += w_refract * fresnel;
      w_refract *= 1 - fresnel;
    }
    if (!refracted) {  // total internal reflection: the refracted weight goes to the mirror ray
      w_reflect += w_refract;
      w_refract = 0;
      tir = true;
    }
  }
  // Like POV-Ray's adc_bailout: a ray whose contribution to the pixel (the product of the
  // weights along its path) is below the cut-off is not traced (w > 0 keeps bailout 0 exact).
  const double cutoff = scene_.render.bailout;
  if constexpr (M == kRecord)
    state.recorder->split(w_reflect, w_refract, tir, fresnel, cutoff / weight);
  if (w_reflect > 0 && weight * w_reflect >= cutoff) {
    const Vec3 m_dir = reflect(wi, n);
    if constexpr (M != kPlain) ++state.recorder->counts.reflection;
    if constexpr (M == kRecord) state.recorder->child(RayKind::kReflection, w_reflect, kWhite);
    result += w_reflect * trace_child<M>({offset_ray_origin(si, m_dir), m_dir}, depth + 1, state,
                                         weight * w_reflect, interior_after(m, !outside), true);
  }
  if (w_refract > 0 && weight * w_refract >= cutoff) {
    if (disperses(m) && state.band < 0) {
      result += dispersed<M>(si, wi, n, m, outside, depth, state, weight, w_refract, kWhite);
    } else {
      if constexpr (M != kPlain) ++state.recorder->counts.refraction;
      if constexpr (M == kRecord) state.recorder->child(RayKind::kRefraction, w_refract, kWhite);
      result += w_refract * trace_child<M>({offset_ray_origin(si, t_dir), t_dir}, depth + 1, state,
                                           weight * w_refract, interior_after(m, outside), false);
    }
  }
  return result;
}

template <Integrator::TraceMode M>
Color Integrator::dispersed(const SurfaceInfo& si, const Vec3& wi, const Vec3& n, const Material& m,
                            bool outside, int depth, SampleState& state, double weight,
                            double w_refract, const Color& tint) const {
  const int bands = std::min(m.dispersion_samples, kMaxDispersionSamples);
  const auto shares = band_weights(bands);
  Color sum{0, 0, 0};
  for (int k = 0; k < bands; ++k) {
    state.band = band_position(k, bands);
    const double ior = band_ior(m.ior, m.dispersion, state.band);
    Vec3 dir;
    const bool refracted = refract(wi, n, outside ? 1 / ior : ior, dir);
    if (!refracted) dir = reflect(wi, n);
    const Color share = mul(tint, double(bands) * shares[std::size_t(k)]);
    const RayKind kind = refracted ? RayKind::kRefraction : RayKind::kReflection;
    if constexpr (M != kPlain)
      ++(refracted ? state.recorder->counts.refraction : state.recorder->counts.reflection);
    if constexpr (M == kRecord) state.recorder->child(kind, w_refract / bands, share);
    sum += mul(share, trace_child<M>({offset_ray_origin(si, dir), dir}, depth + 1, state,
                                     weight * w_refract / bands,
                                     interior_after(m, refracted == outside), !refracted));
  }
  state.band = -1;
  return (w_refract / bands) * sum;
}

template <Integrator::TraceMode M>
Color Integrator::textured_hit(const Ray& ray, const SceneHit& hit, std::size_t mi, int depth,
                               SampleState& state, double weight) const {
  const Object& object = scene_.objects[hit.object];
  const SurfaceInfo si = raycast::surface(object, ray, hit.local, SurfaceNeeds::kAll);
  const Material& m = scene_.materials[mi];
  const Vec3 wi = normalize(ray.d);
  const bool outside = dot(wi, si.n) < 0;
  const texture::SurfaceLook look =
      look_at(object, m, ray, hit, si, outside ? si.shading_n : -si.shading_n);
  const Vec3& n = look.normal;
  const Vec3 v = -wi;
  Color result = mul(scene_.render.ambient, look.ambient);
  if constexpr (M == kRecord) {
    state.recorder->hit(hit, si, mi, outside, n);
    state.recorder->ambient(result);
  }
  if (objects_[std::size_t(hit.object)].terminator)
    direct<M, true>(si, terminator_origin(object, hit.local, si), n, v, m, 0, look.diffuse, state,
                    result, &look);
  else
    direct<M, true>(si, si, n, v, m, 0, look.diffuse, state, result, &look);
  if (depth >= scene_.render.max_depth) {
    if constexpr (M == kRecord) state.recorder->stop(RayStop::kMaxDepth);
    return result;
  }
  // The mirror weight from the finish; what the stack lets through goes on along the refracted
  // ray (bent by the interior's ior), tinted by the filters it passed.
  double w_reflect = reflection_weight(look.finish, dot(v, n), m.ior);
  const double w_refract = (look.through.x + look.through.y + look.through.z) / 3;
  Vec3 t_dir;
  bool tir = false;
  double w_through = w_refract;
  if (w_refract > 0) {
    const double ior = ior_seen(m, state);
    const double eta = outside ? 1 / ior : ior;
    if (!refract(wi, n, eta, t_dir)) {
      w_reflect += w_refract;
      w_through = 0;
      tir = true;
    }
  }
  const double cutoff = scene_.render.bailout;
  if constexpr (M == kRecord) state.recorder->split(w_reflect, w_through, tir, -1, cutoff / weight);
  if (w_reflect > 0 && weight * w_reflect >= cutoff) {
    const Vec3 m_dir = reflect(wi, n);
    if constexpr (M != kPlain) ++state.recorder->counts.reflection;
    if constexpr (M == kRecord) state.recorder->child(RayKind::kReflection, w_reflect, kWhite);
    const Color mirrored = trace_child<M>({offset_ray_origin(si, m_dir), m_dir}, depth + 1, state,
                                          weight * w_reflect, interior_after(m, !outside), true);
    result += look.finish.reflection_metallic ? w_reflect * mul(look.pigment, mirrored)
                                              : w_reflect * mirrored;
  }
  if (w_through > 0 && weight * w_through >= cutoff) {
    // The filter's colour as a tint of the scalar weight: weight * tint is look.through.
    if (disperses(m) && state.band < 0) {
      result += dispersed<M>(si, wi, n, m, outside, depth, state, weight, w_through,
                             look.through / w_refract);
    } else {
      if constexpr (M != kPlain) ++state.recorder->counts.refraction;
      if constexpr (M == kRecord)
        state.recorder->child(RayKind::kRefraction, w_through, look.through / w_refract);
      result +=
          mul(look.through, trace_child<M>({offset_ray_origin(si, t_dir), t_dir}, depth + 1, state,
                                           weight * w_through, interior_after(m, outside), false));
    }
  }
  return result;
}

// The samples of a sphere light seen from p, each passed to add(l, target, at_infinity, e):
// directions uniform in the cone the sphere subtends (pbrt-v4 6.2.4), each carrying 1/samples
// of the light (E / r^2 at its own distance under inverse-square attenuation); inside the
// sphere it acts as a point at its centre.
template <class Add>
[[gnu::always_inline]] inline void sphere_light_samples(const Light& light, const Color& emitted,
                                                        const Vec3& p, Rng& rng, Add& add) {
  const bool inverse_square = light.attenuation == Attenuation::kInverseSquare;
  const Vec3 to = light.position - p;
  const double dist2 = length_squared(to);
  const double r2 = light.radius * light.radius;
  if (dist2 <= r2) {
    add(normalize(to), light.position, false, emitted);
    return;
  }
  const double dist = std::sqrt(dist2);
  const Vec3 w = to / dist;
  Vec3 s, t;
  make_frame(w, s, t);
  const double cos_max = std::sqrt(std::max(0.0, 1 - r2 / dist2));
  const Color share = emitted / double(light.samples);
  for (int k = 0; k < light.samples; ++k) {
    const double cos_theta = 1 - rng.uniform() * (1 - cos_max);
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    const double phi = 2 * std::numbers::pi * rng.uniform();
    const Vec3 l = sin_theta * std::cos(phi) * s + sin_theta * std::sin(phi) * t + cos_theta * w;
    // The nearer crossing of the light's sphere along l (cancellation-free form).
    const double b = dot(l, to);
    const double disc = std::max(0.0, b * b - (dist2 - r2));
    const double q = b + std::sqrt(disc);
    const double along = q > 0 ? (dist2 - r2) / q : dist;
    add(l, p + along * l, false, inverse_square ? share / (along * along) : share);
  }
}

// A point or spot light: one shadow ray to its position, the spot's cone applied.
template <class Add>
[[gnu::always_inline]] inline void point_light(const Light& light, const Color& emitted,
                                               const Vec3& p, Add& add) {
  const Vec3 to = light.position - p;
  const double dist2 = length_squared(to);
  if (!(dist2 > 0)) return;
  const Vec3 l = to / std::sqrt(dist2);
  const bool inverse_square = light.attenuation == Attenuation::kInverseSquare;
  Color e = inverse_square ? emitted / dist2 : emitted * attenuation_factor(light, dist2);
  if (light.type == LightType::kSpot) {
    const double cone = spot_factor(light, -l);
    if (!(cone > 0)) return;  // outside the cone: no term
    e *= cone;
  }
  add(l, light.position, false, e);
}

// A directional light; a bounded one is POV-Ray's parallel light: shadows only from what lies
// between the point and the plane through the light's position, points beyond that plane lit
// unshadowed, attenuation by the distance to the position as a point light's.
template <class Add>
[[gnu::always_inline]] inline void directional_light(const Light& light, const Color& emitted,
                                                     const Vec3& p, bool& unshadowed, Add& add) {
  const Vec3 l = -light.direction;
  if (!light.bounded) return add(l, l, true, emitted);
  const Color e = emitted * attenuation_factor(light, length_squared(light.position - p));
  const double to_plane = dot(light.position - p, l);
  if (!(to_plane > 0)) unshadowed = true;
  add(l, p + to_plane * l, false, e);
}

// Directional, cylinder and area lights: the cone (spot, cylinder) and attenuation of the
// light's centre, then one shadow ray per grid point of an area light (each with its share of the
// light and the centre's direction, as POV-Ray lights its area lights; with `adaptive`, only
// those adaptive_area_light_sum samples, through add_to into its own total) or one along the
// cylinder's axis. `unshadowed`: set for a shadowless light or beyond a parallel light's plane.
template <class Add, class AddTo>
[[gnu::always_inline]] inline void extended_light(const Light& light, const Color& emitted,
                                                  const Vec3& p, Rng& rng, bool& unshadowed,
                                                  Add& add, AddTo& add_to, Color& sum) {
  if (light.type == LightType::kDirectional)
    return directional_light(light, emitted, p, unshadowed, add);
  const Vec3 to = light.position - p;
  const double dist2 = length_squared(to);
  if (!(dist2 > 0)) return;
  Color e = emitted * attenuation_factor(light, dist2);
  if (light.type == LightType::kCylinder) {
    // The light travels along the axis: lit as from a parallel light, shadowed up to the axis.
    const double cone = cylinder_cone(light, p);
    if (!(cone > 0)) return;
    const Vec3 l = -light.direction;
    add(l, p + dot(to, l) * l, false, e * cone);
    return;
  }
  const Vec3 l = to / std::sqrt(dist2);
  if (light.spot) {
    const double cone = spot_cone(light, -l);
    if (!(cone > 0)) return;
    e *= cone;
  }
  const Color share = e / double(light.size1 * light.size2);
  if (light.adaptive >= 0) {
    sum += adaptive_area_light_sum(light, p, rng, [&](const Vec3& target) {
      Color point{0, 0, 0};
      add_to(point, l, target, false, share);
      return point;
    });
    return;
  }
  area_light_points(light, p, rng, [&](const Vec3& target) { add(l, target, false, share); });
}

template <Integrator::TraceMode M, bool kTextured>
void Integrator::direct(const SurfaceInfo& si, const SurfaceInfo& lit, const Vec3& n, const Vec3& v,
                        const Material& m, unsigned exponent, const Color& c, SampleState& state,
                        Color& result, const texture::SurfaceLook* look) const {
  Color sum{0, 0, 0};
  if constexpr (kTextured) {
    if (!(max_component(look->diffuse) > 0) && !(look->finish.phong > 0) &&
        !(look->finish.specular > 0))
      return;
  } else if (m.diffuse <= 0 && m.specular <= 0) {
    result += sum;
    return;
  }
  // offset_ray_origin depends on the direction only through the side of the surface it points
  // to: every shadow ray that leaves the same point to the same side starts at one origin,
  // computed once (the side test is offset_ray_origin's own, NaN included).
  const SurfaceInfo* origin_from = nullptr;
  bool origin_inward = false;
  Vec3 origin;
  auto origin_towards = [&](const SurfaceInfo& from, const Vec3& l) -> const Vec3& {
    const bool inward = dot(l, from.n) < 0;
    if (origin_from != &from || origin_inward != inward) {
      origin = offset_ray_origin(from, l);
      origin_from = &from;
      origin_inward = inward;
    }
    return origin;
  };
  // The direction lists around the light of the loop below (nullptr for lights without: only
  // point and spot lights have them, and add's shadow rays to such a light end at it).
  const DirectionLists* lists = nullptr;
  bool unshadowed = false, no_highlight = false;  // per light below (extended_light)
  // One light direction l towards `target` (a point, or a direction when at infinity), its
  // visible part added to `acc` (add: to `sum`). light_index: the loop's light, for a recorder.
  std::size_t light_index = 0;
  auto add_to = [&](Color & acc, const Vec3& l, const Vec3& target, bool at_infinity,
                    const Color& e) __attribute__((always_inline)) {
    const double nl = dot(n, l);
    // A light with no positive channel (e <= 0) gives a term <= 0: the test of the term below
    // drops it, without a test of e here for every light.
    if (!(nl > 0)) {
      if constexpr (M == kRecord)
        state.recorder->light({light_index, l, nl, {}, {}, false, {}, {}});
      return;
    }
    Color diffuse_part, specular_part;
    double highlight = 0;
    Color term = light_term<kTextured>(m, exponent, c, look, n, l, v, nl, e, highlight,
                                       diffuse_part, specular_part);
    if (no_highlight) drop_highlight<kTextured>(m, nl, c, e, term, highlight, specular_part);
    // The term is >= 0 in every channel; where it is exactly 0 (no diffuse part and the
    // highlight's lobe facing away, as on glass), visibility cannot matter: no shadow ray.
    if constexpr (M != kPlain) {  // the render's shadow query below, counted and told
      const SurfaceInfo& from = &lit != &si && dot(l, si.shading_n) > 0 ? lit : si;
      if constexpr (kTextured)
        light_recorded<M>({light_index, l, nl, diffuse_part, specular_part, false, {}, {}},
                          origin_towards(from, l), target, at_infinity, lists, term, state, acc);
      else
        light_recorded<M>(
            {light_index, l, nl, mul(e, m.diffuse * nl * c), highlight * e, false, {}, {}},
            origin_towards(from, l), target, at_infinity, lists, term, state, acc);
      return;
    }
    if (!(max_component(term) > 0)) return;
    // (lit is si itself except on smooth meshes: then no side test.)
    const SurfaceInfo& from = &lit != &si && dot(l, si.shading_n) > 0 ? lit : si;
    if (!any_transmissive_) {
      // Visibility is 0 or 1: no colour to return and multiply (1 * term is term, bit for bit).
      const Vec3& o = origin_towards(from, l);
      if (unshadowed ||
          !(lists ? blocked_to(o, *lists, state) : blocked(o, target, at_infinity, state)))
        acc += term;
      return;
    }
    // Unblocked, the filter product has a channel above 0 (passes() stops the walk otherwise).
    Color through{1, 1, 1};
    const Vec3& o = origin_towards(from, l);
    if (unshadowed || (lists ? filters_to(o, *lists, state, through)
                             : filters(o, target, at_infinity, state, through)))
      acc += mul(through, term);
  };
  auto add = [&](const Vec3& l, const Vec3& target, bool at_infinity, const Color& e)
      __attribute__((always_inline)) {
    add_to(sum, l, target, at_infinity, e);
  };
  // The lights' bounds once (the shadow rays' calls would otherwise make them reloaded per light).
  const Light* const lights = scene_.lights.data();
  const Color* const emitted_by = emitted_.data();
  const std::size_t light_count = scene_.lights.size();
  for (std::size_t li = 0; li < light_count; ++li) {
    const Light& light = lights[li];
    const Color& emitted = emitted_by[li];
    lists = light_lists_[li];
    light_index = li;
    unshadowed = no_highlight = !light.shadows;
    switch (light.type) {
      case LightType::kDirectional:
      case LightType::kCylinder:
      case LightType::kArea:
        extended_light(light, emitted, si.p, state.rng, unshadowed, add, add_to, sum);
        break;
      case LightType::kPoint:
      case LightType::kSpot:
        point_light(light, emitted, si.p, add);
        break;
      case LightType::kSphere:
        sphere_light_samples(light, emitted, si.p, state.rng, add);
        break;
    }
  }
  result += sum;
}

template <Integrator::TraceMode M>
void Integrator::light_recorded(LightSample sample, const Vec3& o, const Vec3& target,
                                bool at_infinity, const DirectionLists* lists, const Color& term,
                                SampleState& state, Color& sum) const {
  if (!(max_component(term) > 0)) {  // no shadow ray (as below: visibility cannot matter)
    if constexpr (M == kRecord) state.recorder->light(sample);
    return;
  }
  ++state.recorder->counts.shadow;
  // The render's queries (shadow() is blocked() or filters() with their answer as a colour: the
  // filter product, which has a channel above 0 when the light is not blocked).
  Color visibility{1, 1, 1};
  if (!lists)
    visibility = shadow(o, target, at_infinity, state);
  else if (!any_transmissive_)
    visibility = blocked_to(o, *lists, state) ? Color{} : Color{1, 1, 1};
  else if (!filters_to(o, *lists, state, visibility))
    visibility = Color{};
  if (max_component(visibility) > 0) sum += any_transmissive_ ? mul(visibility, term) : term;
  if constexpr (M == kRecord) {
    sample.shadow_ray = true;
    sample.shadow = lists         ? Ray{o, lists->apex() - o, 0, 1}
                    : at_infinity ? Ray{o, target, 0, kInfinity}
                                  : Ray{o, target - o, 0, 1};
    sample.visibility = visibility;
    state.recorder->light(sample);
  }
}

}  // namespace raycast
