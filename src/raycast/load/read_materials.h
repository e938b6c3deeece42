#pragma once
// The scene file's appearance (docs/scene-format.md): materials (named or inline, with their
// textures, read at load so a missing image is an error at its position) and lights.
#include <string>

#include "load/yaml_reader.h"
#include "scene/light.h"
#include "scene/material.h"

namespace raycast {

/// One material mapping; `name` is empty for an inline material. Image textures are loaded here.
Material read_material(const SourceContext& ctx, const YamlNode& node, const std::string& name);

/// One entry of `lights`.
Light read_light(const SourceContext& ctx, const YamlNode& node);

}  // namespace raycast
