// A sweep's case records (OUT/cases/NAME/sweep_case.json), which a later run reads back to keep
// the case: mpm::parse_case_record on the fuzzer's bytes. A record edited or damaged must be
// refused with the file named (common::InputError), never end in another exception (the library's
// own type errors were what reached the user).
#include "acst_sweep/case_record.hpp"
#include "reader_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  return acst::fuzz::read_or_refuse(data, size, [](const std::string& text) {
    acst::mpm::parse_case_record(text, "fuzz/cases/a/sweep_case.json");
  });
}
