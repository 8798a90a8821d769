// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Batch apps: the frames' buffers in 2 MiB pages.
//
// A TRAVEL pipeline writes ~16 MB of buffers when it is built (sized for a full frame, so that
// the first frame does not pay for them) and every frame slot of an app a few MB more. On the
// development VM the first write to a fresh 4 KiB page costs ~15 us (a page fault the hypervisor
// backs): ~60 ms a pipeline, most of what -j N lost to its extra pipelines and slots (perf:
// 15k page faults for -j 2 over 60 HDL-64E frames against 6k for -j 1). Linux's transparent
// huge pages, in their usual `madvise` mode, map 2 MiB per fault in a range the process marks:
// preferLargePages() marks a range of glibc's heap and keeps every large buffer there.
//
//   int run(...) { travel::apps::preferLargePages(jobs); ...build pipelines, start threads... }
//
// Call it before any thread starts. glibc on Linux only (elsewhere, and when the kernel or the
// allocator does not follow, it changes nothing: buffers are mapped 4 KiB at a time as before).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdlib>
#endif

namespace travel::apps {

/// Keeps the process's large buffers in transparent huge pages: every thread allocates from
/// glibc's main heap (one arena: a worker's buffers land in the marked range too), blocks up to
/// 32 MiB come from that heap rather than from their own mapping, the heap is never trimmed
/// (pages given back would fault again), and the heap grows now by room for `workers` + 1
/// workers (each a pipeline of ~16 MB, frame slots and a read buffer of a few MB), marked
/// MADV_HUGEPAGE (virtual memory: pages are only backed once written). Memory beyond that works
/// as before, in 4 KiB pages.
inline void preferLargePages(unsigned workers) {
#if defined(__linux__) && defined(__GLIBC__)
    constexpr std::size_t kBytesPerWorker = std::size_t{32} << 20;
    const std::size_t heap_bytes = kBytesPerWorker * (std::min(workers, 16u) + 1);
    constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
    constexpr std::size_t kBlock = std::size_t{16} << 20;  // forces the heap to grow
    mallopt(M_ARENA_MAX, 1);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's maximum on 64-bit
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, static_cast<int>(heap_bytes));
    void* block = std::malloc(kBlock);
    mallopt(M_TOP_PAD, 0);  // later growth: as requested
    const auto first = reinterpret_cast<std::uintptr_t>(block);
    const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0));
    // Only when the block came from the heap (not under a sanitizer's allocator, not when the
    // heap could not grow): the range from it to the heap's end is ours to mark.
    if (block && first < end && end - first <= kBlock + heap_bytes + kHugePage) {
        const std::uintptr_t from = (first + kHugePage - 1) & ~(kHugePage - 1);
        const std::uintptr_t to = end & ~(kHugePage - 1);
        if (from < to) madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
    }
    std::free(block);
#else
    (void)workers;
#endif
}

}  // namespace travel::apps
