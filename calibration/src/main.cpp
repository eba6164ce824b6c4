// acst_fit: fits ACST or isotropic parameters to lab curves (see --help).
#include <iostream>

#include "acst_common/cli.hpp"
#include "acst_calibration/cli.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  return acst::calibration::fit_cli(acst::common::arguments(argc, argv), std::cout, std::cerr);
}
