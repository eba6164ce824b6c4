#pragma once
// Output folders that never hold the files of two runs at once.
#include <cstddef>
#include <functional>
#include <string>

namespace acst::common {

// Name of the subfolder that keeps the files of the run before the last.
inline constexpr const char* previous_run_folder = "previous";

// Makes `dir` ready for a new run of a tool that writes its files there one by one: creates it
// when missing; when it holds an earlier run (every entry but the `previous` folder passes
// `is_own`), moves those files into dir/previous, replacing what an older run left there, and
// returns how many it moved. A folder holding anything else is refused (InputError naming the
// entry), so no file of the user's is ever moved or overwritten. Interrupted at any point, every
// file is still in dir, in dir/previous or in dir/previous.new, which the next call finishes.
std::size_t set_aside_earlier_run(const std::string& dir, const std::function<bool(const std::string&)>& is_own);

// For a tool that publishes its result set as a whole folder: refuses (InputError naming the
// entry) a `dir` that exists and holds an entry `is_own` refuses, before any work is done.
void require_own_folder(const std::string& dir, const std::function<bool(const std::string&)>& is_own);

// A hidden folder beside `dir`, unique to this process, to build the new result set in.
std::string staging_folder_for(const std::string& dir);

// Before a long run whose result set is to replace `dir` (publish_folder): refuses with
// InputError, naming the folder and why, a `dir` whose parent cannot take the staging folder,
// or, where `dir` holds an earlier set, one whose folders do not let that set be removed (a
// read-only folder). Tried by making and removing a hidden folder in each, so that it also holds
// for root and on a read-only file system, where permission bits say nothing.
void require_replaceable_folder(const std::string& dir);

// Puts the folder `staging` in the place of `dir` in one step, so that `dir` holds the whole
// earlier result set or the whole new one at every moment (an atomic exchange, renameat2
// RENAME_EXCHANGE, where the file system has it; else two renames, between which `dir` is
// briefly absent, never mixed); then removes the earlier set. Throws std::runtime_error when the
// new set could not be put in place. Once it is, a failure to remove the earlier set is no
// failure: the returned warning says where it was left ("" when it was removed).
std::string publish_folder(const std::string& staging, const std::string& dir);

}  // namespace acst::common
