// acst_mpm: runs MPM scenes (strip footings on ACST sand, verification problems).
#include <iostream>

#include "acst_common/cli.hpp"
#include "acst_footing_tool/cli.hpp"

int main(int argc, char** argv) { return acst::mpm::mpm_cli(acst::common::arguments(argc, argv), std::cout, std::cerr); }
