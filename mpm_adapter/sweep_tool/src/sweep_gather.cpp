// acst_sweep --gather (docs/sweeps.md, "Pieces, shards and budgets"): the kept results of several
// folders of one sweep merged into one.
#include <filesystem>
#include <optional>
#include <ostream>

#include "acst_common/cli.hpp"
#include "acst_common/files.hpp"
#include "acst_common/folder_lock.hpp"
#include "acst_common/input_error.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_sweep/case_record.hpp"
#include "acst_sweep/kept_results.hpp"
#include "acst_sweep/sweep_case.hpp"
#include "acst_sweep/sweep_figures.hpp"
#include "acst_sweep/sweep_folder.hpp"
#include "acst_sweep/sweep_runner.hpp"
#include "acst_sweep/sweep_state.hpp"
#include "acst_sweep/sweep_table.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

namespace {

// A row without what differs between two runs of one case (time, threads, a resumption).
ordered_json result_of(ordered_json row) {
  for (const char* k : {"wall_s", "resumed", "threads"}) row.erase(k);
  return row;
}

// Copies `from` (a kept case folder) to `to` whole: built beside it, then put in place.
void copy_kept_folder(const fs::path& from, const fs::path& to) {
  const fs::path staging = to.parent_path() / ("." + to.filename().string() + ".partial");
  fs::remove_all(staging);
  fs::create_directories(staging);
  for (const fs::directory_entry& e : fs::directory_iterator(from)) {
    if (!e.is_regular_file() || e.is_symlink()) continue;  // the sweep keeps plain files only
    common::write_file_atomically((staging / e.path().filename()).string(), common::read_input_file(e.path().string()));
  }
  (void)common::publish_folder(staging.string(), to.string());
}

}  // namespace

int gather_sweeps(const SweepSpec& sweep, const std::vector<std::string>& from, const SweepRunOptions& opt,
                  std::ostream& out, std::ostream& err) {
  // Case i comes from folder source[i] (-1: none has it).
  std::vector<int> source(sweep.cases.size(), -1);
  std::vector<ordered_json> rows;
  std::optional<common::FolderLock> lock;
  try {
    const json description = json::parse(sweep.text);
    for (std::size_t k = 0; k < from.size(); ++k) {
      const fs::path dir(from[k]);
      if (fs::exists(opt.output_dir) && fs::exists(dir) && fs::equivalent(dir, opt.output_dir))
        throw common::InputError("--gather '" + from[k] + "' is the --output folder; gather into another one");
      require_sound_sweep_folder(from[k]);
      const fs::path recorded = dir / "sweep.json";
      if (!fs::is_regular_file(fs::symlink_status(recorded)))
        throw common::InputError("--gather '" + from[k] + "': not a sweep's folder (it has no sweep.json)");
      const json theirs = json::parse(common::read_input_file(recorded.string()), nullptr, false);
      if (theirs != description)
        throw common::InputError("--gather '" + from[k] + "': a folder of another description than '" + sweep.file + "'" +
                                 first_difference(theirs, description));
      const std::vector<CaseState> states = read_case_states(sweep, from[k]);
      for (std::size_t i = 0; i < states.size(); ++i) {
        if (states[i].from == CaseState::From::nothing) continue;
        if (!fs::is_regular_file(fs::path(kept_case_folder(from[k], sweep.cases[i].name)) / sweep_case_record))
          throw common::InputError("--gather '" + from[k] + "': case '" + sweep.cases[i].name +
                                   "' has no kept results (run acst_sweep on that folder once to keep them)");
        if (source[i] >= 0 && result_of(states[i].row) != result_of(rows[i]))
          throw common::InputError("case '" + sweep.cases[i].name + "' is in '" + from[static_cast<std::size_t>(source[i])] +
                                   "' and '" + from[k] + "' with different results; keep one of them");
        if (source[i] < 0) {
          if (rows.empty()) rows.resize(sweep.cases.size());
          rows[i] = states[i].row;
          source[i] = static_cast<int>(k);
        }
      }
    }
    rows.resize(sweep.cases.size());
    for (std::size_t i = 0; i < sweep.cases.size(); ++i)
      if (source[i] < 0) rows[i] = case_row(sweep.cases[i], "", CaseStatus::pending, "", sweep.load_at_S_over_B);
    common::require_own_folder(opt.output_dir, is_sweep_output_name);
    require_sound_sweep_folder(opt.output_dir);
    lock.emplace(opt.output_dir, sweep_lock_file, "acst_sweep");
    // Cases already in the output are those of an earlier gather: replaced by the sources'.
    fs::create_directories(fs::path(opt.output_dir) / sweep_kept_folder);
    common::write_file_atomically((fs::path(opt.output_dir) / "sweep.json").string(), description.dump(2) + "\n");
    for (std::size_t i = 0; i < sweep.cases.size(); ++i)
      if (source[i] >= 0)
        copy_kept_folder(kept_case_folder(from[static_cast<std::size_t>(source[i])], sweep.cases[i].name),
                         kept_case_folder(opt.output_dir, sweep.cases[i].name));
    write_sweep_table(sweep, rows, opt.output_dir);
  } catch (const std::exception& e) {
    err << "acst_sweep: " << e.what() << "\n";
    if (lock && !fs::exists(fs::path(opt.output_dir) / "table.json")) lock->undo();
    return common::exit_bad_input;
  }
  std::vector<std::string> warnings;
  if (sweep.figures && opt.plot) {
    for (const std::string& w : write_group_figures(sweep, rows, opt.output_dir)) warnings.push_back(w);
    for (const std::string& w : write_panel_figures(sweep, opt.output_dir)) warnings.push_back(w);
  }
  write_sweep_report(sweep, rows, opt.output_dir, opt.report, opt.command);
  for (const std::string& w : warnings) err << "acst_sweep: warning: " << w << "\n";
  std::size_t done = 0, found = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    done += status_of(rows[i]) == CaseStatus::done;
    found += source[i] >= 0;
  }
  out << sweep.name << ": gathered " << found << " of " << sweep.cases.size() << " cases from " << from.size()
      << " folder" << (from.size() > 1 ? "s" : "") << " (" << done << " done)\ntable: "
      << (fs::path(opt.output_dir) / "table.md").string() << "\n";
  return common::exit_done;
}

}  // namespace acst::mpm
