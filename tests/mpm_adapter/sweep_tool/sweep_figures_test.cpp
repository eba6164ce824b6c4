// acst_sweep's figures (docs/sweeps.md, "Figures"): titles and legends in the reference study's
// symbols from what the cases share and what sets them apart; the panel figures drawn from the
// kept results (each load panel with its own lab curve only, the maps on one colour scale with
// the footing where it is and a half domain mirrored, the histories per tracked point, the load
// path); a folder without its case folders re-plotted from what it kept; bad panel
// descriptions refused with their JSON path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_sweep/case_labels.hpp"
#include "acst_sweep/sweep.hpp"
#include "scratch.hpp"
#include "sweep_runs.hpp"

namespace acst::test::sweep_figures_test {
namespace {

namespace fs = std::filesystem;
using namespace acst::mpm;
using namespace sweep_runs;

std::string description(const std::string& cases, const std::string& extra = "") {
  return R"({"name": "t", "base": ")" + sweep_runs::small_footing + R"(", "cases": )" + cases + (extra.empty() ? "" : ", " + extra) + "}";
}

std::string text_of(const fs::path& file) { return acst::common::read_input_file(file.string()); }

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// The script's text from the panel titled `title` to the next panel's title.
std::string panel(const std::string& script, const std::string& title) {
  const std::size_t from = script.find("set title \"" + title + "\"");
  if (from == std::string::npos) return "";
  return script.substr(from, script.find("set title", from + 1) - from);
}

// The p-th quantile as the figures define it: the sorted values' element nearest p (n - 1).
double quantile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::lround(p * double(v.size() - 1)))];
}

}  // namespace

TEST(CaseLabels, TheTitleHasWhatTheCasesShareAndEachLegendWhatSetsItApart) {
  const SweepSpec s = parse_sweep(description(R"([{"name": "a"},
      {"name": "b", "set": {"/bodies/0/bedding_angle_deg": 45, "/footing/inclination_deg": -20}},
      {"name": "c", "set": {"/materials/sand": "../../data/parameters/toyoura_isotropic_calibrated.json"}}])"),
                                  sweep_runs::small_footing);
  const CaseLabels l = case_labels({&s.cases[0], &s.cases[1], &s.cases[2]});
  EXPECT_EQ(l.shared, "Dr = 85.6 %, B = 0.3 m, L = 2.4 m");
  ASSERT_EQ(l.legends.size(), 3u);
  EXPECT_EQ(l.legends[0], "α = 0°, β = 0°, anisotropic");
  EXPECT_EQ(l.legends[1], "α = 45°, β = 20°, anisotropic");
  EXPECT_EQ(l.legends[2], "α = 0°, β = 0°, isotropic");
  // Cases that differ in nothing a reader names are told apart by their names.
  EXPECT_EQ(case_labels({&s.cases[0], &s.cases[0]}).legends[1], "a");
}

