// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// -j N for the batch apps: items (frames) are produced on N worker threads and consumed on the
// calling thread in input order, so every output is written exactly as with -j 1. The library
// stays single-threaded per instance: each worker owns its own Pipeline / Segmenter.
//
//   forEachInOrder<FrameEvaluation>(files.size(), jobs,
//       [&] { return !segmenter->independentFrames(); },        // sequential while true
//       [&](unsigned n) { ...room for n workers (each may copy worker 0 on its thread)... },
//       [&](unsigned w, std::size_t i, FrameEvaluation& slot) { ...worker w fills slot... },
//       [&](std::size_t i, FrameEvaluation& slot) { ...write, print, in order... });
//
// Items whose processing carries state into the next ones (TRAVEL's mount, estimated or checked
// on the first frames) run on the calling thread, one by one, while `sequential()` says so; then
// `fork(workers)` runs once and the remaining items are spread over the workers. At most
// workers + 1 items are in flight (slots are reused: each new one costs page faults). An exception
// thrown by `produce` reaches the caller when its item's turn to be consumed comes (the items
// before it are consumed, as with -j 1); one thrown by `consume` (e.g. an interrupt) stops the
// workers and propagates.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace travel::apps {

/// The default of -j: the number of cores (1 when unknown).
inline unsigned defaultJobs() {
    return std::max(1u, std::thread::hardware_concurrency());
}

template <class Slot, class Sequential, class Fork, class Produce, class Consume>
void forEachInOrder(std::size_t count, unsigned workers, Sequential sequential, Fork fork,
                    Produce produce, Consume consume) {
    workers = std::max(1u, workers);
    std::size_t next = 0;
    if (workers == 1 || count < 2) {
        Slot slot;
        for (; next < count; ++next) produce(0u, next, slot), consume(next, slot);
        return;
    }
    {
        Slot slot;
        for (; next < count && sequential(); ++next) produce(0u, next, slot), consume(next, slot);
    }
    if (next == count) return;
    fork(workers);

    // Ring of slots: item i lives in slot i % window until consumed.
    const std::size_t window = static_cast<std::size_t>(workers) + 1;
    std::vector<Slot> slots(window);
    std::vector<std::exception_ptr> errors(window);
    std::vector<char> done(window, 0);
    std::mutex mutex;
    std::condition_variable changed;
    std::size_t claimed = next;   // next item a worker takes
    std::size_t consumed = next;  // next item to consume
    bool stop = false;

    auto work = [&](unsigned w) {
        for (;;) {
            std::size_t item;
            {
                std::unique_lock<std::mutex> lock(mutex);
                changed.wait(lock,
                             [&] { return stop || claimed < std::min(count, consumed + window); });
                if (stop || claimed >= count) return;
                item = claimed++;
            }
            const std::size_t s = item % window;
            std::exception_ptr error;
            try {
                produce(w, item, slots[s]);
            } catch (...) {
                error = std::current_exception();
            }
            {
                std::lock_guard<std::mutex> lock(mutex);
                errors[s] = error;
                done[s] = 1;
                if (error) stop = true;  // nothing after a failed item is consumed
            }
            changed.notify_all();
        }
    };
    std::vector<std::thread> threads;
    auto finish = [&] {
        {
            std::lock_guard<std::mutex> lock(mutex);
            stop = true;
        }
        changed.notify_all();
        for (std::thread& t : threads) t.join();
        threads.clear();
    };
    try {
        for (unsigned w = 0; w < workers; ++w) threads.emplace_back(work, w);
        for (; consumed < count;) {
            const std::size_t s = consumed % window;
            {
                std::unique_lock<std::mutex> lock(mutex);
                changed.wait(lock, [&] { return done[s] != 0; });
                done[s] = 0;
            }
            if (errors[s]) std::rethrow_exception(errors[s]);
            consume(consumed, slots[s]);
            {
                std::lock_guard<std::mutex> lock(mutex);
                ++consumed;
            }
            changed.notify_all();
        }
    } catch (...) {
        finish();
        throw;
    }
    finish();
}

}  // namespace travel::apps
