#pragma once
// A tool's *_cli function run in-process with its output captured, for the command-line tests.
#include <sstream>
#include <string>
#include <vector>

namespace acst::test {

struct Cli {
  int rc = -1;
  std::string out, err;
};

template <class ToolCli>
Cli run_cli(ToolCli&& tool_cli, const std::vector<std::string>& args) {
  std::ostringstream o, e;
  Cli c;
  c.rc = tool_cli(args, o, e);
  c.out = o.str();
  c.err = e.str();
  return c;
}

}  // namespace acst::test