TEST(SweepFigures, PanelsAreDrawnFromTheKeptResultsAndCanBeDrawnAgainWithoutTheCases) {
  const fs::path dir = scratch_folder("sweep_figures");
  const fs::path lab = write(dir / "lab.csv", "# a lab curve\nS_over_B,q_kPa\n0,0\n0.02,900\n0.05,1200\n");
  const std::string cases = R"([{"name": "half", "set": {"/footing/symmetric_half": true,
        "/output/lab_curve": ")" + lab.string() + R"(", "/output/lab_label": "the lab",
        "/output/particle_histories": [{"name": "B", "at": [1.35, 1.05]}, {"name": "C_mirror", "at": [1.65, 1.15]}]}},
      {"name": "inclined", "set": {"/bodies/0/bedding_angle_deg": 90, "/footing/inclination_deg": -20,
        "/output/particle_histories": [{"name": "A", "at": [1.05, 1.05]}, {"name": "B", "at": [1.35, 1.05]},
                                        {"name": "C", "at": [0.75, 1.15]}]}}])";
  const std::string gather = R"("set": {"/output/contours_at_S_over_B": [0.03], "/output/contour_fields": ["shear_strain"]},
      "gather": {"keep": {"maps": ["shear_strain_SB0.030"]}, "panels": [
        {"name": "loads", "kind": "load", "cases": ["half", "inclined"]},
        {"name": "bands", "kind": "map", "map": "shear_strain_SB0.030", "cases": ["half", "inclined"]},
        {"name": "pressures", "kind": "histories", "column": "p_kPa", "cases": ["half", "inclined"]},
        {"name": "path", "kind": "load_path", "cases": ["inclined"]}]})";
  const fs::path file = write(dir / "sweep.json", description(cases, gather));
  const std::string out = (dir / "out").string();
  const Cli run = sweep({"--quiet", "--threads", "1", "--output", out, file.string()});
  ASSERT_EQ(run.rc, 0) << run.err;
  const fs::path figures = fs::path(out) / "figures";

  // One load panel per case, each with its own lab curve only, the legends in the study's symbols.
  const std::string loads = text_of(figures / "loads.gp");
  EXPECT_NE(loads.find("set multiplot layout 1,2"), std::string::npos) << loads;
  EXPECT_NE(loads.find("Dr = 85.6 %, B = 0.3 m, L = 2.4 m"), std::string::npos) << loads;
  EXPECT_EQ(count_of(loads, lab.string()), 1u) << loads;
  EXPECT_NE(panel(loads, "α = 0°, β = 0°").find(lab.string()), std::string::npos) << loads;
  EXPECT_NE(panel(loads, "α = 90°, β = 20°").find("kept/inclined/load_settlement.csv"), std::string::npos) << loads;

  // The maps: one colour scale, the 2nd to 98th percentile of every kept cell of both cases.
  const std::string bands = text_of(figures / "bands.gp");
  std::vector<double> values;
  for (const char* c : {"half", "inclined"})
    for (const std::string& r : data_rows(text_of(fs::path(out) / "kept" / c / "shear_strain_SB0.030.csv")))
      values.push_back(numbers_in(r)[2]);
  ASSERT_FALSE(values.empty());
  const std::smatch range = [&] {
    std::smatch m;
    std::regex_search(bands, m, std::regex(R"(set cbrange \[([^:]+):([^\]]+)\])"));
    return m;
  }();
  ASSERT_EQ(range.size(), 3u) << bands;
  EXPECT_EQ(count_of(bands, "set cbrange"), 1u);
  EXPECT_NEAR(std::stod(range[1]), quantile(values, 0.02), 1e-5 * (1.0 + std::fabs(quantile(values, 0.02))));
  EXPECT_NEAR(std::stod(range[2]), quantile(values, 0.98), 1e-5 * (1.0 + std::fabs(quantile(values, 0.98))));
  // The half domain is drawn with its mirror image, the whole one as it is.
  const std::string half = panel(bands, "α = 0°, β = 0°"), inclined = panel(bands, "α = 90°, β = 20°");
  EXPECT_NE(half.find("using (1.2-$1)"), std::string::npos) << half;
  EXPECT_EQ(inclined.find("using (1.2-$1)"), std::string::npos) << inclined;
  // The footing where it is at S/B 0.03: its base 0.009 m down, the inclined one 0.009 tan 20 deg
  // toward -x.
  const auto footing_at = [](const std::string& text) {
    std::smatch m;
    std::regex_search(text, m, std::regex(R"(rectangle from ([^,]+),([^ ]+) to ([^,]+),)"));
    return m.size() == 4 ? std::vector<double>{std::stod(m[1]), std::stod(m[2]), std::stod(m[3])} : std::vector<double>{};
  };
  const std::vector<double> v = footing_at(half), h = footing_at(inclined);
  ASSERT_EQ(v.size(), 3u) << half;
  ASSERT_EQ(h.size(), 3u) << inclined;
  EXPECT_NEAR(v[0], -0.15, 1e-6);
  EXPECT_NEAR(v[1], -0.009, 1e-6);
  EXPECT_NEAR(v[2], 0.15, 1e-6);
  EXPECT_NEAR(h[0], -0.15 - 0.009 * std::tan(20.0 * M_PI / 180.0), 1e-6);
  // The half domain's mirror image of C is drawn as C, on the left.
  EXPECT_NE(half.find("\"C\" at -"), std::string::npos) << half;
  EXPECT_EQ(half.find("C_mirror"), std::string::npos) << half;

  // A panel per tracked point; the half domain's C_mirror stands in C's panel.
  const std::string pressures = text_of(figures / "pressures.gp");
  for (const char* p : {"point A", "point B", "point C"}) EXPECT_NE(pressures.find(p), std::string::npos) << pressures;
  EXPECT_NE(panel(pressures, "point C").find("kept/half/particle_C_mirror.csv"), std::string::npos) << pressures;
  EXPECT_EQ(panel(pressures, "point A").find("kept/half/"), std::string::npos) << pressures;
  EXPECT_NE(pressures.find("p [kPa]"), std::string::npos) << pressures;
  EXPECT_NE(text_of(figures / "path.gp").find("'V_kN_per_m':'H_kN_per_m'"), std::string::npos);

  // The report shows every figure, and its links resolve.
  const std::string report = text_of(fs::path(out) / "report.md");
  if (acst::common::gnuplot_available()) {
    for (const char* f : {"loads", "bands", "pressures", "path"})
      EXPECT_NE(report.find("figures/" + std::string(f) + ".png"), std::string::npos) << f;
  }
  for (const std::string& link : relative_links(report)) EXPECT_TRUE(fs::exists(fs::path(out) / link)) << link;

  // Without its case folders the sweep draws the same panels again from what it kept.
  fs::remove_all(fs::path(out) / "cases");
  fs::remove(figures / "bands.gp");
  const Cli again = sweep({"--quiet", "--replot", "--output", out, file.string()});
  ASSERT_EQ(again.rc, 0) << again.err;
  EXPECT_EQ(text_of(figures / "bands.gp"), bands);
  EXPECT_EQ(text_of(figures / "loads.gp"), loads);
  EXPECT_NE(text_of(figures / "all.gp").find("kept/half/load_settlement.csv"), std::string::npos);
  // A folder with no table has nothing to re-plot: said, nothing written.
  const Cli empty = sweep({"--quiet", "--replot", "--output", (dir / "empty").string(), file.string()});
  EXPECT_EQ(empty.rc, 2);
  EXPECT_NE(empty.err.find("table.json"), std::string::npos) << empty.err;
  EXPECT_FALSE(fs::exists(dir / "empty" / "figures"));
}

