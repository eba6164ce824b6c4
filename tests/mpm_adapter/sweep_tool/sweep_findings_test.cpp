// The findings of a sweep (docs/sweeps.md, "Findings"): each kind of check judged on rows whose
// answer is known, the verdict from its checks, and the description's errors with their path.
#include <gtest/gtest.h>

#include <cmath>

#include "acst_common/input_error.hpp"
#include "acst_sweep/sweep_findings.hpp"

using namespace acst::mpm;
using nlohmann::json;
using nlohmann::ordered_json;

namespace {

const std::vector<std::string> names{"a", "b", "c", "d", "e"};

// Cases with q 300, 200, 100; d failed before its peak, e after it; left/right sheared areas; a
// residual per case.
std::vector<ordered_json> rows() {
  return {{{"case", "a"}, {"status", "done"}, {"q", 300.0}, {"left", 2.0}, {"right", 1.0}, {"r", 100.0}},
          {{"case", "b"}, {"status", "done"}, {"q", 200.0}, {"left", 1.0}, {"right", 3.0}, {"r", 104.0}},
          {{"case", "c"}, {"status", "done"}, {"q", 100.0}, {"left", 5.0}, {"right", 1.0}, {"r", 96.0}},
          {{"case", "d"}, {"status", "failed"}, {"q", 50.0}},
          {{"case", "e"}, {"status", "failed"}, {"q", 40.0}, {"peak_reached", true}, {"final_S_over_B", 0.4}}};
}

FindingCheck check(const std::string& text) {
  return read_findings(json::parse(R"([{"finding": "f", "checks": [)" + text + "]}]"), "/findings", names)[0].checks[0];
}

std::string status(const std::string& text) { return name_of(judge(check(text), rows()).status); }

std::string error(const std::string& text) {
  try {
    check(text);
  } catch (const acst::common::InputError& e) {
    return e.what();
  }
  return "accepted";
}

std::vector<Band> bands(const std::string& text) { return read_bands(json::parse(text), "/bands"); }

std::string banded(const std::string& check_text, const std::string& bands_text) {
  return name_of(judge(check(check_text), rows(), bands(bands_text)).status);
}

}  // namespace

TEST(SweepFindings, EachKindOfCheckIsJudgedOnTheRows) {
  EXPECT_EQ(status(R"({"expect": "decreasing", "cases": ["a", "b", "c"], "column": "q"})"), "holds");
  EXPECT_EQ(status(R"({"expect": "increasing", "cases": ["a", "b", "c"], "column": "q"})"), "fails");
  EXPECT_EQ(status(R"({"expect": "decreasing", "cases": ["a", "c", "b"], "column": "q"})"), "fails");
  // r spans 96-104: spread 8.3 %.
  EXPECT_EQ(status(R"({"expect": "similar", "within": 0.09, "cases": ["a", "b", "c"], "column": "r"})"), "holds");
  EXPECT_EQ(status(R"({"expect": "similar", "within": 0.08, "cases": ["a", "b", "c"], "column": "r"})"), "fails");
  EXPECT_EQ(status(R"({"expect": "different", "within": 0.08, "cases": ["a", "b", "c"], "column": "r"})"), "holds");
  EXPECT_EQ(status(R"({"expect": "greater", "cases": ["a", "b"], "column": "q"})"), "holds");
  EXPECT_EQ(status(R"({"expect": "greater", "cases": ["a", "c"], "columns": ["left", "right"]})"), "holds");
  EXPECT_EQ(status(R"({"expect": "greater", "cases": ["a", "b"], "columns": ["left", "right"]})"), "fails");
  EXPECT_EQ(status(R"({"expect": "ratio", "value": 1.5, "within": 0.01, "cases": ["a", "b"], "column": "q"})"), "holds");
  EXPECT_EQ(status(R"({"expect": "ratio", "value": 1.4, "within": 0.09, "cases": ["a", "b"], "column": "q"})"), "fails");
  EXPECT_EQ(status(R"({"expect": "near", "value": 310, "within": 0.04, "cases": ["a"], "column": "q"})"), "holds");
  EXPECT_EQ(status(R"({"expect": "near", "value": 310, "within_abs": 5, "cases": ["a"], "column": "q"})"), "fails");
  EXPECT_EQ(status(R"({"expect": "report", "cases": ["a", "b"], "column": "q"})"), "reported");
  // A case that failed before its peak, or a column a row does not have, leaves the check open;
  // one that failed after its peak counts, and the report says where it failed.
  EXPECT_EQ(status(R"({"expect": "decreasing", "cases": ["a", "d"], "column": "q"})"), "open");
  EXPECT_EQ(status(R"({"expect": "decreasing", "cases": ["a", "e"], "column": "q"})"), "holds");
  EXPECT_NE(judge(check(R"({"expect": "report", "cases": ["e"], "column": "q"})"), rows()).numbers.find("e 40 (failed at S/B 0.4, after its peak)"),
            std::string::npos);
  EXPECT_EQ(status(R"({"expect": "report", "cases": ["e"], "column": "r"})"), "open");
  EXPECT_EQ(status(R"({"expect": "greater", "cases": ["a", "b"], "column": "nothing"})"), "open");
  const CheckResult r = judge(check(R"({"expect": "ratio", "value": 1.5, "within": 0.01, "cases": ["a", "b"], "column": "q"})"), rows());
  EXPECT_NE(r.numbers.find("a 300, b 200; ratio 1.5"), std::string::npos) << r.numbers;
}

