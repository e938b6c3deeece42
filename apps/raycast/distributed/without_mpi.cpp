// The distributed entry points of a build without MPI (RAYCAST_MPI off): several processes were
// started by a launcher, and each would do the whole job and write the same files, so refuse.
#include <cstdio>

#include "distributed/distributed.h"

namespace raycast::cli::distributed {

namespace {

int refuse(const char* command) {
  std::fprintf(stderr,
               "raycast %s: started by an MPI launcher with several processes, but this raycast "
               "was built without MPI (RAYCAST_MPI=OFF); run it without mpirun, or rebuild with "
               "OpenMPI installed (docs/distributed.md)\n",
               command);
  return 2;
}

}  // namespace

int render_frames(const std::string&, const std::string&, int, int, const RenderOptions&) {
  return refuse("render");
}

int render_image(const std::string&, const std::string&, const RenderOptions&,
                 const std::vector<std::pair<std::string, RenderMode>>&) {
  return refuse("render");
}

int cast(const std::string&, const std::string&, const std::string&, const CastOptions&) {
  return refuse("cast");
}

}  // namespace raycast::cli::distributed
