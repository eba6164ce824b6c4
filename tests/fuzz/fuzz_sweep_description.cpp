// Sweep descriptions (acst_sweep): mpm::parse_sweep on the fuzzer's bytes, as if read from a file
// in data/sweeps, where the bundled study of the corpus lives (its base scenes resolve). Every
// case's scene is made and read here, so that the reader's overrides, names, groups and findings
// are fuzzed with the scenes they make. A description of more than 64 cases but no more than the
// cap is left out: it would only read more of the same scenes, at a second or more an input.
#include <nlohmann/json.hpp>

#include "acst_common/json_fields.hpp"
#include "acst_sweep/sweep.hpp"
#include "reader_target.hpp"

namespace {

constexpr double most_cases_fuzzed = 64;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  return acst::fuzz::read_or_refuse(data, size, [](const std::string& text) {
    const nlohmann::json j = acst::common::fields::parse_document(text);  // as parse_sweep parses it
    if (j.is_object() && j.contains("cases") && j["cases"].is_array()) {
      const double cases = acst::mpm::sweep_case_count(j["cases"]);
      if (cases > most_cases_fuzzed && cases <= acst::mpm::max_sweep_cases) return;
    }
    acst::mpm::parse_sweep(text, ACST_DATA_DIR "/sweeps/fuzz.json");
  });
}
