#pragma once
// The benchmark programs' command line: `PROGRAM [--help] [ARGUMENT]`, where ARGUMENT is the one
// optional positional value a program takes (an output folder, a repeat count) or none. Anything
// else (an unknown option, a second argument) is refused with exit status 2 rather than taken for
// a folder name or a count, the exit statuses of the project's tools (docs/reliability.md).
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

namespace acst::bench {

// `usage` is printed for --help (exit 0) and after a refusal (exit 2); `takes_argument` says
// whether ARGUMENT exists. Returns ARGUMENT when given.
inline std::optional<std::string> command_line_argument(int argc, char** argv, const char* usage,
                                                        bool takes_argument) {
  const char* program = argc > 0 ? argv[0] : "bench";
  std::optional<std::string> argument;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s", usage);
      std::exit(0);
    }
    const char* problem = nullptr;
    if (!a.empty() && a[0] == '-')
      problem = "unknown option";
    else if (!takes_argument)
      problem = "takes no argument, got";
    else if (argument)
      problem = "takes one argument, got a second one";
    if (problem) {
      std::fprintf(stderr, "%s: %s '%s'\n%s", program, problem, a.c_str(), usage);
      std::exit(2);
    }
    argument = a;
  }
  return argument;
}

}  // namespace acst::bench
