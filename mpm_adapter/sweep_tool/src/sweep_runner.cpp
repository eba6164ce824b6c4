#include "acst_sweep/sweep_runner.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <ostream>

#include "acst_common/cli.hpp"
#include "acst_common/duration.hpp"
#include "acst_common/files.hpp"
#include "acst_common/folder_lock.hpp"
#include "acst_common/input_error.hpp"
#include "acst_common/one_line.hpp"
#include "acst_common/progress.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_footing_tool/build_simulation.hpp"
#include "acst_footing_tool/scene_size.hpp"
#include "acst_sweep/case_record.hpp"
#include "acst_sweep/kept_results.hpp"
#include "acst_sweep/sweep_case.hpp"
#include "acst_sweep/sweep_figures.hpp"
#include "acst_sweep/sweep_table.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

void InTurn::distribute(const std::vector<std::size_t>& pending, const RunOne& run_one, const Finished& finished) {
  for (std::size_t i : pending) finished(i, run_one(i));
}

namespace {

// Entries of SWEEP/cases that a sweep writes: case folders (plain names, each with its record,
// which is written before the folder is published) and the hidden partial folders, fingerprints
// and publishing leftovers. Anything else is the user's: a rerun would replace a folder named
// like a case, so it is refused untouched.
void require_own_cases_folder(const std::string& dir) {
  const fs::path cases = fs::path(dir) / sweep_cases_folder;
  if (!fs::exists(cases)) return;
  if (!fs::is_directory(cases)) throw common::InputError("'" + cases.string() + "' is not a folder");
  const auto refuse = [&](const std::string& name, const std::string& what) {
    throw common::InputError("the sweep folder '" + cases.string() + "' holds '" + name + "', " + what +
                             ", which acst_sweep does not write: move it away, or choose an empty folder or one of "
                             "an earlier sweep");
  };
  for (const fs::directory_entry& e : fs::directory_iterator(cases)) {
    const std::string name = e.path().filename().string();
    const bool hidden_own = name.size() > 1 && name[0] == '.' &&
                            (name.find(".partial") != std::string::npos || common::is_temporary_name(name));
    if (hidden_own) continue;
    if (e.is_symlink() || !e.is_directory()) refuse(name, e.is_symlink() ? "a link" : "a file");
    if (!fs::is_regular_file(e.path() / sweep_case_record) || fs::is_symlink(e.path() / sweep_case_record))
      refuse(name, std::string("a folder without a case record (") + sweep_case_record + ")");
  }
}

// "(first difference at /scene/footing/speed)" between a finished case's fingerprint and now.
std::string first_difference(const json& then, const json& now) {
  const json patch = json::diff(then, now);
  return patch.empty() ? "" : " (first difference at " + patch[0].value("path", std::string("?")) + ")";
}

// What the reader cannot see in a scene alone (a followed particle outside the soil, a material
// that refuses its start) shows when its simulation is built: each case to run is built once
// here, so that such a case stops the sweep before anything runs, not hours into it. Returns each
// case's expected work in particle-steps (index as in the sweep; 0 for the cases not to run).
std::vector<double> check_buildable(const SweepSpec& sweep, const std::vector<std::size_t>& pending) {
  std::string problems;
  std::vector<double> work(sweep.cases.size(), 0.0);
  for (std::size_t i : pending) {
    try {
      const Simulation sim = build_simulation(sweep.cases[i].scene);
      work[i] = expected_particle_steps(sweep.cases[i].scene, sim.stable_time_step());
    } catch (const std::exception& e) {
      problems += "\n  case '" + sweep.cases[i].name + "' (" + sweep.cases[i].origin + "): " + e.what();
    }
  }
  if (!problems.empty()) throw common::InputError("cases that cannot start:" + problems);
  return work;
}

struct Plan {
  std::vector<ordered_json> rows;
  std::vector<std::size_t> pending;
  std::vector<double> work;  // expected particle-steps per case (check_buildable)
  std::size_t skipped = 0;
};

// The order cases are handed out in. In turn: as the sweep lists them. Over several workers:
// the longest first, so that the last case to start is a short one and no worker idles long at
// the end while another finishes a long case (the 27 cases of the reference study are a third
// half-domain runs of about half the others' length).
std::vector<std::size_t> hand_out_order(const Plan& plan, int workers) {
  std::vector<std::size_t> order = plan.pending;
  if (workers > 1)
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return plan.work[a] > plan.work[b]; });
  return order;
}

