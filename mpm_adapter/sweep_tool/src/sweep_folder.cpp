#include "acst_sweep/sweep_folder.hpp"

#include <filesystem>

#include "acst_common/files.hpp"
#include "acst_common/input_error.hpp"
#include "acst_sweep/kept_results.hpp"
#include "acst_sweep/sweep_case.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const fs::path& where, const std::string& what) {
  throw common::InputError("the sweep folder '" + where.parent_path().string() + "' holds '" + where.filename().string() +
                           "', " + what +
                           ", which acst_sweep does not write: move it away, or choose an empty folder or one of an "
                           "earlier sweep");
}

// Whether `p` is a folder of its own (not a link); refused when it is anything else.
bool own_folder(const fs::path& p) {
  const fs::file_status s = fs::symlink_status(p);
  if (!fs::exists(s)) return false;
  if (fs::is_symlink(s)) refuse(p, "a link");
  if (!fs::is_directory(s)) refuse(p, "a file where a folder belongs");
  return true;
}

bool hidden_own(const std::string& name) {
  return name.size() > 1 && name[0] == '.' && (name.find(".partial") != std::string::npos || common::is_temporary_name(name));
}

}  // namespace

void require_sound_sweep_folder(const std::string& dir) {
  const fs::path root(dir);
  if (own_folder(root / "figures")) own_folder(root / "figures" / "cases");
  if (own_folder(root / sweep_cases_folder)) {
    // A user's folder named like a case would be taken for a case and replaced by it.
    for (const fs::directory_entry& e : fs::directory_iterator(root / sweep_cases_folder)) {
      if (hidden_own(e.path().filename().string())) continue;
      if (e.is_symlink() || !e.is_directory()) refuse(e.path(), e.is_symlink() ? "a link" : "a file");
      if (!fs::is_regular_file(fs::symlink_status(e.path() / sweep_case_record)))
        refuse(e.path(), std::string("a folder without a case record (") + sweep_case_record + ")");
    }
  }
  if (own_folder(root / sweep_kept_folder)) {
    for (const fs::directory_entry& e : fs::directory_iterator(root / sweep_kept_folder)) {
      const fs::file_status s = e.symlink_status();
      if (fs::is_symlink(s)) refuse(e.path(), "a link");
      if (!fs::is_directory(s)) refuse(e.path(), "a file");
      if (hidden_own(e.path().filename().string())) continue;  // a kept folder being built: replaced
      for (const fs::directory_entry& f : fs::directory_iterator(e.path()))
        if (!fs::is_regular_file(f.symlink_status()))
          refuse(f.path(), fs::is_symlink(f.symlink_status()) ? "a link" : "something other than a plain file");
    }
  }
}

}  // namespace acst::mpm
