#pragma once
// ACST_INLINE marks the model's formulas that the lanes' kernel (src/update_lanes_kernel.cpp)
// calls as the scalar code does, so that the equations are written once.
//
// Forced inline: the kernel's loops over lanes vectorise only as one straight body, and the loops
// over components in these functions carry `#pragma GCC unroll` for the same reason. For it too,
// the flags of the structs they return are int, not bool: GCC 12 left a returned bool in memory
// (copied as a byte), and that alone kept the kernel's loops from vectorising.
//
// Never an out-of-line copy: the kernel is compiled twice, once with AVX2 and FMA
// (materials/CMakeLists.txt). An inline function of external linkage that the AVX2 object
// emitted would be a weak symbol like the generic objects' copies, and the linker keeps any one
// of them for the whole library: scalar code could then run AVX2 instructions on a CPU without
// them. always_inline inlines every direct call, and an inline function whose calls are all
// inlined and whose address is not taken is never emitted, so the kernel objects define no such
// symbol; tests/CMakeLists.txt's lanes_kernel_symbols checks the AVX2 object for it. (Internal
// linkage, `static`, would avoid the weak symbols too, but an inline function of external
// linkage, as the Sym forms and AcstRates are, may not call one: the one-definition rule.)
#define ACST_INLINE inline __attribute__((always_inline))

namespace acst {

// std::min, std::max and std::clamp as the standard defines them (which operand wins a tie or a
// NaN matters for the bits): the std templates are functions of external linkage that the AVX2
// object could emit.
ACST_INLINE double min_of(double a, double b) { return b < a ? b : a; }
ACST_INLINE double max_of(double a, double b) { return a < b ? b : a; }
ACST_INLINE double clamp_of(double v, double lo, double hi) { return v < lo ? lo : (hi < v ? hi : v); }

}  // namespace acst
