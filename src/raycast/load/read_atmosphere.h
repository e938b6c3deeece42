#pragma once
// The YAML form of the atmosphere: render.sky_sphere and render.fog (docs/rendering.md "Sky and
// fog").
#include <memory>

#include "load/yaml_reader.h"
#include "scene/atmosphere.h"

namespace raycast {

/// The sky_sphere and fog keys of the render mapping; null when it has neither.
std::shared_ptr<const Atmosphere> read_atmosphere(Fields& render);

}  // namespace raycast
