#include "acst_common/json_file.hpp"

#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"

namespace acst::common::fields {

nlohmann::json read_json_file(const std::string& path, const std::string& what, const std::string& named_at) {
  const std::string where = (named_at.empty() ? "" : named_at + ": ") + what + " ";
  std::string text;
  try {
    text = read_input_file(path);
  } catch (const InputError& e) {  // "'<path>': <reason>"
    throw InputError(where + e.what());
  }
  try {
    return parse_document(text);
  } catch (const InputError& e) {
    throw InputError(where + "'" + path + "': not valid JSON: " + e.what());
  }
}

}  // namespace acst::common::fields
