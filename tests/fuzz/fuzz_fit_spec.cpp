// Fit descriptions (acst_fit): calibration::parse_fit_spec on the fuzzer's bytes. Relative file
// names resolve against data/calibration, where the bundled descriptions of the corpus live.
#include "acst_calibration/fit_spec.hpp"
#include "reader_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  return acst::fuzz::read_or_refuse(data, size, [](const std::string& text) {
    acst::calibration::parse_fit_spec(text, ACST_DATA_DIR "/calibration", "fuzz");
  });
}
