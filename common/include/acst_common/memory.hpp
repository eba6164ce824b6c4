#pragma once
// How much memory a tool may plan to use, for refusing inputs whose estimated needs cannot fit.
#include <string>

namespace acst::common {

// The smaller of `cap_bytes` and the machine's physical memory (the cap alone where that is
// unknown).
double memory_limit_bytes(double cap_bytes);

// "1.5 GiB": bytes for messages.
std::string gib_text(double bytes);

}  // namespace acst::common
