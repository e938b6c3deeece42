#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "pov/options.h"

namespace raycast::pov {

namespace {

// Library_Path=DIR lines of an INI file (POV-Ray's configuration syntax: `key=value`,
// `;` comments, `[sections]`); a missing file gives none. `%INSTALLDIR%` and `%HOME%` are
// POV-Ray's substitutions for the install folder and the user's home.
void read_ini_paths(const std::string& file, std::vector<std::string>& out) {
  std::ifstream in(file);
  std::string line;
  const char* home = std::getenv("HOME");
  while (std::getline(in, line)) {
    const auto semicolon = line.find(';');
    if (semicolon != std::string::npos) line.erase(semicolon);
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    auto trim = [](std::string& s) {
      while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.pop_back();
      while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.erase(0, 1);
      if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
    };
    trim(key);
    trim(value);
    for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (key != "library_path" || value.empty()) continue;
    for (const char* var : {"%INSTALLDIR%", "%HOME%"}) {
      const auto at = value.find(var);
      if (at == std::string::npos) continue;
      const std::string with =
          std::string(var) == "%HOME%" ? (home ? home : "") : "/usr/share/povray-3.7";
      value.replace(at, std::string(var).size(), with);
    }
    out.push_back(value);
  }
}

}  // namespace

std::vector<std::string> configured_library_paths() {
  std::vector<std::string> out;
  if (const char* env = std::getenv("RAYCAST_POV_LIBRARY_PATH")) {
    std::string s = env;
    std::size_t start = 0;
    while (start <= s.size()) {
      const auto end = s.find(':', start);
      const std::string part = s.substr(start, end == std::string::npos ? end : end - start);
      if (!part.empty()) out.push_back(part);
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  if (const char* home = std::getenv("HOME"))
    read_ini_paths(std::string(home) + "/.povray/3.7/povray.ini", out);
  read_ini_paths("/etc/povray/3.7/povray.ini", out);
  return out;
}

}  // namespace raycast::pov
