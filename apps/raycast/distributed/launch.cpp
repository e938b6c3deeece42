#include "distributed/launch.h"

#include <cstdlib>
#include <initializer_list>

namespace raycast::cli::distributed {

int launch_size() {
  // OpenMPI's mpirun, then MPICH/Intel MPI (hydra) and Slurm's PMI-1/2, then PMIx.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* value = std::getenv(name)) {
      const int size = std::atoi(value);
      return size > 0 ? size : -1;
    }
  }
  return std::getenv("PMIX_RANK") ? -1 : 0;
}

bool active() {
#ifdef RAYCAST_MPI
  return launch_size() != 0;
#else
  const int size = launch_size();
  return size != 0 && size != 1;
#endif
}

}  // namespace raycast::cli::distributed
