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
    case Expectation::bedding_factor:
      need(c.cases.size() >= 2 && one_column && !std::isnan(c.value) == !std::isnan(c.within_abs) && std::isnan(c.within),
           "two or more cases, one column and, to judge a, both 'value' and 'within_abs'");
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

namespace {

// How a difference d stands against its band w: beyond it either way, or within it. Without a
// band (w = 0) only a difference of zero is within it, which a strict claim does not meet.
enum class Side { above, below, within };
Side side_of(double d, double w) { return d > w ? Side::above : d < -w ? Side::below : Side::within; }

// A claim judged on an interval of values [x - u, x + u]: holds where all of it meets the claim,
// fails where none does, within the band otherwise; `banded` false: the value alone decides.
CheckStatus status_of_interval(bool all_meet, bool none_meets, bool value_meets, bool banded) {
  if (!banded) return value_meets ? CheckStatus::holds : CheckStatus::fails;
  return all_meet ? CheckStatus::holds : none_meets ? CheckStatus::fails : CheckStatus::within_band;
}

// The least-squares a of 1 - q_k/q_0 = a sin^2(alpha_k) over the cases after the first (at
// bedding 0): a = sum s_k (1 - q_k/q_0) / sum s_k^2, s_k = sin^2(alpha_k).
double sin2_factor(const std::vector<double>& q, const std::vector<double>& s) {
  double num = 0.0, den = 0.0;
  for (std::size_t k = 1; k < q.size(); ++k) num += s[k] * (1.0 - q[k] / q[0]), den += s[k] * s[k];
  return num / den;
}

std::string band_text(const Band& b, bool outside = false) {
  const bool relative = std::isnan(b.absolute);
  const double width = outside ? b.outside(1.0) : b.about(1.0);
  const std::string text = relative ? number_text(100.0 * width) + " %" : number_text(width);
  return "; band +-" + text + (outside && b.common > 0.0 ? " (with the part common to every case)" : "");
}

}  // namespace

std::vector<Band> read_bands(const json& j, const std::string& path) {
  if (!j.is_array()) f::fail(path, "expected an array of bands, one per column");
  std::vector<Band> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string p = path + "/" + std::to_string(i);
    f::allow_keys(j[i], {"column", "relative", "absolute", "common", "source"}, p);
    Band b;
    if (!j[i].contains("column")) f::fail(p, "'column' is required");
    b.column = f::string(j[i]["column"], p + "/column");
    for (const Band& other : out)
      if (other.column == b.column) f::fail(p + "/column", "a second band for '" + b.column + "'");
    if (f::one_of(j[i], {"relative", "absolute"}, p) == "relative")
      b.relative = f::number(j[i]["relative"], p + "/relative", {0.0, 10.0});
    else
      b.absolute = f::number(j[i]["absolute"], p + "/absolute", {0.0, 1e12});
    if (j[i].contains("common"))
      b.common = f::number(j[i]["common"], p + "/common", std::isnan(b.absolute) ? f::Range{0.0, 10.0} : f::Range{0.0, 1e12});
    if (!j[i].contains("source")) f::fail(p, "'source' is required: where the band was measured");
    b.source = f::string(j[i]["source"], p + "/source");
    out.push_back(std::move(b));
  }
  return out;
}

