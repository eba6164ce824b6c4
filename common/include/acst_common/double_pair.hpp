#pragma once
// Two doubles in one register (SSE2 on x86-64, NEON on AArch64; GCC and Clang vector
// extensions): two divisions in one instruction. Each lane is the correctly rounded quotient, the
// same number a scalar division gives, so pairing the divisions of a hot loop changes no result.
namespace acst::common {

using DoublePair = double __attribute__((vector_size(16)));

}  // namespace acst::common
