#include "acst_common/cli.hpp"

#include <algorithm>
#include <cstdlib>
#include <ostream>

namespace acst::common {

int parse_command_line(const CliSpec& spec, const std::vector<std::string>& args, const std::string& usage,
                       std::ostream& out, std::ostream& err, CliArgs& parsed) {
  const std::string& tool = spec.tool;
  auto takes_value = [&](const std::string& a) {
    return a == "--output" || a == "-o" || (spec.threads && a == "--threads") ||
           std::find(spec.value_options.begin(), spec.value_options.end(), a) != spec.value_options.end();
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string a = args[i], value;
    const auto eq = a.find('=');
    const bool inline_value = a.rfind("--", 0) == 0 && eq != std::string::npos && takes_value(a.substr(0, eq));
    if (inline_value) {
      value = a.substr(eq + 1);
      a = a.substr(0, eq);
    }
    if (a == "--help" || a == "-h") {
      out << usage;
      return exit_done;
    } else if (a == "--quiet" || a == "-q") {
      parsed.quiet = true;
    } else if (a == "--no-plot") {
      parsed.plot = false;
    } else if (takes_value(a)) {
      if (!inline_value) {
        if (i + 1 >= args.size()) {
          err << tool << ": " << a << " needs a value (see --help)\n";
          return exit_bad_input;
        }
        value = args[++i];
      }
      if (a == "--output" || a == "-o") {
        parsed.output = value;
      } else if (a == "--threads") {
        char* end = nullptr;
        const long n = std::strtol(value.c_str(), &end, 10);
        if (value.empty() || *end != '\0' || n < spec.min_threads || n > 1024) {
          err << tool << ": --threads needs an integer in [" << spec.min_threads << ", 1024], got '" << value << "'\n";
          return exit_bad_input;
        }
        parsed.threads = static_cast<int>(n);
      } else {
        parsed.values[a] = value;
      }
    } else if (std::find(spec.flag_options.begin(), spec.flag_options.end(), a) != spec.flag_options.end()) {
      parsed.flags.insert(a);
    } else if (a.size() > 1 && a[0] == '-') {
      err << tool << ": unknown option '" << a << "' (see --help)\n";
      return exit_bad_input;
    } else if (!spec.many_inputs && !parsed.inputs.empty()) {
      err << tool << ": one " << spec.input_name << " at a time (got '" << parsed.inputs.front() << "' and '" << a
          << "')\n";
      return exit_bad_input;
    } else {
      parsed.inputs.push_back(a);
    }
  }
  if (parsed.inputs.empty()) {
    err << tool << ": no " << spec.input_name << " given\n" << usage;
    return exit_bad_input;
  }
  return -1;
}

std::vector<std::string> arguments(int argc, char** argv) { return std::vector<std::string>(argv + 1, argv + argc); }

}  // namespace acst::common
