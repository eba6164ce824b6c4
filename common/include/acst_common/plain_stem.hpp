#pragma once
// Names a user gives that become file names or reach generated scripts (scene names, output
// names) must be plain file stems: they can neither leave the output folder nor carry quotes,
// newlines or shell syntax into a gnuplot script.
#include <string>

namespace acst::common {

// 1 to 100 characters from [A-Za-z0-9._-], not starting with '.' (so never "." or "..").
bool is_plain_stem(const std::string& name);

// Returns `name`, or throws InputError at `path` saying what a plain stem is.
const std::string& require_plain_stem(const std::string& name, const std::string& path);

}  // namespace acst::common
