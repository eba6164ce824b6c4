#pragma once
// Text from users (file names, messages, labels) that goes into a line-oriented output: a CSV
// comment or header row, a progress or summary line. A line break in it would start a line the
// reader takes for data or a new header.
#include <string>

namespace acst::common {

// `text` with every control character (line breaks, tabs, escapes) replaced by a space.
inline std::string one_line(std::string text) {
  for (char& ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) ch = ' ';
  }
  return text;
}

}  // namespace acst::common
