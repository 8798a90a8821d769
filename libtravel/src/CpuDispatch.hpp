// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Per-point loops compiled twice, for AVX2 and for the x86-64 baseline the build targets, the
// copy picked once at load time by the CPU (GCC function multiversioning). Only AVX2, never
// FMA: a fused multiply-add rounds once where the baseline rounds twice, so with FMA the sums,
// planes and labels could differ between machines. Without it every float operation rounds as
// in the baseline build: the results are bit-identical on every CPU; only more lanes run at once.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define TRAVEL_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define TRAVEL_AVX2_CLONES
#endif

// A helper of a TRAVEL_AVX2_CLONES function inlined into it, so that its AVX2 copy compiles the
// helper for AVX2 too (a call would run the baseline code).
#if defined(__GNUC__)
#define TRAVEL_INTO_CALLER __attribute__((always_inline)) inline
#else
#define TRAVEL_INTO_CALLER inline
#endif
