// Consumer of the installed library through the C++ API (compression positive).
#include <acst/material.hpp>
#include <fstream>
#include <iostream>
#include <sstream>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: consumer_cxx PARAMETER_JSON\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::stringstream text;
  text << in.rdbuf();
  try {
    const acst::Material mat = acst::Material::from_json(text.str());
    acst::State s = mat.initial_state(100.0 * acst::identity_tensor(), 0.7, Eigen::Vector3d(0, 0, 1));
    acst::Sym de = acst::Sym::Zero();
    de[2] = 1e-4;  // axial compression along 3
    const acst::integration::Report r = mat.update(s, de);
    if (r.status != acst::integration::Status::ok || !(s.stress[2] > 100.0 && s.stress[2] > s.stress[0])) {
      std::cerr << "unexpected update result\n";
      return 1;
    }
    std::cout << "consumer_cxx: sigma_33 = " << s.stress[2] << " kPa\n";
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
