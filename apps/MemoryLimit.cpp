// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "MemoryLimit.hpp"

#include <sys/resource.h>

#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>

namespace travel::apps {

namespace {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif
}  // namespace

std::string applyMemoryLimit(std::size_t mib) {
    if (mib == 0) return {};
    if (kSanitized)
        return "memory limit not applied in a sanitizer build (its shadow memory needs the "
               "address space)";
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) != 0) return std::string("getrlimit: ") + std::strerror(errno);
    const rlim_t wanted = static_cast<rlim_t>(mib) << 20;
    // Never raise a limit the user already set lower (ulimit -v).
    if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= wanted) return {};
    limit.rlim_cur = wanted;
    if (limit.rlim_max != RLIM_INFINITY && limit.rlim_cur > limit.rlim_max)
        limit.rlim_cur = limit.rlim_max;
    if (setrlimit(RLIMIT_AS, &limit) != 0)
        return std::string("setrlimit(RLIMIT_AS): ") + std::strerror(errno);
    applied_memory_limit_mib = static_cast<std::size_t>(limit.rlim_cur >> 20);
    return {};
}

}  // namespace travel::apps

// Replacements for libmrpt-core's (same semantics: size rounded up to a multiple of the
// alignment, freed by mrpt::aligned_free = free), except that failure throws std::bad_alloc
// instead of returning a null pointer that MRPT's aligned_allocator_cpp11 would write through.
namespace mrpt {
void* aligned_malloc(std::size_t size, std::size_t alignment) {
    if (alignment == 0) alignment = alignof(std::max_align_t);
    if (size % alignment != 0) size = (size / alignment + 1) * alignment;
    void* p = std::aligned_alloc(alignment, size ? size : alignment);
    if (!p) throw std::bad_alloc();
    return p;
}
void* aligned_calloc(std::size_t bytes, std::size_t alignment) {
    void* p = aligned_malloc(bytes, alignment);
    std::memset(p, 0, bytes);
    return p;
}
}  // namespace mrpt
