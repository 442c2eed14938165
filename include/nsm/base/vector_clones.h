// Builds of a kernel for the x86-64 vector levels, the best one chosen when the
// program loads (GCC's target_clones, function multiversioning); one portable
// build elsewhere (aarch64, POWER) and with compilers that lack it.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
/// AVX-512 (x86-64-v4), AVX2 and FMA (x86-64-v3), and plain x86-64.
#  define NSM_CLONES_AVX512_AVX2 __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
/// AVX2 and FMA (x86-64-v3), and plain x86-64.
#  define NSM_CLONES_AVX2 __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#  define NSM_CLONES_AVX512_AVX2
#  define NSM_CLONES_AVX2
#endif