TEST(SweepFigures, BadPanelDescriptionsNameTheirJsonPath) {
  const std::string one = R"([{"name": "a", "group": "g"}])";
  const auto panels = [&](const std::string& p, bool keep = true) {
    return parse_error(description(one, std::string(R"("gather": {)") + (keep ? R"("keep": {"maps": ["N_SB0.010"]}, )" : "") +
                                            R"("panels": )" + p + "}"));
  };
  EXPECT_NE(panels(R"([{"name": "f", "kind": "load", "cases": ["a"]}])", false).find("/gather/keep"), std::string::npos);
  EXPECT_NE(panels(R"([{"name": "f", "kind": "contour", "cases": ["a"]}])").find("/gather/panels/0/kind"), std::string::npos);
  EXPECT_NE(panels(R"([{"name": "f", "kind": "load", "cases": ["b"]}])").find("/gather/panels/0/cases/0"), std::string::npos);
  EXPECT_NE(panels(R"([{"name": "f", "kind": "load", "cases": []}])").find("/gather/panels/0/cases"), std::string::npos);
  EXPECT_NE(panels(R"([{"name": "f", "kind": "map", "map": "N_SB0.5", "cases": ["a"]}])").find("/gather/panels/0/map"),
            std::string::npos);
  EXPECT_NE(panels(R"([{"name": "f", "kind": "map", "cases": ["a"]}])").find("'map'"), std::string::npos);
  EXPECT_NE(panels(R"([{"name": "f", "kind": "load", "column": "N", "cases": ["a"]}])").find("/gather/panels/0/column"),
            std::string::npos);
  EXPECT_NE(panels(R"([{"name": "../f", "kind": "load", "cases": ["a"]}])").find("/gather/panels/0/name"), std::string::npos);
  EXPECT_NE(panels(R"([{"name": "g", "kind": "load", "cases": ["a"]}])").find("/gather/panels/0/name"), std::string::npos);
  EXPECT_NE(panels(R"([{"name": "f", "kind": "load", "cases": ["a"]}, {"name": "f", "kind": "load", "cases": ["a"]}])")
                .find("/gather/panels/1/name"),
            std::string::npos);
  EXPECT_NE(panels(R"([{"name": "f", "kind": "load", "cases": ["a"], "colour": 1}])").find("colour"), std::string::npos);
  EXPECT_EQ(panels(R"([{"name": "f", "kind": "histories", "column": "q_kPa", "cases": ["a"]}])"), "accepted");
  std::string many = R"([{"name": "f", "kind": "load", "cases": ["a")";
  for (int k = 0; k < 64; ++k) many += R"(, "a")";
  EXPECT_NE(panels(many + "]}]").find("/gather/panels/0/cases: 65 cases; allowed: at most 64"), std::string::npos);
}

}  // namespace acst::test::sweep_figures_test
