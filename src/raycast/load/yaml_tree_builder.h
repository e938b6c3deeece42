#pragma once
// Parsing YAML (or JSON) text into a YamlDocument with libyaml's event parser.
#include <string>

#include "load/yaml_node.h"

namespace raycast {

/// Parses the first document of `text` (an empty text gives a null root). Throws SceneError
/// (with `name` as the file) at the position of a syntax error or of an alias to an anchor not
/// defined before it. Builds iteratively: any nesting depth is safe here (callers bound it for
/// their own recursion: yaml_prescan.h).
YamlDocument build_yaml_document(std::string text, const std::string& name);

}  // namespace raycast
