#include "acst_sweep/sweep_state.hpp"

#include <optional>

#include "acst_common/input_error.hpp"
#include "acst_sweep/case_record.hpp"
#include "acst_sweep/sweep_case.hpp"

namespace acst::mpm {
using nlohmann::json;
using nlohmann::ordered_json;

std::string first_difference(const json& then, const json& now) {
  const json patch = json::diff(then, now);
  return patch.empty() ? "" : " (first difference at " + patch[0].value("path", std::string("?")) + ")";
}

std::vector<CaseState> read_case_states(const SweepSpec& sweep, const std::string& dir) {
  std::vector<CaseState> states;
  for (const SweepCase& c : sweep.cases) {
    CaseState s;
    const json fingerprint = case_fingerprint(c);
    if (const std::optional<CaseRecord> run = read_case_record(dir, c.name)) {
      if (run->fingerprint != fingerprint)
        throw common::InputError("case '" + c.name + "' (" + c.origin + "): '" + case_folder(dir, c.name) +
                                 "' holds a run of another scene or material" +
                                 first_difference(run->fingerprint, fingerprint) +
                                 "; remove that folder to run the case again");
      s.from = CaseState::From::case_folder;
      s.row = case_row(c, case_folder(dir, c.name), run->status, run->message, sweep.load_at_S_over_B);
      s.row["resumed"] = run->resumed;
    } else if (const std::optional<CaseRecord> kept = read_kept_record(dir, c.name)) {
      if (kept->fingerprint == fingerprint) {
        s.from = CaseState::From::kept;
        s.row = kept->row;
      } else {
        s.stale = first_difference(kept->fingerprint, fingerprint);
      }
    }
    if (s.from == CaseState::From::nothing) s.row = case_row(c, "", CaseStatus::pending, "", sweep.load_at_S_over_B);
    states.push_back(std::move(s));
  }
  return states;
}

std::vector<ordered_json> rows_of(const std::vector<CaseState>& states) {
  std::vector<ordered_json> rows;
  for (const CaseState& s : states) rows.push_back(s.row);
  return rows;
}

}  // namespace acst::mpm
