#include "acst_sweep/sweep_runner.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <optional>
#include <ostream>
#include <thread>

#include "acst_common/cli.hpp"
#include "acst_common/duration.hpp"
#include "acst_common/files.hpp"
#include "acst_common/folder_lock.hpp"
#include "acst_common/input_error.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/one_line.hpp"
#include "acst_common/progress.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_sweep/case_record.hpp"
#include "acst_sweep/kept_results.hpp"
#include "acst_sweep/sweep_budget.hpp"
#include "acst_sweep/sweep_case.hpp"
#include "acst_sweep/sweep_figures.hpp"
#include "acst_sweep/sweep_folder.hpp"
#include "acst_sweep/sweep_state.hpp"
#include "acst_sweep/sweep_table.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

void InTurn::distribute(const std::vector<std::size_t>& pending, const RunOne& run_one, const Finished& finished,
                        const MayStart& may_start) {
  // A case refused now may fit once a finished case has measured the rate: after each case the
  // first that may start goes next, until none may.
  std::vector<std::size_t> left = pending;
  for (bool ran = true; ran && !left.empty();) {
    ran = false;
    for (auto it = left.begin(); it != left.end(); ++it) {
      if (!may_start(*it)) continue;
      const std::size_t i = *it;
      left.erase(it);
      finished(i, run_one(i));
      ran = true;
      break;
    }
  }
}

