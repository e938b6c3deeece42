#include "pov/ini_file.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/scene_error.h"

namespace raycast::pov {

namespace {
std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}
std::string trim(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  s = s.substr(i);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}
bool number(const std::string& s, double& out) {
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end && end != s.c_str() && *end == '\0';
}
bool on(const std::string& v) {
  const std::string l = lower(v);
  return l == "on" || l == "true" || l == "yes" || l == "1";
}
}  // namespace

bool apply_ini_setting(const std::string& raw, Options& o, std::string& scene) {
  std::string s = trim(raw);
  if (s.empty()) return true;
  double v = 0;
  if (s[0] == '+' || s[0] == '-') {
    const bool plus = s[0] == '+';
    const std::string k = s.substr(1);
    const std::string lk = lower(k);
    auto num = [&](std::size_t n) { return number(k.substr(n), v); };
    if (lk.rfind("kfi", 0) == 0 && num(3))
      o.initial_frame = static_cast<int>(v), o.clock_on = true;
    else if (lk.rfind("kff", 0) == 0 && num(3))
      o.final_frame = static_cast<int>(v), o.clock_on = true;
    else if (lk.rfind("ki", 0) == 0 && num(2))
      o.initial_clock = v;
    else if (lk.rfind("kf", 0) == 0 && num(2))
      o.final_clock = v;
    else if (lk.rfind("k", 0) == 0 && num(1))
      o.clock = v;
    else if (lk[0] == 'w' && num(1))
      o.width = static_cast<int>(v);
    else if (lk[0] == 'h' && num(1))
      o.height = static_cast<int>(v);
    else if (lk[0] == 'a') {
      o.antialias = plus;
      if (k.size() > 1 && num(1)) o.antialias_threshold = v;
    } else if (lk[0] == 'i' && k.size() > 1)
      scene = k.substr(1);
    else if (lk[0] == 'l' && k.size() > 1)
      o.library_paths.push_back(k.substr(1));
    else
      return false;
    return true;
  }
  const auto eq = s.find('=');
  if (eq == std::string::npos) {
    scene = s;  // a bare file name
    return true;
  }
  const std::string key = lower(trim(s.substr(0, eq)));
  const std::string val = trim(s.substr(eq + 1));
  if (key == "input_file_name")
    scene = val;
  else if (key == "width" && number(val, v))
    o.width = static_cast<int>(v);
  else if (key == "height" && number(val, v))
    o.height = static_cast<int>(v);
  else if (key == "antialias")
    o.antialias = on(val);
  else if (key == "antialias_threshold" && number(val, v))
    o.antialias_threshold = v;
  else if (key == "antialias_depth" && number(val, v))
    o.antialias_depth = static_cast<int>(v);
  else if (key == "clock" && number(val, v))
    o.clock = v;
  else if (key == "initial_frame" && number(val, v))
    o.initial_frame = static_cast<int>(v), o.clock_on = true;
  else if (key == "final_frame" && number(val, v))
    o.final_frame = static_cast<int>(v), o.clock_on = true;
  else if (key == "initial_clock" && number(val, v))
    o.initial_clock = v;
  else if (key == "final_clock" && number(val, v))
    o.final_clock = v;
  else if (key == "library_path")
    o.library_paths.push_back(val);
  else if (key == "declare") {
    const auto e2 = val.find('=');
    if (e2 == std::string::npos) return false;
    o.declares.emplace_back(trim(val.substr(0, e2)), trim(val.substr(e2 + 1)));
  } else
    return false;
  return true;
}

std::string read_ini_file(const std::string& path, Options& o) {
  std::ifstream in(path);
  if (!in) throw SceneError(path, 0, 0, "cannot open the INI file");
  std::string line, scene;
  const std::string dir = std::filesystem::path(path).parent_path().string();
  while (std::getline(in, line)) {
    const auto semicolon = line.find(';');
    if (semicolon != std::string::npos) line.erase(semicolon);
    if (!line.empty() && line[0] == '[') continue;  // sections: every one is read
    std::istringstream words(line);
    if (line.find('=') != std::string::npos) {
      apply_ini_setting(line, o, scene);
    } else {
      std::string w;
      while (words >> w) apply_ini_setting(w, o, scene);
    }
  }
  if (scene.empty()) throw SceneError(path, 0, 0, "the INI file names no Input_File_Name");
  if (!dir.empty() && !std::filesystem::path(scene).is_absolute()) {
    o.library_paths.insert(o.library_paths.begin(), dir);
    scene = (std::filesystem::path(dir) / scene).string();
  }
  // The clock of the first frame when an animation is asked for.
  if (o.clock_on && o.final_frame > o.initial_frame) {
    const int f =
        std::clamp(o.frame > 0 ? o.frame : o.initial_frame, o.initial_frame, o.final_frame);
    o.frame = f;
    o.clock = o.initial_clock + (o.final_clock - o.initial_clock) * (f - o.initial_frame) /
                                    static_cast<double>(o.final_frame - o.initial_frame);
  }
  return scene;
}

}  // namespace raycast::pov
