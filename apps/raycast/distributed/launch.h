#pragma once
// Whether this process was started by an MPI launcher (mpirun, mpiexec, srun), read from the
// environment the launchers set. Checking the environment costs nothing, whereas MPI_Init in a
// process that no launcher started (a "singleton") takes most of a second with OpenMPI 4.1, so a
// plain `raycast render` never initialises MPI (docs/distributed.md).
namespace raycast::cli::distributed {

/// The number of processes the launcher started: 0 when no launcher did, -1 when one did but
/// did not say how many (PMIx under srun).
int launch_size();

/// Whether the distributed code path runs: with RAYCAST_MPI, under any launcher (even
/// `mpirun -np 1`); without it, only when several processes were started, so that the command
/// can refuse instead of every process doing the whole job and writing the same files.
bool active();

}  // namespace raycast::cli::distributed
