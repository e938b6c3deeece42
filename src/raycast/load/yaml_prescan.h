#pragma once
// Parsing scene text into YAML nodes, guarded by a pre-scan of the raw text.
#include <string>

#include "load/yaml_node.h"

namespace raycast {

/// Parses YAML (or JSON) text. Throws SceneError (with `name` as the file) for text nested
/// deeper than `max_nesting` collections, before any node is made (the readers of the nodes
/// recurse per level), and for syntax errors; an error caused by an unclosed `[` or `{` is
/// reported where it opened.
YamlDocument parse_yaml(std::string text, const std::string& name, int max_nesting);

}  // namespace raycast
