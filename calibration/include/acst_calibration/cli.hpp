#pragma once
// The acst_fit command line: acst_fit [--help] [--quiet] [--no-plot] [--output DIR] [--threads N] FIT.json
// Exit status: 0 fitted and written; 1 the fit ran but could not write its results, or every run
// failed at the optimum; 2 bad command line or invalid fit description (nothing is run or written).
#include <iosfwd>
#include <string>
#include <vector>

namespace acst::calibration {

int fit_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace acst::calibration
