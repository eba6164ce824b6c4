#pragma once
// A 64-bit FNV-1a checksum, for files that must be refused when damaged (checkpoints).
// Each byte passes through a bijection of the running value, so any single changed byte always
// changes the result; random damage goes unnoticed with a probability of about 2^-64. It guards
// against accidents (a flipped bit, a file cut or spliced), not against a forger.
#include <cstdint>
#include <string_view>

namespace acst::common {

inline std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace acst::common
