#include "acst_common/json_file.hpp"

#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"

namespace acst::common::fields {

namespace {

std::string where(const std::string& what, const std::string& named_at) {
  return (named_at.empty() ? "" : named_at + ": ") + what + " ";
}

}  // namespace

nlohmann::json read_json_file(const std::string& path, const std::string& what, const std::string& named_at) {
  std::string text;
  try {
    text = read_input_file(path);
  } catch (const InputError& e) {  // "'<path>': <reason>"
    throw InputError(where(what, named_at) + e.what());
  }
  return parse_json_file_text(text, path, what, named_at);
}

nlohmann::json parse_json_file_text(const std::string& text, const std::string& path, const std::string& what,
                                    const std::string& named_at) {
  try {
    return parse_document(text);
  } catch (const InputError& e) {
    throw InputError(where(what, named_at) + "'" + path + "': not valid JSON: " + e.what());
  }
}

}  // namespace acst::common::fields
