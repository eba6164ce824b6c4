#pragma once
// The record a sweep keeps in each published case's folder (sweep_case.json, docs/sweeps.md
// "Folders"): the case's fingerprint and its row. A later run reads it to keep the case; a
// record that is damaged or edited is refused naming the file, never read as far as it goes.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "acst_sweep/case_status.hpp"

namespace acst::mpm {

// A published case's record (sweep_case.json: {"fingerprint": ..., "row": ...}), with the
// fields a later run reads from it.
struct CaseRecord {
  nlohmann::json fingerprint;  // {"scene": ..., "materials": ...}, case_fingerprint's
  nlohmann::ordered_json row;  // as the run wrote it
  CaseStatus status = CaseStatus::pending;
  std::string message;
  bool resumed = false;
};

// The record's text read and every field it is read for checked; InputError naming `path` and
// the field's JSON path otherwise ("'.../sweep_case.json': /row/status: ...").
CaseRecord parse_case_record(const std::string& text, const std::string& path);
// The record of case `name` in the sweep's folder; none when it has no record file. Throws
// InputError naming the file when it cannot be read or is not a record.
std::optional<CaseRecord> read_case_record(const std::string& sweep_dir, const std::string& name);
// The same of its kept results (SWEEP/kept/NAME/sweep_case.json).
std::optional<CaseRecord> read_kept_record(const std::string& sweep_dir, const std::string& name);
// The record at `path`; none when there is no such file.
std::optional<CaseRecord> read_record_in(const std::string& path);

}  // namespace acst::mpm
