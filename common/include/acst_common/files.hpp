#pragma once
// Reading input files and writing output files that are never left half written.
#include <cstdint>
#include <string>

namespace acst::common {

// `name` as given when it is absolute (or there is no base), else relative to `base_dir`, the
// folder of the file that names it.
std::string resolve(const std::string& base_dir, const std::string& name);

// Inputs larger than this are refused: every input of the tools (scenes, fit descriptions,
// material and lab files) is far smaller, and a bigger one is a mistake that would otherwise be
// read into memory whole.
inline constexpr std::uintmax_t max_input_bytes = std::uintmax_t{64} << 20;

// The whole content of the regular file `path` of at most `max_bytes`. Anything else (missing,
// unreadable, a directory, a device such as /dev/zero, a FIFO, too large) throws InputError
// "'<path>': <reason>" ("'/dev/zero': a character device, not a regular file"), for the caller
// to put its own terms in front (what the file is, a JSON path, a command-line argument). A FIFO
// is opened without waiting for a writer. JSON files: fields::read_json_file (json_file.hpp).
std::string read_input_file(const std::string& path, std::uintmax_t max_bytes = max_input_bytes);

// A hidden temporary name beside `path`, unique to this process.
std::string temporary_name(const std::string& path);
// Whether a file name (no folder) is one temporary_name makes.
bool is_temporary_name(const std::string& name);

// Writes `text` to `path` through a temporary file in the same folder and a rename; throws
// std::runtime_error naming the file. The old file stays whole if anything fails.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace acst::common
