#include "serve/json_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/scene_error.h"
#include "load/yaml_prescan.h"

namespace raycast::serve {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", c);
      out += esc;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string json_number(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, end) : "null";
}

std::string json_vec3(const Vec3& v) {
  std::ostringstream out;
  out << '[' << json_number(v.x) << ',' << json_number(v.y) << ',' << json_number(v.z) << ']';
  return out.str();
}

YamlDocument parse_request_object(const std::string& body, std::size_t max_bytes) {
  if (body.size() > max_bytes)
    throw SceneError("request", 0, 0,
                     "the body is larger than " + std::to_string(max_bytes) + " bytes");
  YamlDocument doc = parse_yaml(body, "request", 3);
  if (!doc.root().IsMap()) throw SceneError("request", 1, 1, "the body must be a JSON object");
  return doc;
}

}  // namespace raycast::serve