// Which cases have run (kept as they are), and which are to run.
Plan plan_sweep(const SweepSpec& sweep, const SweepRunOptions& opt) {
  Plan plan;
  for (std::size_t i = 0; i < sweep.cases.size(); ++i) {
    const SweepCase& c = sweep.cases[i];
    const std::optional<CaseRecord> record = read_case_record(opt.output_dir, c.name);
    if (!record) {
      plan.rows.push_back(case_row(c, "", CaseStatus::pending, "", sweep.load_at_S_over_B));
      plan.pending.push_back(i);
      continue;
    }
    const json fingerprint = case_fingerprint(c);
    if (record->fingerprint != fingerprint)
      throw common::InputError("case '" + c.name + "' (" + c.origin + "): '" + case_folder(opt.output_dir, c.name) +
                               "' holds a run of another scene or material" +
                               first_difference(record->fingerprint, fingerprint) +
                               "; remove that folder to run the case again");
    // The row is read again from the case's folder: a newer acst_sweep gathers every case alike.
    plan.rows.push_back(
        case_row(c, case_folder(opt.output_dir, c.name), record->status, record->message, sweep.load_at_S_over_B));
    plan.rows.back()["resumed"] = record->resumed;
    if (opt.retry_failed && record->status != CaseStatus::done) {
      plan.pending.push_back(i);
    } else {
      ++plan.skipped;
    }
  }
  plan.work = check_buildable(sweep, plan.pending);
  return plan;
}

// The table and the report as they stand.
void gather(const SweepSpec& sweep, const std::vector<ordered_json>& rows, const SweepRunOptions& opt) {
  write_sweep_table(sweep, rows, opt.output_dir);
  write_sweep_report(sweep, rows, opt.output_dir, opt.report, opt.command);
}

std::string finished_line(const SweepCase& c, const ordered_json& row) {
  char text[400];
  if (status_of(row) == CaseStatus::done && row.contains("q_ult_kPa")) {
    std::snprintf(text, sizeof text, "%s: done in %s, q_ult %.1f kPa at S/B %.4f%s", c.name.c_str(),
                  common::duration_text(row.value("wall_s", 0.0)).c_str(), row["q_ult_kPa"].get<double>(),
                  row["S_ult_over_B"].get<double>(), row.value("resumed", false) ? " (resumed from its checkpoint)" : "");
    const std::string note = row.value("message", std::string());  // a done case's: its checkpoint discarded
    return note.empty() ? std::string(text) : std::string(text) + " (" + common::one_line(note) + ")";
  }
  return c.name + ": " + name_of(status_of(row)) + ": " + common::one_line(row.value("message", std::string()));
}

}  // namespace

