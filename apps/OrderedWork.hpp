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
// `fork(workers)` runs once and the remaining items are spread over the workers (the item after
// which `sequential()` turned false is consumed once they have started). At most workers + 1
// items are in flight (slots are reused, the sequential items' one too: each new one costs page
// faults). An exception thrown by `produce` reaches the caller when its item's turn to be
// consumed comes (the items before it are consumed, as with -j 1); one thrown by `consume` (e.g.
// an interrupt) stops the workers and propagates.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
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
    Slot first;  // the sequential items' slot, then a slot of the ring (its pages are mapped)
    if (workers == 1 || count < 2) {
        for (; next < count; ++next) produce(0u, next, first), consume(next, first);
        return;
    }
    // The item that settles the state is consumed after the fork, while the workers start.
    bool settled_item = false;
    while (next < count && sequential()) {
        produce(0u, next, first);
        ++next;
        if (next < count && sequential()) {
            consume(next - 1, first);
        } else {
            settled_item = true;
            break;
        }
    }
    if (next == count) {
        if (settled_item) consume(next - 1, first);
        return;
    }
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
    if (settled_item) {
        --consumed;
        std::swap(slots[consumed % window], first);
        done[consumed % window] = 1;
    }
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

/// -j N: objects (the workers' segmenters) built on their own threads while the caller goes on.
/// Each TRAVEL pipeline maps ~20 MB of buffers when it is built; on a virtual machine that
/// backs its memory lazily a first write to a page costs ~15 us (~100 ms a pipeline), so
/// workers built one after the other, once the first frame has settled the mount, start late:
/// built here, next to the first one, they are ready with it and only take its settled state.
template <class T>
class BackgroundBuilds {
  public:
    template <class Make>
    BackgroundBuilds(unsigned count, Make make) : items_(count), errors_(count) {
        for (unsigned i = 0; i < count; ++i)
            threads_.emplace_back([this, i, make]() mutable {
                try {
                    items_[i] = make(i);
                } catch (...) {
                    errors_[i] = std::current_exception();
                }
            });
    }
    ~BackgroundBuilds() {
        for (std::thread& t : threads_)
            if (t.joinable()) t.join();
    }
    BackgroundBuilds(const BackgroundBuilds&) = delete;
    BackgroundBuilds& operator=(const BackgroundBuilds&) = delete;

    /// Item i, once built (rethrows what building it threw). Once per item, from one thread.
    T take(unsigned i) {
        if (threads_.at(i).joinable()) threads_[i].join();
        if (errors_[i]) std::rethrow_exception(errors_[i]);
        return std::move(items_[i]);
    }

  private:
    std::vector<T> items_;
    std::vector<std::exception_ptr> errors_;
    std::vector<std::thread> threads_;
};

/// -j N for a stream whose items must be prepared one after the other on the calling thread
/// (travel-rawlog: each record's motion data feeds the next frames), then processed on N
/// workers, then consumed on the calling thread in preparation order:
///
///   OrderedSlots<Slot> pool(jobs, [&](unsigned w, Slot& s) { ...worker w processes s... });
///   while (...) {
///       Slot& s = pool.next(consume);   // consumes finished items while no slot is free
///       ...prepare s...
///       pool.submit();                  // or pool.submitDone() when prepared and processed here
///   }
///   pool.drain(consume);
///
/// At most N + 1 slots exist (reused: each new one costs page faults). An exception thrown by
/// the work reaches the caller when its item's turn to be consumed comes, as with -j 1; the
/// destructor stops and joins the workers (a worker finishes its current item first).
template <class Slot>
class OrderedSlots {
  public:
    template <class Work>
    OrderedSlots(unsigned workers, Work work)
        : slots_(std::max(1u, workers) + 1), errors_(slots_.size()), done_(slots_.size(), 0) {
        for (unsigned w = 0; w < std::max(1u, workers); ++w)
            threads_.emplace_back([this, w, work]() mutable { run(w, work); });
    }
    ~OrderedSlots() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        changed_.notify_all();
        for (std::thread& t : threads_) t.join();
    }
    OrderedSlots(const OrderedSlots&) = delete;
    OrderedSlots& operator=(const OrderedSlots&) = delete;

    /// The slot of the next item; while all are in use, consumes the oldest once finished.
    template <class Consume>
    Slot& next(Consume consume) {
        if (in_use_ == slots_.size()) consumeOldest(consume);
        return slots_[(first_ + in_use_) % slots_.size()];
    }
    /// Hands the slot of the last next() to the workers.
    void submit() { add(false); }
    /// The slot of the last next() needs no worker (the caller processed it): it is consumed in
    /// its turn.
    void submitDone() { add(true); }
    /// Consumes every submitted item, in order.
    template <class Consume>
    void drain(Consume consume) {
        while (in_use_) consumeOldest(consume);
    }

  private:
    template <class Work>
    void run(unsigned w, Work& work) {
        for (;;) {
            std::size_t s;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                changed_.wait(lock, [&] { return stop_ || !queue_.empty(); });
                if (stop_) return;
                s = queue_.front();
                queue_.pop_front();
            }
            std::exception_ptr error;
            try {
                work(w, slots_[s]);
            } catch (...) {
                error = std::current_exception();
            }
            {
                std::lock_guard<std::mutex> lock(mutex_);
                errors_[s] = error;
                done_[s] = 1;
            }
            changed_.notify_all();
        }
    }
    void add(bool done) {
        const std::size_t s = (first_ + in_use_) % slots_.size();
        ++in_use_;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            errors_[s] = nullptr;
            done_[s] = done;
            if (!done) queue_.push_back(s);
        }
        if (!done) changed_.notify_all();
    }
    template <class Consume>
    void consumeOldest(Consume& consume) {
        const std::size_t s = first_;
        std::exception_ptr error;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            changed_.wait(lock, [&] { return done_[s] != 0; });
            done_[s] = 0;
            error = errors_[s];
        }
        first_ = (first_ + 1) % slots_.size();
        --in_use_;
        if (error) std::rethrow_exception(error);
        consume(slots_[s]);
    }

    std::vector<Slot> slots_;
    std::vector<std::exception_ptr> errors_;
    std::vector<char> done_;
    std::deque<std::size_t> queue_;  // submitted slots not yet taken by a worker
    std::size_t first_ = 0;          // oldest slot in use (caller's thread only)
    std::size_t in_use_ = 0;         // slots prepared and not yet consumed (caller's thread only)
    bool stop_ = false;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<std::thread> threads_;
};

}  // namespace travel::apps