// q 300, 200, 100 and r 100, 104, 96, judged against bands whose answers follow from the numbers.
TEST(SweepFindings, AChecksVerdictStandsOnlyWhereItsWholeBandAgrees) {
  const std::string q10 = R"([{"column": "q", "relative": 0.1, "source": "s"}])";
  const std::string q40 = R"([{"column": "q", "relative": 0.4, "source": "s"}])";
  const std::string r5 = R"([{"column": "r", "absolute": 5, "source": "s"}])";
  const std::string q70 = R"([{"column": "q", "relative": 0.7, "source": "s"}])";
  // Steps of 100 against bands of 30 and 20 (10 % of the larger): beyond them; of 40 %: 120 and
  // 80, the first step within its band but the whole fall of 200 beyond its 120; of 70 %: the
  // whole fall within its 210.
  EXPECT_EQ(banded(R"({"expect": "decreasing", "cases": ["a", "b", "c"], "column": "q"})", q10), "holds");
  EXPECT_EQ(banded(R"({"expect": "increasing", "cases": ["a", "b", "c"], "column": "q"})", q10), "fails");
  EXPECT_EQ(banded(R"({"expect": "decreasing", "cases": ["a", "b", "c"], "column": "q"})", q40), "holds");
  EXPECT_EQ(banded(R"({"expect": "increasing", "cases": ["a", "b", "c"], "column": "q"})", q40), "fails");  // 200 -> 100 is 100 > 80 the wrong way
  EXPECT_EQ(banded(R"({"expect": "decreasing", "cases": ["a", "b", "c"], "column": "q"})", q70), "within the band");
  // 300, 100, 200: the step up of 100 is within its 140, the whole fall of 100 within its 210.
  EXPECT_EQ(banded(R"({"expect": "decreasing", "cases": ["a", "c", "b"], "column": "q"})", q70), "within the band");
  // ... and with 10 %: the step up of 100 beyond its 20 undoes the trend.
  EXPECT_EQ(banded(R"({"expect": "decreasing", "cases": ["a", "c", "b"], "column": "q"})", q10), "fails");
  EXPECT_EQ(banded(R"({"expect": "greater", "cases": ["a", "b"], "column": "q"})", q40), "within the band");
  // A band on another column changes nothing.
  EXPECT_EQ(banded(R"({"expect": "greater", "cases": ["a", "b"], "column": "q"})", r5), "holds");
  // r: spread 8.3 %, its band 5/96 = 5.2 %: similar within 9 % needs 8.3 + 5.2 <= 9, within 2 % fails
  // only beyond 8.3 - 5.2 = 3.1 %.
  EXPECT_EQ(banded(R"({"expect": "similar", "within": 0.09, "cases": ["a", "b", "c"], "column": "r"})", r5), "within the band");
  EXPECT_EQ(banded(R"({"expect": "similar", "within": 0.14, "cases": ["a", "b", "c"], "column": "r"})", r5), "holds");
  EXPECT_EQ(banded(R"({"expect": "similar", "within": 0.02, "cases": ["a", "b", "c"], "column": "r"})", r5), "fails");
  EXPECT_EQ(banded(R"({"expect": "different", "within": 0.02, "cases": ["a", "b", "c"], "column": "r"})", r5), "holds");
  EXPECT_EQ(banded(R"({"expect": "different", "within": 0.05, "cases": ["a", "b", "c"], "column": "r"})", r5), "within the band");
  // a/b = 1.5 against 1.4 +- 0.09: 0.1 off; the band moves the ratio by 1.5 x 10 % = 0.15.
  EXPECT_EQ(banded(R"({"expect": "ratio", "value": 1.4, "within": 0.09, "cases": ["a", "b"], "column": "q"})", q10), "within the band");
  EXPECT_EQ(banded(R"({"expect": "ratio", "value": 1.1, "within": 0.09, "cases": ["a", "b"], "column": "q"})", q10), "fails");
  // a = 300 near 310 +- 12.4 (4 %): 10 off, its band 30: neither all within nor all beyond.
  EXPECT_EQ(banded(R"({"expect": "near", "value": 310, "within": 0.04, "cases": ["a"], "column": "q"})", q10), "within the band");
  EXPECT_EQ(banded(R"({"expect": "near", "value": 310, "within": 0.2, "cases": ["a"], "column": "q"})", q10), "holds");
  EXPECT_EQ(banded(R"({"expect": "near", "value": 400, "within_abs": 20, "cases": ["a"], "column": "q"})", q10), "fails");
  // Two columns compared within each case take the first column's band.
  EXPECT_EQ(banded(R"({"expect": "greater", "cases": ["a", "c"], "columns": ["left", "right"]})",
                   R"([{"column": "left", "absolute": 1.5, "source": "s"}])"),
            "within the band");
  const CheckResult r = judge(check(R"({"expect": "greater", "cases": ["a", "b"], "column": "q"})"), rows(), bands(q10));
  EXPECT_NE(r.numbers.find("band +-10 %"), std::string::npos) << r.numbers;
}

