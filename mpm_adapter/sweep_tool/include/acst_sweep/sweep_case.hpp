#pragma once
// One case of a sweep in its own folder (docs/sweeps.md, "Folders"): run in SWEEP/cases/.NAME.partial
// (checkpointed there), then published whole as SWEEP/cases/NAME with its record, the row of the
// sweep's table.
#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "acst_sweep/case_status.hpp"
#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

inline constexpr const char* sweep_cases_folder = "cases";
inline constexpr const char* sweep_case_record = "sweep_case.json";
// In the sweep's folder, locked by the running acst_sweep (common::FolderLock); holds its PID.
inline constexpr const char* sweep_lock_file = ".acst_sweep.lock";

std::string case_folder(const std::string& sweep_dir, const std::string& name);
std::string case_partial_folder(const std::string& sweep_dir, const std::string& name);

// What a case's results depend on: its scene, its materials' parameters and the build options
// that change numbers (-march=native: {"build": {"march_native": true}}). A checkpoint or a
// finished case made from another fingerprint is not this case's. The thread count is left out:
// the table's `threads` column says it (docs/sweeps.md, "Kept results").
nlohmann::json case_fingerprint(const SweepCase& c);

struct CaseRunOptions {
  std::string sweep_dir;
  int threads = 0;  // 0: the scene's solver/threads, else all cores
  bool plot = true;
  std::optional<std::chrono::steady_clock::time_point> stop_at;  // the budget's deadline
};

// Runs the case (from its checkpoint when an interrupted run of the same fingerprint left one),
// publishes its folder and returns its row; a run that fails is published
// too, with status "failed" and the message in its row. `note` (why it runs again) starts the
// row's message. A run stopped at `stop_at` is left checkpointed in its partial folder, nothing
// published, and its row is pending, its message saying so. A checkpoint is only a shortcut: one that cannot be
// resumed (damaged, or its fingerprint file is) is discarded and the case runs afresh, its row's
// message saying so. Throws std::runtime_error only when the folder cannot be written.
nlohmann::ordered_json run_case(const SweepCase& c, const CaseRunOptions& options,
                                const std::vector<double>& load_at_S_over_B, const std::string& note = "");

// Whether `name` is (or may be, as q_at_S_over_B_X_kPa) a column of the table that case_row
// writes besides the case's variables: a variable of that name would overwrite it or be
// overwritten, so the description's reader refuses it.
bool is_table_column(const std::string& name);

// Of a run that failed, the last part of its record (in S/B) that the row leaves out.
inline constexpr double failure_approach_S_over_B = 0.02;

// The row of a case from its run's files in `dir`: the load record (load_settlement.csv, or the
// record up to a failure) and summary.json when the run finished.
nlohmann::ordered_json case_row(const SweepCase& c, const std::string& dir, CaseStatus status,
                                const std::string& message, const std::vector<double>& load_at_S_over_B);

}  // namespace acst::mpm
