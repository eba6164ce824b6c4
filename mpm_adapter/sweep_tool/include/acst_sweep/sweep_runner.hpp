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

#include "acst_sweep/case_selection.hpp"
#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

// Where the cases run. The coordinator (the only process, or MPI rank 0) decides what runs and
// gathers; the other processes run what it hands out.
class CaseDistributor {
 public:
  using RunOne = std::function<std::string(std::size_t)>;               // case index -> its row (JSON text)
  using Finished = std::function<void(std::size_t, const std::string&)>;  // on the coordinator, as each ends
  using MayStart = std::function<bool(std::size_t)>;  // on the coordinator, just before a case is handed out
  virtual ~CaseDistributor() = default;
  virtual bool coordinator() const = 0;
  virtual int workers() const = 0;
  // Whether every process says `ok` (all processes call it at the same point).
  virtual bool all(bool ok) = 0;
  // Coordinator: runs each case of `pending` that `may_start` allows when its turn comes, once,
  // somewhere, and calls `finished` for each; those it refuses are skipped. The others: run the
  // cases handed to them until there are none left (`pending` is not used).
  virtual void distribute(const std::vector<std::size_t>& pending, const RunOne& run_one, const Finished& finished,
                          const MayStart& may_start) = 0;
};

// One process, the cases in turn.
class InTurn : public CaseDistributor {
 public:
  bool coordinator() const override { return true; }
  int workers() const override { return 1; }
  bool all(bool ok) override { return ok; }
  void distribute(const std::vector<std::size_t>& pending, const RunOne& run_one, const Finished& finished,
                  const MayStart& may_start) override;
};

struct SweepRunOptions {
  std::string output_dir;
  int threads = 0;            // per case; 0: the scene's solver/threads, else all cores
  bool plot = true, quiet = false;
  bool retry_failed = false;  // run failed cases again instead of reporting them as they are
  std::string report;         // a copy of report.md here too ("" : none)
  std::string command;        // the command line, for the report
  double budget_minutes = 0;  // --budget (0: none), counted from the call of run_sweep
  // The rate the budget assumes before any case of the folder has run whole, in particle-steps a
  // second a thread (0: assumed_particle_steps_per_s_thread, sweep_budget.hpp).
  double assumed_rate = 0;
  Shard shard;                // --shard K/N
  std::vector<std::string> only;  // --only: names or shell patterns
};

// The exit status of a run stopped by its budget with cases waiting (sysexits' EX_TEMPFAIL: a
// batch system requeues on it).
inline constexpr int exit_budget_spent = 75;

// Exit status: 0 every case of this run's selection done; 1 a case failed (the others ran; the
// table says which); 2 the output folder cannot be used (nothing is run or written); 75 the
// budget ended with cases waiting (exit_budget_spent).
int run_sweep(const SweepSpec& sweep, const SweepRunOptions& options, CaseDistributor& where, std::ostream& out,
              std::ostream& err);

// acst_sweep --replot: runs nothing; the table, the figures and the report drawn again from what
// the folder keeps (case folders and kept results; the cases with neither listed as pending).
// 0 when drawn, 2 when the folder cannot be used.
int replot_sweep(const SweepSpec& sweep, const SweepRunOptions& options, std::ostream& out, std::ostream& err);

// acst_sweep --gather DIR... --output OUT: the kept results of the sweep folders `from` (shards
// run apart, pieces from other machines) merged into OUT with one table, report and figures. A
// folder of another description, or a case kept in two folders with different rows, is refused
// (2, nothing written); a case in none stays pending.
int gather_sweeps(const SweepSpec& sweep, const std::vector<std::string>& from, const SweepRunOptions& options,
                  std::ostream& out, std::ostream& err);

// acst_sweep's command line (the usage text says it all). `where`: MPI ranks when the tool runs
// under mpirun; null: the cases in turn. `default_threads`: threads per case when --threads is
// not given (0: the scene's, else all cores).
int sweep_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, CaseDistributor* where = nullptr,
              int default_threads = 0);

}  // namespace acst::mpm
