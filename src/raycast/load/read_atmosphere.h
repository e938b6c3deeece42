#pragma once
// The YAML form of the atmosphere: render.sky_sphere, render.fog and render.rainbow
// (docs/rendering.md "Sky and fog").
#include <memory>

#include "load/yaml_reader.h"
#include "scene/atmosphere.h"

namespace raycast {

/// The sky_sphere, fog and rainbow keys of the render mapping; null when it has none.
std::shared_ptr<const Atmosphere> read_atmosphere(Fields& render);

}  // namespace raycast