// Bedding series whose factor is known in closed form: q(alpha) = 1000 (1 - a sin^2 alpha).
TEST(SweepFindings, TheBeddingFactorIsFittedWithItsBand) {
  const double pi = 3.14159265358979323846;
  const auto series = [&](double a, const std::vector<double>& angles) {
    std::vector<ordered_json> out;
    for (std::size_t k = 0; k < angles.size(); ++k) {
      const double s = std::sin(angles[k] * pi / 180.0);
      out.push_back({{"case", names[k]}, {"status", "done"}, {"bedding_angle_deg", angles[k]}, {"q", 1000.0 * (1.0 - a * s * s)}});
    }
    return out;
  };
  const auto judged = [&](const std::string& extra, const std::vector<ordered_json>& rows, const std::string& band_text = "[]") {
    return judge(check(R"({"expect": "bedding_factor", "cases": ["a", "b", "c", "d"], "column": "q")" + extra + "}"), rows, bands(band_text));
  };
  // Four beddings on the exact form: a = 0.2 back, reported.
  const CheckResult exact = judged("", series(0.2, {0, 30, 60, 90}));
  EXPECT_EQ(name_of(exact.status), "reported");
  EXPECT_NE(exact.numbers.find("a = 0.2"), std::string::npos) << exact.numbers;
  // 0 and 90 only (the rest at 0 carry nothing): a = 1 - q(90)/q(0) = 0.1; over a 10 % band its
  // ends are 1 - 900 (1 + 0.1) / (1000 (1 - 0.1)) = -0.1 and 1 - 900 (1 - 0.1) / (1000 (1 + 0.1)) = 0.264.
  const std::vector<ordered_json> pair = series(0.1, {0, 0, 0, 90});
  const std::string q10 = R"([{"column": "q", "relative": 0.1, "source": "s"}])";
  const CheckResult wide = judged("", pair, q10);
  EXPECT_NE(wide.numbers.find("a = 0.1 (-0.1 to 0.264 over the band)"), std::string::npos) << wide.numbers;
  EXPECT_EQ(name_of(judged(R"(, "value": 0.12, "within_abs": 0.05)", pair).status), "holds");
  EXPECT_EQ(name_of(judged(R"(, "value": 0.3, "within_abs": 0.05)", pair).status), "fails");
  EXPECT_EQ(name_of(judged(R"(, "value": 0.12, "within_abs": 0.05)", pair, q10).status), "within the band");
  EXPECT_EQ(name_of(judged(R"(, "value": 0.08, "within_abs": 0.2)", pair, q10).status), "holds");    // 0.18 and 0.184 off
  EXPECT_EQ(name_of(judged(R"(, "value": 0.6, "within_abs": 0.05)", pair, q10).status), "fails");    // 0.264 < 0.55
  // A series that does not start at bedding 0, or a case without its angle, leaves it open.
  EXPECT_EQ(name_of(judged("", series(0.1, {20, 45, 70, 90})).status), "open");
  std::vector<ordered_json> no_angle = pair;
  no_angle[3].erase("bedding_angle_deg");
  EXPECT_EQ(name_of(judged("", no_angle).status), "open");
}

