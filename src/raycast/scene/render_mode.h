#pragma once
// What a render computes per sample, and the one table of its names: the integrators of
// `render.integrator` / `--integrator` and the extra outputs of `--aov` (docs/cli.md).
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raycast {

/// whitted, raycast, depth, normal and id are integrators; depth, normal, id and albedo (the
/// surface colour before any lighting, black for misses) are also extra outputs (AOVs).
enum class RenderMode { kWhitted, kRaycast, kDepth, kNormal, kId, kAlbedo };

/// The mode's name as the scene format and the CLI write it ("whitted", ..., "albedo").
const char* render_mode_name(RenderMode mode);

/// The integrator of that name (every mode but albedo), or nothing.
std::optional<RenderMode> integrator_named(std::string_view name);
/// The extra output of that name (depth, normal, id, albedo), or nothing.
std::optional<RenderMode> aov_named(std::string_view name);

/// For messages: "whitted, raycast, depth, normal or id" and "depth, normal, id, albedo".
inline constexpr const char* kIntegratorNames = "whitted, raycast, depth, normal or id";
inline constexpr const char* kAovNames = "depth, normal, id, albedo";

/// A comma-separated `--aov` list as (name, mode) pairs. Returns false with `bad` set to the
/// first name that is not an output.
bool parse_aov_list(const std::string& list, std::vector<std::pair<std::string, RenderMode>>& aovs,
                    std::string& bad);

}  // namespace raycast
