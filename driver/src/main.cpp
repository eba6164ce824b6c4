// acst_element: element tests of the ACST sand model from JSON scenes (see --help).
#include <iostream>

#include "acst_common/cli.hpp"
#include "acst_driver/cli.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  return acst::driver::element_cli(acst::common::arguments(argc, argv), std::cout, std::cerr);
}
