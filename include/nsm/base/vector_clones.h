// Builds of a kernel for the x86-64 vector levels, the best one chosen when the
// program loads (GCC's target_clones, function multiversioning); one portable
// build elsewhere (aarch64, POWER) and with compilers that lack it.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
/// AVX-512 (x86-64-v4), AVX2 and FMA (x86-64-v3), and plain x86-64.
#  define NSM_CLONES_AVX512_AVX2 __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
/// AVX2 and FMA (x86-64-v3), and plain x86-64.
#  define NSM_CLONES_AVX2 __attribute__((target_clones("arch=x86-64-v3", "default")))
/// AVX-512 (x86-64-v4) only: a kernel the caller runs where
/// nsm_has_avx512() says so.
#  define NSM_TARGET_AVX512 __attribute__((target("arch=x86-64-v4")))
/// Whether the processor has x86-64-v4 (AVX-512 F, BW, CD, DQ, VL).
inline bool nsm_has_avx512()
{
  return __builtin_cpu_supports("x86-64-v4");
}
#else
#  define NSM_CLONES_AVX512_AVX2
#  define NSM_CLONES_AVX2
#  define NSM_TARGET_AVX512
inline bool nsm_has_avx512()
{
  return false;
}
#endif
