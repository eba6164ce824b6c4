#pragma once
// Parameter sets and small helpers shared by the tests (model convention: compression positive).
#include <fstream>
#include <sstream>
#include <string>

#include "acst/material.hpp"

namespace acst::test {

inline std::string read_text(const std::string& relative_path) {
  std::ifstream in(std::string(ACST_SOURCE_DIR) + "/" + relative_path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The design notes' guide set (data/parameters/toyoura_acst_guide.json).
inline Material guide_material() { return Material::from_json(read_text("data/parameters/toyoura_acst_guide.json")); }

inline Material literature_material() {
  return Material::from_json(read_text("data/parameters/toyoura_acst_literature.json"));
}

inline Sym isotropic_stress(double p) { return p * identity_tensor(); }

}  // namespace acst::test
