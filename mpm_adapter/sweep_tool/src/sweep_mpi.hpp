#pragma once
// acst_sweep under mpirun: rank 0 hands out whole cases and gathers their rows; every rank
// (rank 0 too, in a thread of its own) runs cases.
#include <string>
#include <vector>

namespace acst::mpm {

// Initialises MPI, runs the sweep's command line over the ranks, finalises MPI; returns the
// exit status (the same on every rank).
int sweep_over_mpi(int argc, char** argv, const std::vector<std::string>& args);

}  // namespace acst::mpm
