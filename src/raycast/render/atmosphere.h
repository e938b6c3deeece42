#pragma once
// The atmosphere's effect on one ray (docs/rendering.md "Sky and fog"): the sky sphere's colour
// where a ray leaves the scene, and the fogs over a segment of it.
#include "geometry/ray.h"
#include "math/vec3.h"
#include "scene/atmosphere.h"

namespace raycast {

/// The sky's colour in direction d (any length): the layers, top first, each seen through the
/// filter and transmit of those above, times the emission; the background through what is left.
Vec3 sky_color(const SkySphere& sky, const Vec3& background, const Vec3& d);

/// The fog's optical depth over the segment from ray.o along ray.d of world length `span`
/// (infinite for a ray that leaves the scene): the length for a constant fog, the integral of the
/// ground fog's density along it, each scaled by the turbulence.
double fog_depth(const Fog& fog, const Ray& ray, double span);

/// The ground fog's density integral over a segment whose height starts at h0 and changes by dh
/// per unit of length, in closed form (an infinite length is allowed).
double ground_fog_depth(double offset, double alt, double h0, double dh, double length);

/// `light` as seen across the fogs after a segment of world length `span` (infinite: a miss):
/// each fog lets k = max(transmit, exp(-depth / distance)) of it through, (1 - k) filter of it
/// tinted by the fog's colour, and adds (1 - k) (1 - filter) of its colour; several fogs multiply
/// their passing fractions and add their colours.
Vec3 apply_fogs(const std::vector<Fog>& fogs, const Ray& ray, double span, const Vec3& light);

/// `light` as seen across the rainbows after a segment of world length `span`: a rainbow's
/// colour c (filter f, transmit t) at the ray's angle lets k = max(t, exp(-span / distance)) of
/// the light through, tinted as k (1 - f (1 - k) (1 - c)), and adds (1 - k) c, with 1 - k scaled
/// by the arc's fade; several rainbows in turn.
Vec3 apply_rainbows(const std::vector<Rainbow>& rainbows, const Ray& ray, double span,
                    const Vec3& light);

/// The light of a segment of world length `span` across the rainbows, then the fogs.
Vec3 veiled(const Atmosphere& atmosphere, const Ray& ray, double span, const Vec3& light);

/// What a ray that hits nothing sees: the sky (or the background) across the fogs.
Vec3 miss_color(const Atmosphere& atmosphere, const Vec3& background, const Ray& ray);

}  // namespace raycast
