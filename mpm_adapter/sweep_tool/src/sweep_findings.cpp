#include "acst_sweep/sweep_findings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "acst_common/json_fields.hpp"
#include "acst_sweep/case_status.hpp"

namespace acst::mpm {

namespace f = common::fields;
using nlohmann::json;
using nlohmann::ordered_json;

namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, std::fabs(v) >= 100 ? "%.0f" : "%.3g", v);
  return text;
}

std::vector<std::string> names(const json& j, const std::string& p, std::size_t at_least) {
  if (!j.is_array() || j.size() < at_least)
    f::fail(p, "expected an array of at least " + std::to_string(at_least) + " names");
  std::vector<std::string> out;
  for (std::size_t k = 0; k < j.size(); ++k) out.push_back(f::string(j[k], p + "/" + std::to_string(k)));
  return out;
}

FindingCheck read_check(const json& j, const std::string& p, const std::vector<std::string>& case_names) {
  f::allow_keys(j, {"what", "expect", "cases", "column", "columns", "value", "within", "within_abs"}, p);
  FindingCheck c;
  if (j.contains("what")) c.what = f::string(j["what"], p + "/what");
  if (!j.contains("expect")) f::fail(p, "'expect' is required");
  c.expect = f::choice<Expectation>(j["expect"], p + "/expect", expectation_names);
  if (!j.contains("cases")) f::fail(p, "'cases' is required");
  c.cases = names(j["cases"], p + "/cases", 1);
  for (std::size_t k = 0; k < c.cases.size(); ++k)
    if (std::find(case_names.begin(), case_names.end(), c.cases[k]) == case_names.end())
      f::fail(p + "/cases/" + std::to_string(k), "'" + c.cases[k] + "' is not a case of this sweep");
  if (f::one_of(j, {"column", "columns"}, p) == "column")
    c.columns.push_back(f::string(j["column"], p + "/column"));
  else
    c.columns = names(j["columns"], p + "/columns", 2);
  if (j.contains("value")) c.value = f::number(j["value"], p + "/value");
  if (j.contains("within")) c.within = f::number(j["within"], p + "/within", {0.0, 100.0});
  if (j.contains("within_abs")) c.within_abs = f::number(j["within_abs"], p + "/within_abs", {0.0, 1e12});

  const auto need = [&](bool ok, const std::string& what) {
    if (!ok) f::fail(p, std::string("'") + name_of(c.expect) + "' needs " + what);
  };
  const bool one_column = c.columns.size() == 1;
  switch (c.expect) {
    case Expectation::increasing:
    case Expectation::decreasing: need(c.cases.size() >= 2 && one_column, "two or more cases and one column"); break;
    case Expectation::similar:
    case Expectation::different:
      need(c.cases.size() >= 2 && one_column && !std::isnan(c.within), "two or more cases, one column and 'within'");
      break;
    case Expectation::greater:
      need((c.cases.size() == 2 && one_column) || c.columns.size() == 2, "two cases and one column, or two columns");
      break;
    case Expectation::ratio:
      need(c.cases.size() == 2 && one_column && !std::isnan(c.value) && !std::isnan(c.within), "two cases, one column, 'value' and 'within'");
      break;
    case Expectation::near:
      need(one_column && !std::isnan(c.value) && (std::isnan(c.within) != std::isnan(c.within_abs)),
           "one column, 'value' and one of 'within' (relative) or 'within_abs'");
      break;
    case Expectation::report: break;
  }
  if (c.expect != Expectation::greater && c.columns.size() != 1) f::fail(p + "/columns", "two columns go with 'greater' only");
  return c;
}

const ordered_json* row_of(const std::vector<ordered_json>& rows, const std::string& name) {
  for (const ordered_json& r : rows)
    if (r.value("case", std::string()) == name) return &r;
  return nullptr;
}

// The value of `column` in the row of case `name`: from a run that ended, or from one that failed
// after its peak (what its record holds up to the failure stands; the columns past the failure
// are empty); NaN otherwise.
double value_of(const std::vector<ordered_json>& rows, const std::string& name, const std::string& column) {
  const ordered_json* r = row_of(rows, name);
  if (!r || !r->contains(column) || !(*r)[column].is_number()) return std::numeric_limits<double>::quiet_NaN();
  const CaseStatus status = status_of(*r);
  if (status == CaseStatus::done || (status == CaseStatus::failed && r->value("peak_reached", false))) return (*r)[column].get<double>();
  return std::numeric_limits<double>::quiet_NaN();
}

