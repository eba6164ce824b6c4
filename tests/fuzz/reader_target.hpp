#pragma once
// The body shared by the reader targets: the fuzzer's bytes are the JSON text; a reader may
// refuse it with the project's input-error type, as the tools do (exit 2). Any other exception
// escapes to libFuzzer, which reports it like a crash: the tools would take it for a failure
// while running, not for bad input. ACST_FUZZ_VERBOSE=1 prints each refusal (to see why a seed
// is refused: `ACST_FUZZ_VERBOSE=1 fuzz_element_scene FILE`).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "acst_common/input_error.hpp"

namespace acst::fuzz {

template <class Read>
int read_or_refuse(const uint8_t* data, std::size_t size, Read&& read) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read(text);
  } catch (const common::InputError& e) {
    static const bool verbose = std::getenv("ACST_FUZZ_VERBOSE") != nullptr;
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
  }
  return 0;
}

}  // namespace acst::fuzz
