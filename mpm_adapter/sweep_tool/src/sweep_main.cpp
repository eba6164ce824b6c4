// acst_sweep: runs a footing sweep (docs/sweeps.md), in turn or over MPI ranks under mpirun.
#include <cstdlib>
#include <iostream>

#include "acst_common/cli.hpp"
#include "acst_sweep/sweep_runner.hpp"
#ifdef ACST_HAVE_MPI
#include "sweep_mpi.hpp"
#endif

namespace {

// Whether an MPI launcher started this process (Open MPI, MPICH/Hydra, PMIx); without one the
// tool runs the cases in turn and never initialises MPI.
bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args = acst::common::arguments(argc, argv);
  if (launched_by_mpirun()) {
#ifdef ACST_HAVE_MPI
    return acst::mpm::sweep_over_mpi(argc, argv, args);
#else
    std::cerr << "acst_sweep: started by mpirun, but this build has no MPI (configure with Open MPI installed: "
                 "libopenmpi-dev; docs/sweeps.md); running the cases in turn in every rank would repeat them\n";
    return acst::common::exit_bad_input;
#endif
  }
  return acst::mpm::sweep_cli(args, std::cout, std::cerr);
}
