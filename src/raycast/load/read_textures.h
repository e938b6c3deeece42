#pragma once
// The YAML form of patterned textures, normals and POV-Ray finishes (docs/textures.md).
#include "load/yaml_node.h"

#include "load/yaml_reader.h"
#include "scene/material.h"

namespace raycast {

/// A pigment: {color: [r, g, b, filter?, transmit?]} or {pattern: NAME, ... colors: [[v, c]...]}
/// or {pattern: NAME, ... pigments: [[v, PIGMENT]...]} (nested at most 16 deep).
texture::Pigment read_pigment(const SourceContext& ctx, const YamlNode& node, int depth = 0);
/// A normal: {pattern: NAME, bump_size: B, ...pattern modifiers}, or {pattern: average,
/// normals: [[weight, NORMAL], ...]}.
texture::Normal read_normal(const SourceContext& ctx, const YamlNode& node, int depth = 0);

/// Whether a material mapping asks for the texture system: a `texture` with a `pattern`, a
/// `normal`, `layers` or a finish key plain materials do not have.
bool wants_texture(const YamlNode& material);

/// Reads the texture keys of a material mapping (texture, normal, layers, brilliance, metallic,
/// crand, roughness, reflection_max, reflection_falloff, reflection_metallic) into m.texture,
/// with the finish of the bottom layer from m's own ambient, diffuse, specular, shininess,
/// reflection and fresnel.
void read_texture_keys(Fields& f, Material& m);

}  // namespace raycast
