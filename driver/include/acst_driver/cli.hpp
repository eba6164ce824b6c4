#pragma once
// The acst_element command line: acst_element [--help] [--quiet] [--no-plot] [--output DIR] SCENE.json...
// Every scene is read and validated before any is run: with an invalid scene nothing is written.
// Exit status: 0 all ran; 1 a scene failed while running; 2 bad command line or invalid scene.
#include <iosfwd>
#include <string>
#include <vector>

namespace acst::driver {

int element_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace acst::driver
