#pragma once
// Runs a sweep's cases and gathers them (docs/sweeps.md): finished cases are skipped, interrupted
// ones resume from their checkpoints, the others run, in turn or spread over MPI ranks by a
// CaseDistributor; the table (CSV, markdown, JSON) is rewritten as each case ends, the group
// figures at the end.
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

// Where the cases run. The coordinator (the only process, or MPI rank 0) decides what runs and
// gathers; the other processes run what it hands out.
class CaseDistributor {
 public:
  using RunOne = std::function<std::string(std::size_t)>;               // case index -> its row (JSON text)
  using Finished = std::function<void(std::size_t, const std::string&)>;  // on the coordinator, as each ends
  virtual ~CaseDistributor() = default;
  virtual bool coordinator() const = 0;
  virtual int workers() const = 0;
  // Whether every process says `ok` (all processes call it at the same point).
  virtual bool all(bool ok) = 0;
  // Coordinator: runs each case of `pending` once, somewhere, and calls `finished` for each. The
  // others: run the cases handed to them until there are none left (`pending` is not used).
  virtual void distribute(const std::vector<std::size_t>& pending, const RunOne& run_one, const Finished& finished) = 0;
};

// One process, the cases in turn.
class InTurn : public CaseDistributor {
 public:
  bool coordinator() const override { return true; }
  int workers() const override { return 1; }
  bool all(bool ok) override { return ok; }
  void distribute(const std::vector<std::size_t>& pending, const RunOne& run_one, const Finished& finished) override;
};

struct SweepRunOptions {
  std::string output_dir;
  int threads = 0;            // per case; 0: the scene's solver/threads, else all cores
  bool plot = true, quiet = false;
  bool retry_failed = false;  // run failed cases again instead of reporting them as they are
  std::string report;         // a copy of report.md here too ("" : none)
  std::string command;        // the command line, for the report
};

// Exit status: 0 every case done; 1 a case failed (the others ran; the table says which);
// 2 the output folder cannot be used (nothing is run or written).
int run_sweep(const SweepSpec& sweep, const SweepRunOptions& options, CaseDistributor& where, std::ostream& out,
              std::ostream& err);

// acst_sweep --replot: runs nothing; the figures and the report drawn again from the folder's
// table.json (which must list this description's cases) and kept results. 0 when drawn, 2 when
// the folder cannot be used.
int replot_sweep(const SweepSpec& sweep, const SweepRunOptions& options, std::ostream& out, std::ostream& err);

// acst_sweep's command line (the usage text says it all). `where`: MPI ranks when the tool runs
// under mpirun; null: the cases in turn. `default_threads`: threads per case when --threads is
// not given (0: the scene's, else all cores).
int sweep_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, CaseDistributor* where = nullptr,
              int default_threads = 0);

}  // namespace acst::mpm
