#pragma once
// The acst_mpm command line:
//   acst_mpm [--help] [--quiet] [--no-plot] [--output DIR] [--threads N] [--resume FILE] SCENE.json
// Exit status: 0 done; 1 the simulation failed (the message names step and particle); 2 bad
// command line, invalid scene or material (nothing is written).
#include <iosfwd>
#include <string>
#include <vector>

namespace acst::mpm {

int mpm_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace acst::mpm
