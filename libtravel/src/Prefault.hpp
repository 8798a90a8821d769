// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Buffers sized for a sensor before its first frame (Pipeline's constructor): the first write to
// a fresh page of memory costs a page fault (about 40 us per 4 KiB page on the development VM,
// i.e. ~100 ms for the ~10 MB a 124k-point frame uses), so a pipeline that grows its buffers on
// the first frame makes that frame many times slower than the next ones.
#pragma once

#include <cstddef>
#include <vector>

namespace travel::detail {

/// Gives `v` room for `n` elements and writes them once (so their pages are mapped), keeping its
/// size and contents: later resize()/assign()/push_back() up to `n` neither allocate nor fault.
template <class T>
void prefault(std::vector<T>& v, std::size_t n) {
    if (v.capacity() >= n) return;
    const std::size_t size = v.size();
    v.resize(n);
    v.resize(size);
}

}  // namespace travel::detail
