#pragma once
// The command-line skeleton the project's tools share:
//   TOOL [--help] [--quiet] [--no-plot] [--output DIR] [--threads N] [tool options] INPUT...
// Exit status of every tool: 0 done, 1 failed while running, 2 bad command line or bad input.
#include <iosfwd>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace acst::common {

inline constexpr int exit_done = 0, exit_failed = 1, exit_bad_input = 2;

struct CliSpec {
  CliSpec(std::string tool_name, std::string input) : tool(std::move(tool_name)), input_name(std::move(input)) {}
  std::string tool;                        // "acst_mpm": starts every message
  std::string input_name;                  // "scene file": for "no scene file given"
  bool many_inputs = false;                // acst_element takes several scenes
  bool threads = false;                    // --threads N is an option of this tool
  int min_threads = 1;                     // acst_fit takes 0 (= all hardware threads)
  std::vector<std::string> value_options;  // tool-specific options with a value, e.g. "--resume"
  std::vector<std::string> flag_options;   // tool-specific options without one, e.g. "--cross-validate"
};

struct CliArgs {
  bool quiet = false, plot = true;
  std::string output;  // "" when not given
  int threads = -1;    // -1 when not given
  std::map<std::string, std::string> values;  // the tool-specific options given
  std::set<std::string> flags;                // the tool-specific flags given
  std::vector<std::string> inputs;
};

// Parses `args` (without the program name). Returns -1 to go on, or the exit status to return
// now: 0 after printing `usage` for --help, 2 after a message (and the usage for a missing
// input) on `err`.
int parse_command_line(const CliSpec& spec, const std::vector<std::string>& args, const std::string& usage,
                       std::ostream& out, std::ostream& err, CliArgs& parsed);

// argv as the vector the tools' *_cli functions take.
std::vector<std::string> arguments(int argc, char** argv);

}  // namespace acst::common
