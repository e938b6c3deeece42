#pragma once
// Parsing scene text into YAML nodes, guarded by a pre-scan of the raw text.
#include <yaml-cpp/yaml.h>

#include <string>

namespace raycast {

/// Parses YAML (or JSON) text. Throws SceneError (with `name` as the file) for text nested
/// deeper than `max_nesting` collections, before yaml-cpp's recursive parser sees it, and for
/// syntax errors; an error caused by an unclosed `[` or `{` is reported where it opened.
YAML::Node parse_yaml(const std::string& text, const std::string& name, int max_nesting);

}  // namespace raycast
