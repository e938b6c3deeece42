#pragma once
// The little JSON the server writes (state, pick answers) and reads (request bodies).
#include <string>

#include "load/yaml_node.h"
#include "math/vec3.h"

namespace raycast::serve {

/// A JSON string literal: quotes, backslashes and control characters escaped; other bytes (UTF-8)
/// as they are (a browser decodes invalid UTF-8 to replacement characters).
std::string json_string(const std::string& text);
/// The shortest text that reads back as the same double; null for NaN and infinities.
std::string json_number(double value);
std::string json_vec3(const Vec3& v);

/// Parses a request body that must be a JSON (or YAML flow) mapping, at most `max_bytes` long and
/// nested at most 3 deep. Throws SceneError (file "request") with the position of the problem.
YamlDocument parse_request_object(const std::string& body, std::size_t max_bytes);

}  // namespace raycast::serve