CheckResult judge(const FindingCheck& c, const std::vector<ordered_json>& rows, const std::vector<Band>& bands) {
  CheckResult r;
  const Band* band = nullptr;
  for (const Band& b : bands)
    if (b.column == c.columns[0]) band = &b;
  const auto width = [&](double a, double b) { return band ? band->about(std::max(std::fabs(a), std::fabs(b))) : 0.0; };
  // Steps a over b that must all be above (beyond the band) for the claim to hold.
  const auto steps = [&](const std::vector<std::pair<double, double>>& pairs) {
    bool all_above = true, any_below = false;
    for (const auto& [a, b] : pairs) {
      const Side s = side_of(a - b, width(a, b));
      all_above = all_above && s == Side::above;
      any_below = any_below || s == Side::below || (!band && s == Side::within);
    }
    return all_above ? CheckStatus::holds : any_below ? CheckStatus::fails : CheckStatus::within_band;
  };
  bool missing = false;
  bool pending = false;  // a case the check reads has not run
  for (const std::string& name : c.cases) {
    const ordered_json* row = row_of(rows, name);
    pending = pending || !row || status_of(*row) == CaseStatus::pending;
  }
  const CheckStatus unknown = pending ? CheckStatus::pending : CheckStatus::open;
  if (c.columns.size() == 2) {  // within each case, the first column above the second
    std::vector<std::pair<double, double>> pairs;
    for (const std::string& name : c.cases) {
      const double a = value_of(rows, name, c.columns[0]), b = value_of(rows, name, c.columns[1]);
      missing = missing || std::isnan(a) || std::isnan(b);
      pairs.emplace_back(a, b);
      r.numbers += (r.numbers.empty() ? "" : "; ") + shown_value(rows, name, a) + " vs " + number_text(b);
    }
    if (band) r.numbers += band_text(*band);
    r.status = missing ? unknown : steps(pairs);
    return r;
  }
  std::vector<double> v;
  for (const std::string& name : c.cases) {
    v.push_back(value_of(rows, name, c.columns[0]));
    missing = missing || std::isnan(v.back());
  }
  for (std::size_t k = 0; k < v.size(); ++k) r.numbers += (k ? ", " : "") + shown_value(rows, c.cases[k], v[k]);
  CheckStatus status = CheckStatus::reported;
  switch (c.expect) {
    case Expectation::increasing:
    case Expectation::decreasing: {
      std::vector<std::pair<double, double>> pairs;
      for (std::size_t k = 1; k < v.size(); ++k)
        pairs.push_back(c.expect == Expectation::increasing ? std::make_pair(v[k], v[k - 1]) : std::make_pair(v[k - 1], v[k]));
      status = steps(pairs);
      // With a band a trend holds where its whole change, first case to last, is beyond the band
      // and no step goes the other way beyond it: steps each within the band do not undo a trend.
      if (band && status == CheckStatus::within_band) {
        const auto [a, b] = c.expect == Expectation::increasing ? std::make_pair(v.back(), v.front()) : std::make_pair(v.front(), v.back());
        const Side whole = side_of(a - b, width(a, b));
        status = whole == Side::above ? CheckStatus::holds : whole == Side::below ? CheckStatus::fails : CheckStatus::within_band;
      }
      break;
    }
    case Expectation::similar:
    case Expectation::different: {
      const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
      // The spread relative to the value of smallest size where all have one sign (hi / lo - 1 for
      // positive values, as before); across zero, or at it, relative to the largest size, so that
      // the scale never vanishes. Values all zero are alike: spread 0.
      const double a = std::fabs(*lo), b = std::fabs(*hi);
      const double scale = (*lo > 0 || *hi < 0) ? std::min(a, b) : std::max(a, b);
      const double spread = scale > 0 ? (*hi - *lo) / scale : 0.0;
      const double u = scale > 0 ? width(*hi, *lo) / scale : 0.0;  // the band, in the spread's terms
      const bool similar = c.expect == Expectation::similar;
      const auto meets = [&](double s) { return similar ? s <= c.within : s > c.within; };
      status = status_of_interval(meets(spread + (similar ? u : -u)), !meets(spread - (similar ? u : -u)), meets(spread),
                                  band != nullptr);
      r.numbers += "; spread " + number_text(100.0 * spread) + " % (limit " + number_text(100.0 * c.within) + " %)";
      break;
    }
    case Expectation::greater: status = steps({{v[0], v[1]}}); break;
    case Expectation::ratio: {
      if (v[1] == 0.0) {  // no ratio to judge: said, not read as infinity or NaN
        r.numbers += "; no ratio: the second value is 0";
        missing = true;
        break;
      }
      const double ratio = v[0] / v[1], off = std::fabs(ratio - c.value);
      const double u = band ? std::fabs(ratio) * width(v[0], v[1]) / std::max(std::fabs(v[0]), std::fabs(v[1])) : 0.0;
      status = status_of_interval(off + u <= c.within, off - u > c.within, off <= c.within, band != nullptr);
      r.numbers += "; ratio " + number_text(ratio) + " (expected " + number_text(c.value) + " +- " + number_text(c.within) + ")";
      break;
    }
    case Expectation::near: {
      const double tolerance = std::isnan(c.within) ? c.within_abs : c.within * std::fabs(c.value);
      // Every value near: all of each one's band within the tolerance holds; one whose whole band
      // lies beyond it fails.
      bool all = true, any_beyond = false, value = true;
      for (double x : v) {
        const double off = std::fabs(x - c.value), u = band ? band->outside(x) : 0.0;
        all = all && off + u <= tolerance, value = value && off <= tolerance;
        any_beyond = any_beyond || off - u > tolerance;
      }
      status = status_of_interval(all, any_beyond, value, band != nullptr);
      r.numbers += "; expected " + number_text(c.value) + " +- " + number_text(tolerance);
      break;
    }
    case Expectation::bedding_factor: {
      std::vector<double> s;
      bool angles = true;
      for (const std::string& name : c.cases) {
        const double alpha = value_of(rows, name, "bedding_angle_deg") * M_PI / 180.0;
        angles = angles && !std::isnan(alpha);
        s.push_back(std::pow(std::sin(alpha), 2));
      }
      double den = 0.0;
      for (std::size_t k = 1; k < s.size(); ++k) den += s[k] * s[k];
      if (!angles || s[0] > 1e-12 || !(den > 0.0)) {
        r.numbers += "; needs bedding_angle_deg of every case, the first at 0 deg and another not at 0 or 180";
        missing = true;
      }
      if (missing || !(v[0] > 0.0)) break;
      // a falls as any q_k grows and rises with q_0, so the band's ends are its corners.
      const double a = sin2_factor(v, s);
      std::vector<double> to_high = v, to_low = v;  // the q that give a's largest and smallest value
      for (std::size_t k = 0; k < v.size(); ++k) {
        const double u = k == 0 ? width(v[k], v[k]) : -width(v[k], v[k]);
        to_high[k] += u, to_low[k] -= u;
      }
      const double a_high = sin2_factor(to_high, s);
      const double a_low = to_low[0] > 0.0 ? sin2_factor(to_low, s) : -std::numeric_limits<double>::infinity();  // q_0's band reaches 0
      r.numbers += "; i_alpha = 1 - a sin^2(alpha): a = " + number_text(a);
      if (band) r.numbers += " (" + number_text(a_low) + " to " + number_text(a_high) + " over the band)";
      if (!std::isnan(c.value)) {
        status = status_of_interval(std::max(std::fabs(a_low - c.value), std::fabs(a_high - c.value)) <= c.within_abs,
                                    a_low - c.value > c.within_abs || c.value - a_high > c.within_abs,
                                    std::fabs(a - c.value) <= c.within_abs, band != nullptr);
        r.numbers += ", expected " + number_text(c.value) + " +- " + number_text(c.within_abs);
      }
      break;
    }
    case Expectation::report: break;
  }
  if (band) r.numbers += band_text(*band, c.expect == Expectation::near);
  r.status = missing ? unknown : status;
  return r;
}

std::string verdict(const std::vector<CheckResult>& results) {
  std::size_t held = 0, failed = 0, open = 0, within = 0, pending = 0;
  for (const CheckResult& r : results) {
    pending += r.status == CheckStatus::pending;
    held += r.status == CheckStatus::holds;
    failed += r.status == CheckStatus::fails;
    open += r.status == CheckStatus::open;
    within += r.status == CheckStatus::within_band;
  }
  if (pending > 0) return "not decided: cases pending";
  if (open > 0) return "open";
  const std::string where = within > 0 ? " where decided" : "";
  if (failed == 0 && held == 0) return within > 0 ? "not decided within the band" : "reported";
  if (failed == 0) return "reproduced" + where;
  return held == 0 ? "not reproduced" + where : "partly reproduced";
}

}  // namespace acst::mpm
