#include "scene/render_mode.h"

#include <sstream>

namespace raycast {

namespace {

struct ModeName {
  RenderMode mode;
  const char* name;
  bool integrator;  // allowed as render.integrator / --integrator
  bool aov;         // allowed in --aov
};

constexpr ModeName kModes[] = {{RenderMode::kWhitted, "whitted", true, false},
                               {RenderMode::kRaycast, "raycast", true, false},
                               {RenderMode::kDepth, "depth", true, true},
                               {RenderMode::kNormal, "normal", true, true},
                               {RenderMode::kId, "id", true, true},
                               {RenderMode::kAlbedo, "albedo", false, true}};

}  // namespace

const char* render_mode_name(RenderMode mode) {
  for (const ModeName& m : kModes)
    if (m.mode == mode) return m.name;
  return "whitted";
}

std::optional<RenderMode> integrator_named(std::string_view name) {
  for (const ModeName& m : kModes)
    if (m.integrator && name == m.name) return m.mode;
  return std::nullopt;
}

std::optional<RenderMode> aov_named(std::string_view name) {
  for (const ModeName& m : kModes)
    if (m.aov && name == m.name) return m.mode;
  return std::nullopt;
}

bool parse_aov_list(const std::string& list, std::vector<std::pair<std::string, RenderMode>>& aovs,
                    std::string& bad) {
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    const std::optional<RenderMode> mode = aov_named(name);
    if (!mode) {
      bad = name;
      return false;
    }
    aovs.emplace_back(name, *mode);
  }
  return true;
}

}  // namespace raycast
