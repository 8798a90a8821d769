// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Per-point loops compiled twice, for AVX2 and for the x86-64 baseline the build targets, the
// copy picked once at load time by the CPU (GCC function multiversioning). Only AVX2, never
// FMA: a fused multiply-add rounds once where the baseline rounds twice, so with FMA the sums,
// planes and labels could differ between machines. Without it every float operation rounds as
// in the baseline build: the results are bit-identical on every CPU; only more lanes run at once.
#pragma once

#include <cstdint>
#include <cstring>

// TRAVEL_NO_CPU_DISPATCH builds the baseline copy only (to check it on an AVX2 machine). Not
// under the sanitizers either: the clones' resolver runs before their runtime is set up (a
// ThreadSanitizer build crashes there).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(TRAVEL_NO_CPU_DISPATCH) && !defined(__SANITIZE_ADDRESS__) &&                    \
    !defined(__SANITIZE_THREAD__)
#define TRAVEL_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define TRAVEL_AVX2_CLONES
#endif

// Hand-written AVX2 intrinsics (loops GCC does not vectorise itself), chosen at run time by
// detail::cpuHasAvx2() rather than by the clones' resolver: GCC on x86-64, not where the build
// asks for baseline code only.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && \
    !defined(TRAVEL_NO_CPU_DISPATCH)
#define TRAVEL_AVX2_INTRINSICS 1
#include <immintrin.h>
#endif

// A helper of a TRAVEL_AVX2_CLONES function inlined into it, so that its AVX2 copy compiles the
// helper for AVX2 too (a call would run the baseline code).
#if defined(__GNUC__)
#define TRAVEL_INTO_CALLER __attribute__((always_inline)) inline
#else
#define TRAVEL_INTO_CALLER inline
#endif

namespace travel::detail {

#ifdef TRAVEL_AVX2_INTRINSICS
/// Whether this CPU runs the TRAVEL_AVX2_INTRINSICS code (AVX2 and POPCNT), checked once.
inline bool cpuHasAvx2() {
    static const bool avx2 = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
    }();
    return avx2;
}
#endif

// kLanes float lanes as one value (GCC vector extension): one AVX register, or two SSE ones in
// the baseline build. Lane l holds exactly what a scalar loop over lane l would: the same
// products and sums in the same order (no FMA is generated for either target).
// (Internal header, in this library's .cpp files only. These values never cross a non-inlined
// call: GCC's note that passing 32-byte vectors by value changes the ABI does not apply.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
constexpr int kLanes = 8;
typedef float Lanes __attribute__((vector_size(4 * kLanes)));
typedef int32_t LaneMask __attribute__((vector_size(4 * kLanes)));

TRAVEL_INTO_CALLER Lanes loadLanes(const float* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
// 1.f where the mask is set, else +0.f (the scalar selections' values, bit for bit).
TRAVEL_INTO_CALLER Lanes oneWhere(const LaneMask& mask) {
    const Lanes one = {1.f, 1.f, 1.f, 1.f, 1.f, 1.f, 1.f, 1.f};
    LaneMask bits;
    std::memcpy(&bits, &one, sizeof bits);
    const LaneMask selected = mask & bits;
    Lanes v;
    std::memcpy(&v, &selected, sizeof v);
    return v;
}

// True when any lane of the mask is set.
TRAVEL_INTO_CALLER bool anyLane(const LaneMask& mask) {
    uint64_t words[sizeof(LaneMask) / sizeof(uint64_t)];
    std::memcpy(words, &mask, sizeof mask);
    uint64_t any = 0;
    for (const uint64_t w : words) any |= w;
    return any != 0;
}

}  // namespace travel::detail
