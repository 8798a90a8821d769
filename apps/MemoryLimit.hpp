// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A memory ceiling for the apps that read MRPT files.
//
// MRPT 2.5's deserializers trust the sizes written in the stream: one flipped byte in a rawlog
// announces a 3.5 GB vector or a deque of billions of pointers, and the process grows until the
// kernel kills it (measured: travel-rawlog reached 23.6 GB on a fuzzed 3 kB rawlog). Capping
// the address space (RLIMIT_AS) turns that into a failed allocation; and because MRPT's aligned
// allocator (mrpt::aligned_malloc) returns null instead of throwing - then writes through it -
// MemoryLimit.cpp also replaces mrpt::aligned_malloc / aligned_calloc with versions that throw
// std::bad_alloc, which the readers report as a corrupt record.
//
// Link MemoryLimit.cpp into the EXECUTABLE (not a static library): its definitions of the two
// MRPT functions must win symbol interposition over libmrpt-core's.
#pragma once

#include <cstddef>
#include <string>

namespace travel::apps {

/// Default ceiling of the apps' address space [MiB]: far above what a real rawlog needs
/// (travel-rawlog on the VLP-16 sample maps ~420 MiB with -j 1, ~660 MiB with -j 2, for 125 MB
/// resident: shared libraries, thread stacks and malloc's per-thread arenas count too).
constexpr std::size_t kDefaultMemoryLimitMiB = 4096;

/// The ceiling applyMemoryLimit() set [MiB], 0 when none: runMain() names it when an
/// allocation or a thread start fails.
inline std::size_t applied_memory_limit_mib = 0;

/// Caps the process's address space at `mib` MiB (0 = no limit). Returns a note for the user
/// when the limit cannot be applied (sanitizer builds reserve terabytes of address space for
/// their shadow memory, so the cap is skipped there), or an empty string.
std::string applyMemoryLimit(std::size_t mib);

}  // namespace travel::apps