// "V85.6 1729", with the settlement where a case failed after its peak.
std::string shown_value(const std::vector<ordered_json>& rows, const std::string& name, double v) {
  const ordered_json* r = row_of(rows, name);
  std::string text = name + " " + number_text(v);
  if (r && status_of(*r) == CaseStatus::failed && !std::isnan(v))
    text += " (failed at S/B " + number_text(r->value("final_S_over_B", 0.0)) + ", after its peak)";
  return text;
}

}  // namespace

std::vector<Finding> read_findings(const json& j, const std::string& path, const std::vector<std::string>& case_names) {
  if (!j.is_array()) f::fail(path, "expected an array of findings");
  std::vector<Finding> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string p = path + "/" + std::to_string(i);
    f::allow_keys(j[i], {"finding", "note", "checks"}, p);
    Finding fd;
    if (!j[i].contains("finding")) f::fail(p, "'finding' is required");
    fd.claim = f::string(j[i]["finding"], p + "/finding");
    if (j[i].contains("note")) fd.note = f::string(j[i]["note"], p + "/note");
    if (!j[i].contains("checks") || !j[i]["checks"].is_array() || j[i]["checks"].empty())
      f::fail(p + "/checks", "expected a non-empty array of checks");
    for (std::size_t k = 0; k < j[i]["checks"].size(); ++k)
      fd.checks.push_back(read_check(j[i]["checks"][k], p + "/checks/" + std::to_string(k), case_names));
    out.push_back(std::move(fd));
  }
  return out;
}

CheckResult judge(const FindingCheck& c, const std::vector<ordered_json>& rows) {
  CheckResult r;
  bool missing = false;
  if (c.columns.size() == 2) {  // within each case, the first column above the second
    bool all = true;
    for (const std::string& name : c.cases) {
      const double a = value_of(rows, name, c.columns[0]), b = value_of(rows, name, c.columns[1]);
      missing = missing || std::isnan(a) || std::isnan(b);
      all = all && a > b;
      r.numbers += (r.numbers.empty() ? "" : "; ") + shown_value(rows, name, a) + " vs " + number_text(b);
    }
    r.status = missing ? CheckStatus::open : all ? CheckStatus::holds : CheckStatus::fails;
    return r;
  }
  std::vector<double> v;
  for (const std::string& name : c.cases) {
    v.push_back(value_of(rows, name, c.columns[0]));
    missing = missing || std::isnan(v.back());
  }
  for (std::size_t k = 0; k < v.size(); ++k) r.numbers += (k ? ", " : "") + shown_value(rows, c.cases[k], v[k]);
  bool holds = true;
  switch (c.expect) {
    case Expectation::increasing:
    case Expectation::decreasing: {
      const bool up = c.expect == Expectation::increasing;
      for (std::size_t k = 1; k < v.size(); ++k) holds = holds && (up ? v[k] > v[k - 1] : v[k] < v[k - 1]);
      break;
    }
    case Expectation::similar:
    case Expectation::different: {
      const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
      const double spread = *hi / *lo - 1.0;
      holds = *lo > 0 && (c.expect == Expectation::similar ? spread <= c.within : spread > c.within);
      r.numbers += "; spread " + number_text(100.0 * spread) + " % (limit " + number_text(100.0 * c.within) + " %)";
      break;
    }
    case Expectation::greater: holds = v[0] > v[1]; break;
    case Expectation::ratio: {
      const double ratio = v[0] / v[1];
      holds = std::fabs(ratio - c.value) <= c.within;
      r.numbers += "; ratio " + number_text(ratio) + " (expected " + number_text(c.value) + " +- " + number_text(c.within) + ")";
      break;
    }
    case Expectation::near: {
      const double tolerance = std::isnan(c.within) ? c.within_abs : c.within * std::fabs(c.value);
      for (double x : v) holds = holds && std::fabs(x - c.value) <= tolerance;
      r.numbers += "; expected " + number_text(c.value) + " +- " + number_text(tolerance);
      break;
    }
    case Expectation::report: break;
  }
  r.status = missing ? CheckStatus::open
             : c.expect == Expectation::report ? CheckStatus::reported
             : holds ? CheckStatus::holds : CheckStatus::fails;
  return r;
}

std::string verdict(const std::vector<CheckResult>& results) {
  std::size_t held = 0, failed = 0, open = 0;
  for (const CheckResult& r : results) {
    held += r.status == CheckStatus::holds;
    failed += r.status == CheckStatus::fails;
    open += r.status == CheckStatus::open;
  }
  if (open > 0) return "open";
  if (failed == 0) return held > 0 ? "reproduced" : "reported";
  return held == 0 ? "not reproduced" : "partly reproduced";
}

}  // namespace acst::mpm
