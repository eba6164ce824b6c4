#pragma once
// A sweep case's status in its row of the table (docs/sweeps.md, "The table").
#include <nlohmann/json.hpp>
#include <string>

#include "acst_common/name_table.hpp"

namespace acst::mpm {

// Where a case stands, as its row of the table says ("status"): pending, not run yet; done, the
// run reached its stop; failed, the run ended early (its row keeps the message) or its folder
// could not be written.
enum class CaseStatus { pending, done, failed };

inline constexpr common::Named<CaseStatus> case_status_names[] = {
    {"pending", CaseStatus::pending}, {"done", CaseStatus::done}, {"failed", CaseStatus::failed}};

inline const char* name_of(CaseStatus s) { return common::name_in(case_status_names, s); }

// The status a row names; a row without one acst_sweep writes (a record edited by hand) is
// pending: no run of it is known to have ended.
inline CaseStatus status_of(const nlohmann::ordered_json& row) {
  const auto it = row.find("status");
  const auto status = it != row.end() && it->is_string() ? common::value_in(case_status_names, it->get<std::string>())
                                                         : std::nullopt;
  return status.value_or(CaseStatus::pending);
}

}  // namespace acst::mpm
