#include "acst_sweep/sweep_budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "acst_common/csv_table.hpp"
#include "acst_common/files.hpp"
#include "acst_common/input_error.hpp"
#include "acst_sweep/case_status.hpp"

namespace acst::mpm {

SweepBudget::SweepBudget(double minutes, SweepClock::time_point start) : limited_(true), minutes_(minutes) {
  const double total_s = 60.0 * minutes;
  // 5 % of the budget, at most two minutes: a checkpoint and the table take seconds, the figures
  // of a large study about a minute.
  reserve_s_ = std::min(120.0, 0.05 * total_s);
  deadline_ = start + std::chrono::duration_cast<SweepClock::duration>(std::chrono::duration<double>(total_s - reserve_s_));
}

double SweepBudget::left_s(SweepClock::time_point now) const {
  return std::chrono::duration<double>(deadline_ - now).count();
}

double parse_budget_minutes(const std::string& text) {
  char* end = nullptr;
  const double m = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(m) || !(m > 0.0) || m > 525600.0)
    throw common::InputError("--budget '" + text + "': expected the minutes this run may take, a number > 0 and at most 525600 (a year)");
  return m;
}

double CaseTimeEstimate::seconds(double work, int threads, double fraction) const {
  return estimate_margin * work * fraction * seconds_per_work_thread / std::max(1, threads);
}

CaseTimeEstimate estimate_from(const std::vector<nlohmann::ordered_json>& rows, const std::vector<double>& work,
                               double assumed_rate) {
  CaseTimeEstimate e;
  double seconds = 0.0, units = 0.0;
  for (std::size_t i = 0; i < rows.size() && i < work.size(); ++i) {
    const nlohmann::ordered_json& r = rows[i];
    if (status_of(r) != CaseStatus::done || r.value("resumed", false) || !(work[i] > 0.0)) continue;
    const auto wall = r.find("wall_s"), threads = r.find("threads");
    if (wall == r.end() || threads == r.end() || !wall->is_number() || !threads->is_number()) continue;
    seconds += wall->get<double>() * threads->get<double>();
    units += work[i];
    ++e.measured_on;
  }
  e.seconds_per_work_thread = e.measured_on > 0 && seconds > 0.0 ? seconds / units
                                                                 : 1.0 / (assumed_rate > 0 ? assumed_rate : assumed_particle_steps_per_s_thread);
  if (!(seconds > 0.0)) e.measured_on = 0;
  return e;
}

double fraction_left(const std::string& partial_folder, double stop_S_over_B) {
  const std::filesystem::path record = std::filesystem::path(partial_folder) / "load_settlement.partial.csv";
  if (!(stop_S_over_B > 0.0) || !std::filesystem::is_regular_file(record)) return 1.0;
  try {
    const std::vector<double> s = common::parse_csv_table(common::read_input_file(record.string())).values("S_over_B");
    if (s.empty() || !std::isfinite(s.back())) return 1.0;
    return std::clamp(1.0 - s.back() / stop_S_over_B, 0.05, 1.0);
  } catch (const std::exception&) {
    return 1.0;  // an estimate only: a damaged record counts the case whole
  }
}

}  // namespace acst::mpm
