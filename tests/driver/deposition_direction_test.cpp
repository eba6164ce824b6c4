// A scene's deposition_direction is taken as the model takes it (issue 57, item 10): any finite
// non-zero vector, scaled by its largest component before it is normalised. Normalised directly,
// [1e308, 1e308, 1e308] overflowed its norm and the CSV header stated [0, 0, 0], and the norm of
// [1e-320, 0, 0] underflowed to zero, so acst_element refused a direction the C ABI accepts.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "acst_common/files.hpp"
#include "acst_driver/cli.hpp"
#include "driver_scenes.hpp"
#include "scratch.hpp"

namespace acst::test::deposition_direction_test {
namespace {

namespace fs = std::filesystem;

std::string scene_with_direction(const std::string& direction) {
  return "{\"material\": {\"file\": \"" + parameter_file() + "\"}, \"initial_state\": {\"confining_pressure\": 100, "
         "\"void_ratio\": 0.7, \"deposition_direction\": " + direction + "}, \"steps\": [{\"control\": {\"11\": "
         "{\"strain_pct\": 0.05}, \"22\": {\"stress\": 0}, \"33\": {\"stress\": 0}, \"12\": {\"strain_pct\": 0}, \"13\": "
         "{\"strain_pct\": 0}, \"23\": {\"strain_pct\": 0}}, \"increments\": 2}]}";
}

// The CSV header's initial-state line of the scene's run ("" when the tool refused the scene).
std::string header_line(const fs::path& dir, const std::string& name, const std::string& direction, std::string& err) {
  std::ofstream(dir / (name + ".json")) << scene_with_direction(direction);
  std::ostringstream o, e;
  const int rc = driver::element_cli({"--quiet", "--no-plot", "--output", (dir / "out").string(), (dir / (name + ".json")).string()}, o, e);
  err = e.str();
  if (rc != 0) return "";
  std::istringstream csv(common::read_input_file((dir / "out" / (name + ".csv")).string()));
  for (std::string line; std::getline(csv, line);)
    if (line.rfind("# initial state:", 0) == 0) return line;
  return "no initial-state line";
}

TEST(DepositionDirection, AHugeOrTinyDirectionIsStatedAsItsUnitVector) {
  const fs::path dir = scratch_folder("deposition_direction");
  std::string err;
  // The diagonal: each component 1/sqrt(3) = 0.5774, the angle to axis 1 acos(1/sqrt(3)) = 54.74 deg.
  const std::string huge = header_line(dir, "huge", "[1e308, 1e308, 1e308]", err);
  EXPECT_NE(huge.find("bedding angle 54.74 deg (deposition direction [0.5774, 0.5774, 0.5774])"), std::string::npos)
      << huge << err;
  const std::string tiny = header_line(dir, "tiny", "[1e-320, 0, 0]", err);
  EXPECT_NE(tiny.find("bedding angle 0 deg (deposition direction [1, 0, 0])"), std::string::npos) << tiny << err;
  // Still refused, with its path: the zero vector and a direction that is not finite.
  EXPECT_EQ(header_line(dir, "zero", "[0, 0, 0]", err), "");
  EXPECT_NE(err.find("/initial_state/deposition_direction: must not be the zero vector"), std::string::npos) << err;
  EXPECT_EQ(header_line(dir, "overflow", "[1e999, 0, 0]", err), "");
  EXPECT_NE(err.find("/initial_state/deposition_direction/0"), std::string::npos) << err;
}

}  // namespace
}  // namespace acst::test::deposition_direction_test
