// Lab curves must have their rows sorted by axial strain (data/lab/README.md): the fit took a
// series' extent from its last row and interpolates along the strain, so reversed rows silently
// changed the fit (issue 14). An unsorted file is refused with its name and line, in the fit
// tool (exit 2, the experiment's JSON path, nothing written) and wherever a lab curve is read.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acst_calibration/cli.hpp"
#include "acst_common/files.hpp"
#include "acst_driver/lab_data.hpp"
#include "scratch.hpp"

namespace acst::test::lab_data_order_test {
namespace {

namespace fs = std::filesystem;

const std::string data = std::string(ACST_SOURCE_DIR) + "/data";
const std::string header = "# kind: TC\n# sigma3_kPa: 100\n# e0: 0.8\n# bedding_angle_deg: 0\n# strain_range_pct: 0 5\n";

std::string error_of(const fs::path& file) {
  try {
    driver::read_lab_curve(file.string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(LabDataOrder, RowsOutOfOrderAreRefusedWithFileAndLine) {
  const fs::path dir = scratch_folder("lab_order");
  // Line 7 is the first data row, line 9 the one that goes back.
  std::ofstream(dir / "reversed.csv") << header << "eps_a_pct,stress_ratio\n1,2.0\n2,2.5\n1.5,2.4\n3,2.6\n";
  EXPECT_EQ(error_of(dir / "reversed.csv"), (dir / "reversed.csv").string() +
                                                ":9: eps_a_pct 1.5 is below the 2 of line 8: rows must be sorted by eps_a_pct "
                                                "(lab-data format, data/lab/README.md)");
  // Ties keep the source order and rows without a strain are skipped: both are allowed.
  std::ofstream(dir / "ties.csv") << header << "eps_a_pct,stress_ratio,eps_v_pct\n1,2.0,\n1,,0.1\n,2.2,\n2,2.5,0.2\n";
  EXPECT_EQ(error_of(dir / "ties.csv"), "");
  fs::remove_all(dir);
}

TEST(LabDataOrder, TheFitToolRefusesAnUnsortedSeries) {
  const fs::path dir = scratch_folder("lab_order_fit");
  // A bundled curve with its data rows reversed (the header rows kept in front).
  std::istringstream original(common::read_input_file(data + "/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv"));
  std::string line, comments, columns;
  std::vector<std::string> rows;
  while (std::getline(original, line)) {
    if (line.empty() || line[0] == '#') comments += line + "\n";
    else if (columns.empty()) columns = line + "\n";
    else rows.push_back(line);
  }
  ASSERT_GT(rows.size(), 10u);
  std::ofstream out(dir / "reversed.csv");
  out << comments << columns;
  for (auto it = rows.rbegin(); it != rows.rend(); ++it) out << *it << "\n";
  out.close();
  std::ofstream(dir / "fit.json") << "{\"material\": {\"file\": \"" << data << "/parameters/toyoura_acst_guide.json\"},"
                                  << " \"parameters\": {\"d1\": {\"start\": 0.5, \"bounds\": [0.1, 2.0]}},"
                                  << " \"experiments\": [{\"data\": \"reversed.csv\"}]}";
  const std::vector<std::string> before = everything_under(dir);
  std::ostringstream o, e;
  EXPECT_EQ(calibration::fit_cli({"--quiet", "--output", (dir / "out").string(), (dir / "fit.json").string()}, o, e), 2);
  const std::string first_row_line = std::to_string(std::count(comments.begin(), comments.end(), '\n') + 2);
  const std::string second_row_line = std::to_string(std::count(comments.begin(), comments.end(), '\n') + 3);
  EXPECT_NE(e.str().find("/experiments/0/data: " + (dir / "reversed.csv").string() + ":" + second_row_line + ": eps_a_pct "),
            std::string::npos) << e.str();
  EXPECT_NE(e.str().find("of line " + first_row_line + ": rows must be sorted by eps_a_pct"), std::string::npos) << e.str();
  EXPECT_EQ(everything_under(dir), before);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace acst::test::lab_data_order_test
