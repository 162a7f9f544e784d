#include "common/cpu_features.h"

#include <cpuid.h>

namespace relight {

bool has_avx2_fma() {
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has;
}

bool has_f16c() {
  // F16C is CPUID leaf 1, ECX bit 29 (Intel SDM vol. 2A, CPUID); clang 14 has no
  // __builtin_cpu_supports("f16c").
  static const bool has = [] {
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    const bool f16c = __get_cpuid(1, &eax, &ebx, &ecx, &edx) != 0 && (ecx & (1u << 29)) != 0;
    return f16c && has_avx2_fma();
  }();
  return has;
}

}  // namespace relight
