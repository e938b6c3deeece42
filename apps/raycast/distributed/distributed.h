#pragma once
// The commands' distributed (MPI) paths, run on every rank when distributed::active()
// (docs/distributed.md). Each returns the exit code of this rank: the same on every rank, 0 when
// the whole job succeeded. Rank 0 reports progress and errors for the whole job. Without
// RAYCAST_MPI they only explain that this build has no MPI and return 2.
#include <string>
#include <utility>
#include <vector>

#include "cast/cast.h"
#include "render/renderer.h"

namespace raycast::cli::distributed {

/// `render SCENE --frames A-B -o PATTERN`: frames handed out one at a time; each rank loads its
/// frame's scene and writes its image itself.
int render_frames(const std::string& scene, const std::string& output, int first, int last,
                  const RenderOptions& options);

/// `render [SCENE] -o OUT [--aov ...]`: every rank loads the scene; the image is cut into tiles
/// handed out one at a time; rank 0 gathers the pixels and writes the files.
int render_image(const std::string& scene, const std::string& output, const RenderOptions& options,
                 const std::vector<std::pair<std::string, RenderMode>>& aovs);

/// `cast SCENE --binary --rays IN -o OUT`: rank r answers the r-th contiguous slice of the rays
/// and writes its answers at their place in OUT with MPI-IO.
int cast(const std::string& scene, const std::string& rays, const std::string& output,
         const CastOptions& options);

}  // namespace raycast::cli::distributed
