#pragma once
// Findings a sweep tests (docs/sweeps.md, "Findings"): claims of a study written as checks on the
// gathered table (a trend along cases, two cases or two columns compared, a ratio or a value
// against an expected one), judged on the rows and written as a markdown report.
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_common/name_table.hpp"

namespace acst::mpm {

// What a check expects of the values it reads (docs/sweeps.md, "Findings").
// bedding_factor: the anisotropy factor i_alpha = 1 - a sin^2(alpha) fitted to q(alpha)/q(0) of
// the cases (the first at bedding 0, the angles from the table's bedding_angle_deg).
enum class Expectation { increasing, decreasing, similar, different, greater, ratio, near, report, bedding_factor };

// The names in the sweep description ("expect") and the report.
inline constexpr common::Named<Expectation> expectation_names[] = {
    {"increasing", Expectation::increasing}, {"decreasing", Expectation::decreasing}, {"similar", Expectation::similar},
    {"different", Expectation::different},   {"greater", Expectation::greater},       {"ratio", Expectation::ratio},
    {"near", Expectation::near},             {"report", Expectation::report},         {"bedding_factor", Expectation::bedding_factor}};

inline const char* name_of(Expectation e) { return common::name_in(expectation_names, e); }

struct FindingCheck {
  std::string what;                  // shown in the report; default: made from the check
  Expectation expect = Expectation::report;
  std::vector<std::string> cases;    // case names, in the order the check reads them
  std::vector<std::string> columns;  // one column, or two for "greater" within each case
  double value = std::numeric_limits<double>::quiet_NaN();
  double within = std::numeric_limits<double>::quiet_NaN();      // relative
  double within_abs = std::numeric_limits<double>::quiet_NaN();  // absolute (near)
};

struct Finding {
  std::string claim, note;
  std::vector<FindingCheck> checks;
};

// The spread a column's value keeps from the method itself (the cell, the loading speed, round-off:
// what the converged footing leaves), measured elsewhere and cited in `source`: a difference
// between two values within it says nothing (docs/sweeps.md, "Findings").
// `common` (in the band's own unit, 0 without one) is a spread every case shares, such as the
// material's internal length, which moves all loads together: it cancels between cases and
// widens only a comparison with an outside value (`near`), where the two add as independent
// spreads (root of the sum of squares).
struct Band {
  std::string column, source;
  double relative = std::numeric_limits<double>::quiet_NaN();  // of the larger value's size
  double absolute = std::numeric_limits<double>::quiet_NaN();
  double common = 0.0;
  // The band about values of size `size`, between cases of the sweep.
  double about(double size) const { return std::isnan(absolute) ? relative * std::fabs(size) : absolute; }
  // The band about a value of size `size` against an outside value.
  double outside(double size) const {
    return std::hypot(about(size), std::isnan(absolute) ? common * std::fabs(size) : common);
  }
};

// Reads "bands" at `path` (one per column). Throws InputError.
std::vector<Band> read_bands(const nlohmann::json& j, const std::string& path);

// Reads "findings" at `path`; every case named must be one of `case_names`. Throws InputError.
std::vector<Finding> read_findings(const nlohmann::json& j, const std::string& path,
                                   const std::vector<std::string>& case_names);

// What a check says about the rows: open, a value is missing (the case failed, or its record does
// not reach the column); pending, a case it reads has not run yet (a sweep in pieces: never
// judged on the cases there are); reported, no verdict asked; within band, the difference that
// decides lies inside the column's band, so the rows cannot tell.
enum class CheckStatus { holds, fails, open, reported, within_band, pending };

// The names in the report.
inline constexpr common::Named<CheckStatus> check_status_names[] = {
    {"holds", CheckStatus::holds},       {"fails", CheckStatus::fails},
    {"open", CheckStatus::open},         {"reported", CheckStatus::reported},
    {"within the band", CheckStatus::within_band}, {"not decided: cases pending", CheckStatus::pending}};

inline const char* name_of(CheckStatus s) { return common::name_in(check_status_names, s); }

// `numbers`: the values the check read, as the report shows them.
struct CheckResult {
  CheckStatus status = CheckStatus::open;
  std::string numbers;
};
// Judged against the band of the check's (first) column when `bands` has one.
CheckResult judge(const FindingCheck& check, const std::vector<nlohmann::ordered_json>& rows,
                  const std::vector<Band>& bands = {});

// "reproduced", "not reproduced", "partly reproduced", "not decided within the band" (no check
// holds or fails beyond its band), "open" or "not decided: cases pending" (a check reads a case
// not yet run), from its checks' results.
std::string verdict(const std::vector<CheckResult>& results);

}  // namespace acst::mpm