// A spread every case shares (q10 with 30 % common: 94.9 about a = 300 against an outside value,
// hypot(30, 90)) cancels between cases and widens only `near`.
TEST(SweepFindings, ACommonSpreadWidensOnlyTheComparisonWithAnOutsideValue) {
  const std::string q10 = R"([{"column": "q", "relative": 0.1, "source": "s"}])";
  const std::string shared = R"([{"column": "q", "relative": 0.1, "common": 0.3, "source": "s"}])";
  const std::string far = R"({"expect": "near", "value": 400, "within_abs": 20, "cases": ["a"], "column": "q"})";
  const std::string close = R"({"expect": "near", "value": 310, "within": 0.2, "cases": ["a"], "column": "q"})";
  EXPECT_EQ(banded(far, q10), "fails");  // 100 off, band 30: beyond 20 at either end
  EXPECT_EQ(banded(far, shared), "within the band");  // 100 - 94.9 < 20 < 100 + 94.9
  EXPECT_EQ(banded(close, q10), "holds");  // 10 + 30 <= 62
  EXPECT_EQ(banded(close, shared), "within the band");  // 10 + 94.9 > 62
  for (const char* between : {R"({"expect": "decreasing", "cases": ["a", "b", "c"], "column": "q"})",
                              R"({"expect": "greater", "cases": ["a", "b"], "column": "q"})"})
    EXPECT_EQ(banded(between, shared), banded(between, q10)) << between;
  const CheckResult r = judge(check(far), rows(), bands(shared));
  EXPECT_NE(r.numbers.find("with the part common to every case"), std::string::npos) << r.numbers;
}

