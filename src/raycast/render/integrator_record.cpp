// The Whitted recursion's counting and recording modes (render/whitted_trace.inl), compiled
// apart from the render's mode so that they change nothing in how that one is optimised.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "geometry/spawn.h"
#include "render/area_light_adaptive.h"
#include "render/dispersion.h"
#include "render/integrator.h"
#include "render/light_falloff.h"
#include "render/optics.h"
#include "render/terminator.h"
#include "render/whitted_trace.inl"

namespace raycast {

template Color Integrator::trace<Integrator::kCount>(const Ray& ray, int depth, SampleState& state,
                                                     double weight, const Material* medium) const;
template Color Integrator::trace<Integrator::kRecord>(const Ray& ray, int depth, SampleState& state,
                                                      double weight, const Material* medium) const;

}  // namespace raycast
