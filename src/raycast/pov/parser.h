#pragma once
// The POV-Ray 3.7 scene language subset of docs/pov-import.md, parsed into a PovScene (still in
// POV-Ray's coordinates). Directives (#declare, #local, #include, #default, #version) are
// evaluated while parsing; anything outside the subset is a positioned SceneError naming the
// construct.
#include <cstddef>
#include <string>

#include "pov/pov_scene.h"

namespace raycast::pov {

/// Parses `text` (the scene file's contents, called `name` in messages); #include files are
/// looked up in `dir`, the scene's folder.
PovScene parse_pov(const std::string& text, const std::string& name, const std::string& dir);

/// The deepest nesting of objects, textures and expressions, and of #include files.
inline constexpr int kMaxPovNesting = 256;
inline constexpr int kMaxIncludeDepth = 16;
/// The most items a counted list may announce (mesh2 vectors and indices, poly coefficients).
inline constexpr long kMaxPovCount = 1L << 24;
/// How much a scene may hold in all, counting every copy that `object { Name }` makes: each
/// object weighs kPovNodeWeight (at most 131072 objects), each point, vertex, triangle or
/// polynomial term 1.
inline constexpr std::size_t kMaxPovWeight = std::size_t{1} << 25;
inline constexpr std::size_t kPovNodeWeight = 256;
/// What image_width and image_height evaluate to: raycast's default image size.
inline constexpr int kPovImageWidth = 640, kPovImageHeight = 480;

}  // namespace raycast::pov
