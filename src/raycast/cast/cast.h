#pragma once
// `raycast cast`: rays in, answers out, in input order (docs/cli.md).
#include <iosfwd>
#include <string>

#include "scene/scene.h"

namespace raycast {

enum class CastMode { kNearest, kAny, kAll };

struct CastOptions {
  CastMode mode = CastMode::kNearest;
  bool binary = false;
  std::string source = "<stdin>";  // name of the ray input, for error messages
  long first_record = 0;           // binary records are numbered from first_record + 1 in messages
};

/// Reads rays from `in`, answers them on `scene` (in parallel, in batches) and writes one answer
/// per ray to `out` in input order. Text rays: `ox oy oz dx dy dz [tmin [tmax]]` per line, blank
/// and `#` lines skipped. Binary: 8 little-endian float64 per ray. A malformed line, a truncated
/// binary record or a ray with a zero or non-finite direction throws SceneError naming it.
void run_cast(const Scene& scene, std::istream& in, std::ostream& out, const CastOptions& options);

}  // namespace raycast
