#pragma once
// Reading input files and writing output files that are never left half written.
#include <optional>
#include <string>

namespace acst::common {

// `name` as given when it is absolute (or there is no base), else relative to `base_dir`, the
// folder of the file that names it.
std::string resolve(const std::string& base_dir, const std::string& name);

// The whole content of a file, or nothing when it cannot be opened (the caller says why, in
// its own terms: a JSON path, a command-line argument).
std::optional<std::string> read_file(const std::string& path);

// A hidden temporary name beside `path`, unique to this process.
std::string temporary_name(const std::string& path);

// Writes `text` to `path` through a temporary file in the same folder and a rename; throws
// std::runtime_error naming the file. The old file stays whole if anything fails.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace acst::common
