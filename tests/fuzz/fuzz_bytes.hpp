#pragma once
// Reads the fuzzer's bytes as numbers (the role of libFuzzer's FuzzedDataProvider, which ships
// with clang only: the targets also build with g++ to replay their corpus in the test suite).
// Past the end every read gives zero bytes, so any input decodes to something.
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace acst::fuzz {

class Bytes {
 public:
  Bytes(const uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::size_t remaining() const { return size_ - used_; }

  uint64_t bits(int bytes) {
    uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | (used_ < size_ ? data_[used_++] : 0);
    return v;
  }
  bool flag() { return bits(1) & 1; }
  // An integer in [lo, hi] (hi - lo < 256).
  int pick(int lo, int hi) { return lo + static_cast<int>(bits(1) % static_cast<uint64_t>(hi - lo + 1)); }
  // A number in [lo, hi], in 2^32 even steps.
  double in_range(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(bits(4)) / 4294967295.0);
  }
  // Any double: eight bytes as its bit pattern (NaN, infinities and denormals included).
  double any() {
    const uint64_t v = bits(8);
    double d;
    std::memcpy(&d, &v, sizeof d);
    return d;
  }

 private:
  const uint8_t* data_;
  std::size_t size_, used_ = 0;
};

}  // namespace acst::fuzz
