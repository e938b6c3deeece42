#pragma once
// The scene file's settings (docs/scene-format.md): `camera`, `image` and `render`, each read from
// its mapping with positioned errors.
#include <string>

#include "load/yaml_reader.h"
#include "scene/material.h"
#include "scene/render_settings.h"

namespace raycast {

CameraDesc read_camera(const SourceContext& ctx, const YamlNode& node);
/// `image`: the size and samples; refuses an image over kMaxImagePixels before anything is made.
ImageSettings read_image(const SourceContext& ctx, const YamlNode& node);
/// `render`: integrator, max_depth, background, ambient, seed, antialias.
RenderSettings read_render(const SourceContext& ctx, const YamlNode& node);

/// A colour field, every channel >= 0; `fallback` when the field is absent.
Color read_color(Fields& f, const std::string& key, const Color& fallback);

}  // namespace raycast
