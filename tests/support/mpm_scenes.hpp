#pragma once
// Small MPM scenes for the verification tests, built from JSON text like user scenes.
#include <string>

#include "acst_footing_tool/build_simulation.hpp"

namespace mpm_test {

// A rectangle of linear elastic soil (E kPa, nu) on a fixed base with smooth sides.
inline std::string elastic_block(double width, double depth, double h, double E, double nu, double density,
                                 const std::string& extra, const std::string& solver = "{}") {
  return R"({"name": "test", "grid": {"cell_size": )" + std::to_string(h) +
         R"(}, "materials": {"soil": {"model": "linear_elastic", "parameters": {"E": )" + std::to_string(E) +
         R"(, "nu": )" + std::to_string(nu) + R"(}}}, "bodies": [{"material": "soil", "x_range": [0, )" +
         std::to_string(width) + R"(], "y_range": [0, )" + std::to_string(depth) + R"(], "density": )" +
         std::to_string(density) + R"(}], "solver": )" + solver + (extra.empty() ? "" : ", " + extra) + "}";
}

inline acst::mpm::Simulation build(const std::string& json) {
  return acst::mpm::build_simulation(acst::mpm::parse_scene(json));
}

// The reader's message for a bad scene, or "accepted".
inline std::string parse_error(const std::string& json) {
  try {
    acst::mpm::parse_scene(json);
  } catch (const acst::common::InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace mpm_test
