#include "load/frame_pattern.h"

#include <cctype>
#include <cstdio>
#include <stdexcept>

namespace raycast {

bool has_frame_pattern(const std::string& text) { return text.find("{frame") != std::string::npos; }

std::string expand_frame_pattern(const std::string& text, int frame) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t at = text.find("{frame", i);
    if (at == std::string::npos) {
      out += text.substr(i);
      break;
    }
    out += text.substr(i, at - i);
    const std::size_t close = text.find('}', at);
    if (close == std::string::npos)
      throw std::invalid_argument("unclosed '{frame' pattern (expected {frame} or {frame:04d})");
    const std::string spec = text.substr(at + 6, close - at - 6);  // "" or ":04d"
    std::string number = std::to_string(frame);
    if (!spec.empty()) {
      const bool ok = spec.size() >= 3 && spec.size() <= 4 && spec[0] == ':' &&
                      spec.back() == 'd' &&
                      std::isdigit(static_cast<unsigned char>(spec[spec.size() - 2])) &&
                      (spec.size() == 3 || spec[1] == '0') && spec[spec.size() - 2] != '0';
      if (!ok)
        throw std::invalid_argument("bad frame pattern '{frame" + spec +
                                    "}' (expected {frame} or {frame:0Nd}, N = 1..9)");
      const int width = spec[spec.size() - 2] - '0';
      char buf[32];
      std::snprintf(buf, sizeof buf, spec.size() == 4 ? "%0*d" : "%*d", width, frame);
      number = buf;
    }
    out += number;
    i = close + 1;
  }
  return out;
}

}  // namespace raycast
