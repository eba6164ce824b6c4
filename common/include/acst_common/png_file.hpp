#pragma once
// Figures are checked before they take an earlier one's place: gnuplot exits 0 after a write
// that failed (a full disk, a file-size limit), leaving a PNG cut short.
#include <string>

namespace acst::common {

// "" when `path` is a whole PNG file: not empty, the PNG signature first and the IEND chunk
// last; otherwise what is wrong with it ("'a.png' is empty", "... ends before its IEND chunk").
std::string png_problem(const std::string& path);

// Puts the figure gnuplot wrote at `written` in the place of `target` (the same name is
// allowed) when it is a whole PNG, and returns "". Otherwise removes `written`, leaves `target`
// as it was (an earlier figure stays) and returns a warning that says so.
std::string keep_complete_png(const std::string& written, const std::string& target);

}  // namespace acst::common
