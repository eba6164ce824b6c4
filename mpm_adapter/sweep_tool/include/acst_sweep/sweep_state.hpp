#pragma once
// Where each case of a sweep stands in its folder (docs/sweeps.md, "Kept results"): run, from its
// case folder or from its kept results alone (a recorded study in a fresh clone, a gathered
// shard), or still to run. The table, the report, --replot and --gather all start from it.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

struct CaseState {
  enum class From { nothing, case_folder, kept };
  From from = From::nothing;
  nlohmann::ordered_json row;  // the table's row: the run's, or a pending one
  // A kept result of another fingerprint (a changed scene, set, material or build option): the
  // case runs again, and `stale` says why ("(first difference at /scene/footing/speed)").
  std::string stale;
};

// Each case's state in `dir`. A case folder's row is read again from its files (a newer
// acst_sweep gathers every case alike); a case folder of another fingerprint is refused
// (InputError: it holds a whole run the user may want; removing it is theirs to decide); a kept
// record of another fingerprint makes the case pending, `stale` set. A damaged record is refused
// naming its file.
std::vector<CaseState> read_case_states(const SweepSpec& sweep, const std::string& dir);

// "(first difference at /scene/footing/speed)" between a record's fingerprint and now.
std::string first_difference(const nlohmann::json& then, const nlohmann::json& now);

// The rows of the states, in the sweep's order.
std::vector<nlohmann::ordered_json> rows_of(const std::vector<CaseState>& states);

}  // namespace acst::mpm
