#include "acst_common/plain_stem.hpp"

#include <cctype>

#include "acst_common/input_error.hpp"

namespace acst::common {

bool is_plain_stem(const std::string& name) {
  if (name.empty() || name.size() > 100 || name[0] == '.') return false;
  for (unsigned char c : name)
    if (!std::isalnum(c) && c != '.' && c != '_' && c != '-') return false;
  return true;
}

const std::string& require_plain_stem(const std::string& name, const std::string& path) {
  if (!is_plain_stem(name)) {
    std::string shown;
    for (unsigned char c : name.substr(0, 60)) shown += std::isprint(c) ? static_cast<char>(c) : '?';
    throw InputError((path.empty() ? std::string("/") : path) + ": '" + shown +
                     "' is not a plain file stem (1 to 100 letters, digits, '.', '_' or '-', not starting with '.')");
  }
  return name;
}

}  // namespace acst::common
