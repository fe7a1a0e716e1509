// `mpirun -n K suspend sweep ...`: the points of a campaign handed out to MPI ranks one at a time. Rank 0 keeps the
// list, hands the next point to whichever rank asks, and writes the table; ranks 1..K-1 each run the points they
// are given, exactly as `suspend sweep --point NAME` would (so a point's result does not depend on where it ran).
// Built only when CMake finds MPI (SUSPEND_HAVE_MPI); under one rank it is the local sweep.
#pragma once
#include "campaign/sweep.hpp"

namespace suspend::campaign {

// True when this process was started by an MPI launcher (mpirun, srun with PMI) and the program has MPI.
bool launched_by_mpi();

// Same exit codes as run_sweep (on every rank: the outcome of the whole sweep).
int run_sweep_mpi(const Campaign& c, const SweepOptions& o);

}  // namespace suspend::campaign