TEST(SweepFindings, BadBandsNameTheirPath) {
  const auto error_of = [](const std::string& text) {
    try {
      bands(text);
    } catch (const acst::common::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(error_of(R"([{"relative": 0.1, "source": "s"}])").find("/bands/0: 'column' is required"), std::string::npos);
  EXPECT_NE(error_of(R"([{"column": "q", "relative": -0.1, "source": "s"}])").find("/bands/0/relative"), std::string::npos);
  EXPECT_NE(error_of(R"([{"column": "q", "relative": 0.1, "absolute": 1, "source": "s"}])").find("/bands/0"), std::string::npos);
  EXPECT_NE(error_of(R"([{"column": "q", "relative": 0.1}])").find("'source' is required"), std::string::npos);
  EXPECT_NE(error_of(R"([{"column": "q", "relative": 0.1, "common": -0.2, "source": "s"}])").find("/bands/0/common"),
            std::string::npos);
  EXPECT_NE(error_of(R"([{"column": "q", "relative": 0.1, "source": "s"}, {"column": "q", "absolute": 1, "source": "s"}])")
                .find("/bands/1/column"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"column": "q"})").find("/bands"), std::string::npos);
}

TEST(SweepFindings, TheVerdictFollowsItsChecks) {
  const auto results = [](std::vector<CheckStatus> statuses) {
    std::vector<CheckResult> out;
    for (CheckStatus s : statuses) out.push_back({s, ""});
    return out;
  };
  using S = CheckStatus;
  EXPECT_EQ(verdict(results({S::holds, S::holds})), "reproduced");
  EXPECT_EQ(verdict(results({S::holds, S::reported})), "reproduced");
  EXPECT_EQ(verdict(results({S::fails, S::fails})), "not reproduced");
  EXPECT_EQ(verdict(results({S::holds, S::fails})), "partly reproduced");
  EXPECT_EQ(verdict(results({S::holds, S::open})), "open");
  EXPECT_EQ(verdict(results({S::reported})), "reported");
  EXPECT_EQ(verdict(results({S::within_band, S::within_band})), "not decided within the band");
  EXPECT_EQ(verdict(results({S::holds, S::within_band})), "reproduced where decided");
  EXPECT_EQ(verdict(results({S::fails, S::within_band})), "not reproduced where decided");
  EXPECT_EQ(verdict(results({S::holds, S::fails, S::within_band})), "partly reproduced");
}

TEST(SweepFindings, BadChecksNameTheirPath) {
  struct Bad {
    std::string text, says;
  };
  const std::vector<Bad> bad{
      {R"({"expect": "decreasing", "cases": ["a", "z"], "column": "q"})", "/findings/0/checks/0/cases/1: 'z' is not a case"},
      {R"({"expect": "rising", "cases": ["a"], "column": "q"})", "/findings/0/checks/0/expect"},
      {R"({"expect": "decreasing", "cases": ["a"], "column": "q"})", "'decreasing' needs two or more cases and one column"},
      {R"({"expect": "similar", "cases": ["a", "b"], "column": "q"})", "'similar' needs two or more cases, one column and 'within'"},
      {R"({"expect": "ratio", "value": 1, "cases": ["a", "b"], "column": "q"})", "'ratio' needs"},
      {R"({"expect": "near", "value": 1, "within": 0.1, "within_abs": 2, "cases": ["a"], "column": "q"})", "one of 'within'"},
      {R"({"expect": "report", "cases": ["a", "b"], "columns": ["q", "r"]})", "two columns go with 'greater' only"},
      {R"({"expect": "bedding_factor", "value": 0.1, "cases": ["a", "b"], "column": "q"})", "'bedding_factor' needs"},
      {R"({"expect": "bedding_factor", "within": 0.1, "cases": ["a", "b"], "column": "q"})", "'bedding_factor' needs"},
      {R"({"expect": "greater", "cases": ["a", "b"]})", "one of column, columns is required"},
      {R"({"expect": "greater", "cases": ["a", "b"], "column": "q", "colour": 1})", "/findings/0/checks/0/colour: unknown key"},
  };
  for (const Bad& b : bad) {
    const std::string message = error(b.text);
    EXPECT_NE(message.find(b.says), std::string::npos) << b.text << "\n" << message;
  }
}

namespace acst::test::sweep_findings_test {

// A relative spread needs a scale that does not vanish: values at zero, near it or negative (H, M,
// heave, the asymmetry) read as they are. Equal values are alike whatever their sign; -2 and -1
// differ by 100 % of the smaller size, as 1 and 2 do; 0 and 1 by 100 % of the larger.
TEST(SweepFindings, SimilarAndDifferentHoldAtZeroAndForNegativeValues) {
  const auto judged = [](double x, double y, const char* expect, double within) {
    FindingCheck c;
    c.expect = expect == std::string("similar") ? Expectation::similar : Expectation::different;
    c.cases = {"x", "y"};
    c.columns = {"v"};
    c.within = within;
    const std::vector<ordered_json> rows = {{{"case", "x"}, {"status", "done"}, {"v", x}},
                                            {{"case", "y"}, {"status", "done"}, {"v", y}}};
    const CheckResult r = judge(c, rows);
    EXPECT_EQ(r.numbers.find("nan"), std::string::npos) << r.numbers;
    return std::string(name_of(r.status));
  };
  EXPECT_EQ(judged(0.0, 0.0, "similar", 0.01), "holds");
  EXPECT_EQ(judged(0.0, 0.0, "different", 0.01), "fails");
  EXPECT_EQ(judged(-5.0, -5.0, "similar", 0.01), "holds");
  EXPECT_EQ(judged(-2.0, -1.0, "similar", 0.99), "fails");
  EXPECT_EQ(judged(-2.0, -1.0, "similar", 1.0), "holds");
  EXPECT_EQ(judged(-2.0, -1.0, "different", 0.5), "holds");
  EXPECT_EQ(judged(1.0, 2.0, "similar", 1.0), "holds");
  EXPECT_EQ(judged(0.0, 1.0, "similar", 0.99), "fails");
  EXPECT_EQ(judged(-1.0, 1.0, "similar", 2.0), "holds");  // across zero: 2 of the larger size 1
  EXPECT_EQ(judged(-1.0, 1.0, "similar", 1.9), "fails");
  // A ratio over a zero is no ratio: open, said in the numbers, never infinity or NaN.
  FindingCheck ratio;
  ratio.expect = Expectation::ratio;
  ratio.cases = {"x", "y"};
  ratio.columns = {"v"};
  ratio.value = 1.0;
  ratio.within = 0.1;
  const std::vector<ordered_json> zero = {{{"case", "x"}, {"status", "done"}, {"v", 0.0}}, {{"case", "y"}, {"status", "done"}, {"v", 0.0}}};
  const CheckResult r = judge(ratio, zero);
  EXPECT_EQ(r.status, CheckStatus::open);
  EXPECT_NE(r.numbers.find("no ratio: the second value is 0"), std::string::npos) << r.numbers;
  EXPECT_EQ(r.numbers.find("nan"), std::string::npos) << r.numbers;
}

}  // namespace acst::test::sweep_findings_test
