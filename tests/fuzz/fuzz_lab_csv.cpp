// The CSV readers of acst_element and acst_fit on the fuzzer's bytes (the first byte picks the
// reader, the rest is the file's text): a lab curve (driver::parse_lab_curve, data/lab/README.md),
// a commented table read with text cells as NaN (as acst_element reads its own CSV files back),
// and a strain_path_csv step's file (driver::strain_path_segments on the commented table). A
// malformed file is refused with std::runtime_error naming 'file:line' (the tools put the JSON
// path in front) or, for a strain path, common::InputError at the step's path; any other
// exception is a finding, as are a refusal that names no file, a crash and a sanitizer report.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "acst_driver/lab_data.hpp"
#include "acst_driver/strain_path.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::string file = "fuzz.csv";
  try {
    switch (data[0] % 3) {
      case 0: acst::driver::parse_lab_curve(text, file); break;
      case 1: acst::driver::parse_commented_csv(text, file, true); break;
      default: {
        const acst::driver::LabCurve table = acst::driver::parse_commented_csv(text, file);
        acst::driver::strain_path_segments(table, file, "/steps/0/file", 1);
      }
    }
  } catch (const std::runtime_error& e) {  // common::InputError is one too
    static const bool verbose = std::getenv("ACST_FUZZ_VERBOSE") != nullptr;
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
    // Every refusal says which file (docs/reliability.md: 'file:line' for CSV tables).
    if (std::string(e.what()).find(file) == std::string::npos) {
      std::fprintf(stderr, "fuzz_lab_csv: a refusal that names no file: %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}
