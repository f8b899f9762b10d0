#pragma once
// Whether this CPU runs the AVX2/FMA clones of the thermal kernels (the build's baseline is SSE2;
// each kernel is compiled for both and picks one at run time).

namespace mtcs::thermal {

inline bool has_avx2_fma() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}

}  // namespace mtcs::thermal