int run_sweep(const SweepSpec& sweep, const SweepRunOptions& opt, CaseDistributor& where, std::ostream& out,
              std::ostream& err) {
  Plan plan;
  std::string problem;
  // Held by the coordinator until the sweep ends: a second sweep into the folder is refused.
  std::optional<common::FolderLock> lock;
  if (where.coordinator()) {
    try {
      common::require_own_folder(opt.output_dir, is_sweep_output_name);
      lock.emplace(opt.output_dir, sweep_lock_file, "acst_sweep");
      require_own_cases_folder(opt.output_dir);
      plan = plan_sweep(sweep, opt);
      fs::create_directories(fs::path(opt.output_dir) / sweep_cases_folder);
      common::write_file_atomically((fs::path(opt.output_dir) / "sweep.json").string(),
                                    json::parse(sweep.text).dump(2) + "\n");
      gather(sweep, plan.rows, opt);
    } catch (const std::exception& e) {
      problem = e.what();
      if (lock && plan.rows.empty()) lock->undo();  // refused before writing: nothing left behind
    }
  }
  if (!where.all(problem.empty())) {
    if (where.coordinator()) err << "acst_sweep: " << (problem.empty() ? "another rank could not start" : problem) << "\n";
    return common::exit_bad_input;
  }

  CaseRunOptions case_opt;
  case_opt.sweep_dir = opt.output_dir;
  case_opt.threads = opt.threads;
  case_opt.plot = opt.plot;
  const auto run_one = [&](std::size_t i) {
    try {
      return run_case(sweep.cases[i], case_opt, sweep.load_at_S_over_B).dump();
    } catch (const std::exception& e) {  // its folder could not be written: the others go on
      return case_row(sweep.cases[i], "", CaseStatus::failed, e.what(), sweep.load_at_S_over_B).dump();
    }
  };
  if (!where.coordinator()) {
    where.distribute({}, run_one, {});
    return common::exit_done;
  }

  common::ProgressLine progress(err, !opt.quiet);
  if (!opt.quiet)
    progress.finish("acst_sweep: " + sweep.name + ": " + std::to_string(sweep.cases.size()) + " cases, " +
                    std::to_string(plan.skipped) + " already run (kept), " + std::to_string(plan.pending.size()) +
                    " to run on " + std::to_string(where.workers()) + " worker" + (where.workers() > 1 ? "s" : ""));
  std::size_t ended = 0;
  double work_total = 0.0, work_ended = 0.0;  // the time left goes by the expected work, not the case count
  for (std::size_t i : plan.pending) work_total += plan.work[i];
  std::vector<std::string> warnings;
  where.distribute(hand_out_order(plan, where.workers()), run_one, [&](std::size_t i, const std::string& row_text) {
    plan.rows[i] = ordered_json::parse(row_text);
    ++ended;
    work_ended += plan.work[i];
    try {
      gather(sweep, plan.rows, opt);
    } catch (const std::exception& e) {
      warnings.push_back(e.what());
    }
    if (!opt.quiet)
      progress.finish("[" + std::to_string(ended) + "/" + std::to_string(plan.pending.size()) + "] " +
                      finished_line(sweep.cases[i], plan.rows[i]) + "; " + common::duration_text(progress.elapsed_s()) +
                      " elapsed, " +
                      common::ProgressLine::time_left(progress.elapsed_s(), work_total > 0.0 ? work_ended / work_total
                                                                                            : double(ended) / double(plan.pending.size())));
  });
  if (sweep.figures && opt.plot)
    for (const std::string& w : write_group_figures(sweep, plan.rows, opt.output_dir)) warnings.push_back(w);
  if (sweep.keep)
    for (const SweepCase& c : sweep.cases)
      for (const std::string& w : keep_case_results(*sweep.keep, c, opt.output_dir)) warnings.push_back(w);
  if (sweep.figures && opt.plot)  // drawn from the kept results, so after them
    for (const std::string& w : write_panel_figures(sweep, opt.output_dir)) warnings.push_back(w);
  try {
    gather(sweep, plan.rows, opt);  // the report links the figures now there
  } catch (const std::exception& e) {
    warnings.push_back(e.what());
  }
  for (const std::string& w : warnings) err << "acst_sweep: warning: " << w << "\n";

  std::size_t done = 0;
  for (const ordered_json& r : plan.rows) done += status_of(r) == CaseStatus::done;
  out << sweep.name << ": " << done << " of " << sweep.cases.size() << " cases done";
  if (done < sweep.cases.size()) {
    out << "; not done:";
    for (const ordered_json& r : plan.rows)
      if (status_of(r) != CaseStatus::done) out << " " << r.value("case", std::string()) << " (" << name_of(status_of(r)) << ")";
  }
  out << "\ntable: " << (fs::path(opt.output_dir) / "table.md").string() << "\n";
  return done == sweep.cases.size() ? common::exit_done : common::exit_failed;
}

int replot_sweep(const SweepSpec& sweep, const SweepRunOptions& opt, std::ostream& out, std::ostream& err) {
  std::vector<ordered_json> rows;
  std::optional<common::FolderLock> lock;
  try {
    common::require_own_folder(opt.output_dir, is_sweep_output_name);
    const fs::path table = fs::path(opt.output_dir) / "table.json";
    if (!fs::exists(table)) throw common::InputError("'" + table.string() + "' does not exist: nothing to re-plot");
    lock.emplace(opt.output_dir, sweep_lock_file, "acst_sweep");
    const ordered_json t = ordered_json::parse(common::read_input_file(table.string()), nullptr, false);
    if (!t.is_object() || !t.contains("cases") || !t["cases"].is_array() || t["cases"].size() != sweep.cases.size())
      throw common::InputError("'" + table.string() + "' does not list the " + std::to_string(sweep.cases.size()) +
                               " cases of sweep '" + sweep.name + "'");
    for (std::size_t i = 0; i < sweep.cases.size(); ++i) {
      const ordered_json& r = t["cases"][i];
      if (!r.is_object() || r.value("case", std::string()) != sweep.cases[i].name)
        throw common::InputError("'" + table.string() + "': row " + std::to_string(i) + " is not case '" +
                                 sweep.cases[i].name + "' of this description");
      rows.push_back(r);
    }
  } catch (const std::exception& e) {
    err << "acst_sweep: " << e.what() << "\n";
    return common::exit_bad_input;
  }
  std::vector<std::string> warnings;
  if (sweep.figures && opt.plot) {
    for (const std::string& w : write_group_figures(sweep, rows, opt.output_dir)) warnings.push_back(w);
    for (const std::string& w : write_panel_figures(sweep, opt.output_dir)) warnings.push_back(w);
  }
  write_sweep_report(sweep, rows, opt.output_dir, opt.report, opt.command);
  for (const std::string& w : warnings) err << "acst_sweep: warning: " << w << "\n";
  out << sweep.name << ": figures and report drawn again from " << opt.output_dir << "\n";
  return common::exit_done;
}

}  // namespace acst::mpm
