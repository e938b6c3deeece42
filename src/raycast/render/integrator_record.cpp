// The Whitted recursion's recording mode (render/whitted_trace.inl with kRecord true), compiled
// apart from the render's mode so that adding it changes nothing in how that one is optimised.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/spawn.h"
#include "render/integrator.h"
#include "render/optics.h"
#include "render/terminator.h"
#include "render/whitted_trace.inl"

namespace raycast {

template Color Integrator::trace<true>(const Ray& ray, int depth, SampleState& state,
                                       double weight) const;

}  // namespace raycast
