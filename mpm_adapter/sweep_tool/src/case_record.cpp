#include "acst_sweep/case_record.hpp"

#include <filesystem>

#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/json_file.hpp"
#include "acst_sweep/kept_results.hpp"
#include "acst_sweep/sweep_case.hpp"

namespace acst::mpm {
namespace f = common::fields;
using nlohmann::json;

namespace {

constexpr const char* what_it_is = "the case record";

CaseRecord record_from(const json& j, const std::string& path) {
  try {
    f::allow_keys(j, {"fingerprint", "row"}, "");
    for (const char* k : {"fingerprint", "row"})
      if (!j.contains(k)) f::fail("", std::string("'") + k + "' is required");
    const json& fingerprint = f::object(j["fingerprint"], "/fingerprint");
    f::allow_keys(fingerprint, {"scene", "materials", "build"}, "/fingerprint");
    for (const char* k : {"scene", "materials"}) {
      if (!fingerprint.contains(k)) f::fail("/fingerprint", std::string("'") + k + "' is required");
      f::object(fingerprint[k], std::string("/fingerprint/") + k);
    }
    const json& row = f::object(j["row"], "/row");
    if (!row.contains("status")) f::fail("/row", "'status' is required");
    CaseRecord r;
    r.fingerprint = fingerprint;
    r.row = row;
    r.status = f::choice<CaseStatus>(row["status"], "/row/status", case_status_names);
    if (row.contains("message")) r.message = f::string(row["message"], "/row/message");
    if (row.contains("resumed")) r.resumed = f::boolean(row["resumed"], "/row/resumed");
    return r;
  } catch (const common::InputError& e) {
    throw common::InputError(std::string(what_it_is) + " '" + path + "': " + e.what());
  }
}

}  // namespace

CaseRecord parse_case_record(const std::string& text, const std::string& path) {
  return record_from(f::parse_json_file_text(text, path, what_it_is), path);
}

std::optional<CaseRecord> read_case_record(const std::string& sweep_dir, const std::string& name) {
  return read_record_in((std::filesystem::path(case_folder(sweep_dir, name)) / sweep_case_record).string());
}

std::optional<CaseRecord> read_kept_record(const std::string& sweep_dir, const std::string& name) {
  return read_record_in((std::filesystem::path(kept_case_folder(sweep_dir, name)) / sweep_case_record).string());
}

std::optional<CaseRecord> read_record_in(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return std::nullopt;
  return record_from(f::read_json_file(path, what_it_is), path);
}

}  // namespace acst::mpm