namespace {

struct Plan {
  std::vector<CaseState> states;
  std::vector<ordered_json> rows;
  std::vector<std::size_t> pending;  // this run's cases still to run
  std::vector<double> work;          // expected particle-steps (expected_case_work)
  std::vector<bool> chosen;          // this run's cases (--shard, --only)
  std::size_t mine = 0, kept = 0;    // this run's cases, and those of them already run
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

// The kept results of each case run in this folder, written again where its kept record is
// missing or is not the run's (a stop between publishing the case and keeping it).
std::vector<std::string> keep_what_is_missing(const SweepSpec& sweep, const std::vector<CaseState>& states,
                                              const std::string& dir) {
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (states[i].from != CaseState::From::case_folder) continue;
    const std::optional<CaseRecord> run = read_case_record(dir, sweep.cases[i].name);
    std::optional<CaseRecord> kept;
    try {
      kept = read_kept_record(dir, sweep.cases[i].name);
    } catch (const common::InputError&) {  // damaged: the run's folder has it whole
    }
    if (kept && run && kept->fingerprint == run->fingerprint && kept->row == run->row) continue;
    for (const std::string& w : keep_case_results(sweep.keep.value_or(KeepSpec{}), sweep.cases[i], dir)) warnings.push_back(w);
  }
  return warnings;
}

// Which cases have run (kept as they are), and which of this run's are to run.
Plan plan_sweep(const SweepSpec& sweep, const SweepRunOptions& opt) {
  Plan plan;
  plan.states = read_case_states(sweep, opt.output_dir);
  plan.rows = rows_of(plan.states);
  std::vector<std::size_t> every(sweep.cases.size());
  std::iota(every.begin(), every.end(), std::size_t{0});
  // The shards and the budget's measured rate need every case's work; otherwise the cases to run
  // are built alone.
  const bool all_work = opt.shard.n > 1 || opt.budget_minutes > 0;
  if (all_work) plan.work = expected_case_work(sweep, every);
  plan.chosen = selected_cases(sweep, all_work ? plan.work : std::vector<double>(sweep.cases.size(), 0.0), opt.shard,
                               opt.only);
  for (std::size_t i = 0; i < sweep.cases.size(); ++i) {
    if (!plan.chosen[i]) continue;
    ++plan.mine;
    const CaseState& s = plan.states[i];
    const bool run = s.from == CaseState::From::nothing ||
                     (opt.retry_failed && status_of(s.row) != CaseStatus::done);
    if (run)
      plan.pending.push_back(i);
    else
      ++plan.kept;
  }
  if (!all_work) plan.work = expected_case_work(sweep, plan.pending);
  return plan;
}

// The table and the report as they stand.
void gather(const SweepSpec& sweep, const std::vector<ordered_json>& rows, const SweepRunOptions& opt) {
  write_sweep_table(sweep, rows, opt.output_dir);
  write_sweep_report(sweep, rows, opt.output_dir, opt.report, opt.command);
}

// The figures and the report, once the table is complete for this run.
std::vector<std::string> draw(const SweepSpec& sweep, const std::vector<ordered_json>& rows, const SweepRunOptions& opt) {
  std::vector<std::string> warnings;
  if (sweep.figures && opt.plot) {
    for (const std::string& w : write_group_figures(sweep, rows, opt.output_dir)) warnings.push_back(w);
    for (const std::string& w : write_panel_figures(sweep, opt.output_dir)) warnings.push_back(w);
  }
  try {
    gather(sweep, rows, opt);  // the report links the figures now there
  } catch (const std::exception& e) {
    warnings.push_back(e.what());
  }
  return warnings;
}

// A folder recorded before kept results held each case's record (no case has one) has its rows in
// table.json only: --replot keeps those rows (a sweep never takes them as run, having no
// fingerprint to check them by). Returns how many it kept.
std::size_t rows_from_table_alone(const SweepSpec& sweep, const std::vector<CaseState>& states, const std::string& dir,
                                  std::vector<ordered_json>& rows) {
  const fs::path table = fs::path(dir) / "table.json";
  const bool recorded_before = std::all_of(states.begin(), states.end(),
                                           [](const CaseState& s) { return s.from == CaseState::From::nothing && s.stale.empty(); });
  if (!recorded_before || !fs::is_regular_file(table)) return 0;
  const ordered_json t = ordered_json::parse(common::read_input_file(table.string()), nullptr, false);
  if (!t.is_object() || !t.contains("cases") || !t["cases"].is_array()) return 0;
  std::size_t used = 0;
  for (std::size_t i = 0; i < sweep.cases.size(); ++i) {
    if (states[i].from != CaseState::From::nothing) continue;
    for (const ordered_json& r : t["cases"])
      if (r.is_object() && r.value("case", std::string()) == sweep.cases[i].name && status_of(r) != CaseStatus::pending) {
        rows[i] = r;
        ++used;
        break;
      }
  }
  return used;
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

// The threads a case runs with: --threads, else its scene's, else every core.
int threads_of(const SweepCase& c, const SweepRunOptions& opt) {
  if (opt.threads > 0) return opt.threads;
  if (c.scene.solver.threads > 0) return c.scene.solver.threads;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

int run_sweep(const SweepSpec& sweep, const SweepRunOptions& opt, CaseDistributor& where, std::ostream& out,
              std::ostream& err) {
  const SweepBudget budget = opt.budget_minutes > 0 ? SweepBudget(opt.budget_minutes, SweepClock::now()) : SweepBudget();
  Plan plan;
  std::string problem;
  std::vector<std::string> warnings;
  // Held by the coordinator until the sweep ends: a second sweep into the folder is refused.
  std::optional<common::FolderLock> lock;
  if (where.coordinator()) {
    try {
      common::require_own_folder(opt.output_dir, is_sweep_output_name);
      lock.emplace(opt.output_dir, sweep_lock_file, "acst_sweep");
      require_sound_sweep_folder(opt.output_dir);
      plan = plan_sweep(sweep, opt);
      fs::create_directories(fs::path(opt.output_dir) / sweep_cases_folder);
      common::write_file_atomically((fs::path(opt.output_dir) / "sweep.json").string(),
                                    json::parse(sweep.text).dump(2) + "\n");
      warnings = keep_what_is_missing(sweep, plan.states, opt.output_dir);
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
  if (budget.limited()) case_opt.stop_at = budget.deadline();
  const auto run_one = [&](std::size_t i) {
    const std::string& stale = plan.states.empty() ? std::string() : plan.states[i].stale;
    const std::string note = stale.empty() ? "" : "run again: its kept result was of another description" + stale;
    try {
      return run_case(sweep.cases[i], case_opt, sweep.load_at_S_over_B, note).dump();
    } catch (const std::exception& e) {  // its folder could not be written: the others go on
      return case_row(sweep.cases[i], "", CaseStatus::failed, e.what(), sweep.load_at_S_over_B).dump();
    }
  };
  if (!where.coordinator()) {
    // Workers: the coordinator decides what starts; a case they run stops at their own deadline,
    // counted from their own start, within the launch's spread of the coordinator's.
    where.distribute({}, run_one, {}, {});
    return common::exit_done;
  }

  common::ProgressLine progress(err, !opt.quiet);
  if (!opt.quiet)
    progress.finish("acst_sweep: " + sweep.name + ": " + std::to_string(sweep.cases.size()) + " cases" +
                    (plan.mine < sweep.cases.size() ? ", " + std::to_string(plan.mine) + " of them this run's" : "") +
                    ", " + std::to_string(plan.kept) + " already run (kept), " + std::to_string(plan.pending.size()) +
                    " to run on " + std::to_string(where.workers()) + " worker" + (where.workers() > 1 ? "s" : "") +
                    (budget.limited() ? " within a budget of " + common::fields::shown(budget.minutes()) + " min" : ""));
  std::size_t ended = 0;
  double work_total = 0.0, work_ended = 0.0;  // the time left goes by the expected work, not the case count
  for (std::size_t i : plan.pending) work_total += plan.work[i];
  std::vector<bool> started(sweep.cases.size(), false);
  std::string refused;  // what the budget said of the last case it did not start
  const auto may_start = [&](std::size_t i) -> bool {
    if (!budget.limited()) return started[i] = true;
    const CaseTimeEstimate estimate = estimate_from(plan.rows, plan.work, opt.assumed_rate);
    const SweepCase& c = sweep.cases[i];
    const double left = budget.left_s();
    const double need = estimate.seconds(
        plan.work[i], threads_of(c, opt),
        fraction_left(case_partial_folder(opt.output_dir, c.name), c.scene.stop.S_over_B.value_or(0.0)));
    if (need <= left) return started[i] = true;
    const std::string rate = estimate.measured_on > 0 ? "at the rate of the " + std::to_string(estimate.measured_on) +
                                                            " cases run whole in this folder"
                                                      : "at the assumed rate, no case having run whole in this folder yet";
    refused = c.name + " is expected to take " + common::duration_text(need) + " (" + rate + "), " +
              common::duration_text(std::max(0.0, left)) + " of the budget left";
    return false;
  };
  where.distribute(hand_out_order(plan, where.workers()), run_one, [&](std::size_t i, const std::string& row_text) {
    plan.rows[i] = ordered_json::parse(row_text);
    const bool interrupted = status_of(plan.rows[i]) == CaseStatus::pending;
    if (!interrupted) {
      try {
        for (const std::string& w : keep_case_results(sweep.keep.value_or(KeepSpec{}), sweep.cases[i], opt.output_dir))
          warnings.push_back(w);
      } catch (const std::exception& e) {
        warnings.push_back("case '" + sweep.cases[i].name + "': cannot keep its results: " + e.what());
      }
    }
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
  }, may_start);
  for (const std::string& w : draw(sweep, plan.rows, opt)) warnings.push_back(w);
  for (const std::string& w : warnings) err << "acst_sweep: warning: " << w << "\n";

  const std::vector<bool>& chosen = plan.chosen;
  std::size_t done = 0, waiting = 0, interrupted = 0, mine_done = 0;
  for (std::size_t i = 0; i < plan.rows.size(); ++i) {
    const CaseStatus s = status_of(plan.rows[i]);
    done += s == CaseStatus::done;
    if (!chosen[i]) continue;
    mine_done += s == CaseStatus::done;
    if (s == CaseStatus::pending) {
      ++waiting;
      interrupted += started[i];
    }
  }
  if (waiting > 0 && budget.limited()) {
    // Spent, or what is left too short for the next case (the estimate errs long by design).
    out << sweep.name << ": the budget of " << common::fields::shown(budget.minutes()) << " min is "
        << (budget.left_s() > 0.0 ? "too short for the cases that wait: " : "spent: ") << mine_done << " of " << plan.mine
        << " cases done, " << waiting << " wait";
    if (interrupted > 0) out << " (" << interrupted << " checkpointed)";
    if (waiting > interrupted && !refused.empty())
      out << (ended == 0 && interrupted == 0 ? "; too small for any case: " : "; the next would not end in time: ") << refused;
    out << "; run the same command again to go on\n";
    return exit_budget_spent;
  }
  out << sweep.name << ": " << done << " of " << sweep.cases.size() << " cases done";
  if (plan.mine < sweep.cases.size()) out << " (" << mine_done << " of this run's " << plan.mine << ")";
  bool failed = false;
  if (mine_done < plan.mine) {
    out << "; not done:";
    for (std::size_t i = 0; i < plan.rows.size(); ++i)
      if (chosen[i] && status_of(plan.rows[i]) != CaseStatus::done) {
        out << " " << sweep.cases[i].name << " (" << name_of(status_of(plan.rows[i])) << ")";
        failed = true;
      }
  }
  out << "\ntable: " << (fs::path(opt.output_dir) / "table.md").string() << "\n";
  return failed ? common::exit_failed : common::exit_done;
}

int replot_sweep(const SweepSpec& sweep, const SweepRunOptions& opt, std::ostream& out, std::ostream& err) {
  std::vector<ordered_json> rows;
  std::size_t legacy = 0;
  std::optional<common::FolderLock> lock;
  try {
    common::require_own_folder(opt.output_dir, is_sweep_output_name);
    require_sound_sweep_folder(opt.output_dir);
    const fs::path dir(opt.output_dir);
    if (!fs::is_regular_file(dir / "table.json") && !fs::is_directory(dir / sweep_kept_folder) &&
        !fs::is_directory(dir / sweep_cases_folder))
      throw common::InputError("'" + opt.output_dir + "' has no table.json, kept results or case folders: nothing to re-plot");
    lock.emplace(opt.output_dir, sweep_lock_file, "acst_sweep");
    const std::vector<CaseState> states = read_case_states(sweep, opt.output_dir);
    rows = rows_of(states);
    legacy = rows_from_table_alone(sweep, states, opt.output_dir, rows);
    write_sweep_table(sweep, rows, opt.output_dir);
  } catch (const std::exception& e) {
    err << "acst_sweep: " << e.what() << "\n";
    return common::exit_bad_input;
  }
  // A folder with rows alone has no load records to draw from: its figures are kept as they are.
  SweepRunOptions drawing = opt;
  if (legacy > 0) drawing.plot = false;
  for (const std::string& w : draw(sweep, rows, drawing)) err << "acst_sweep: warning: " << w << "\n";
  std::size_t done = 0;
  for (const ordered_json& r : rows) done += status_of(r) == CaseStatus::done;
  out << sweep.name << ": table, figures and report drawn again from " << opt.output_dir << " (" << done << " of "
      << sweep.cases.size() << " cases done";
  if (legacy > 0)
    out << "; " << legacy << " rows from its table.json alone, kept by an acst_sweep before case records were: its "
        << "figures are left as they are";
  out << ")\n";
  return common::exit_done;
}

}  // namespace acst::mpm
