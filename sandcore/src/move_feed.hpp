#pragma once
// The moves of one grid's sweep, handed while the sweep runs to the thread that writes
// their grain records (one producer, one consumer). Private to sandcore.
//
// When the two grids are swept side by side, grains moving in both at once have nearby ids, so
// two threads writing grain records would keep stealing each other's cache lines (writing them
// from both threads made a two-thread step slower than one thread). So neither sweep writes a
// record: each feeds its moves here, and the thread whose sweep ends first writes the records of
// both, the other's while that one still sweeps. The longer sweep is then relieved of its own
// record writes, which balances the two threads.

#include "sandcore/grain_store.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

namespace sandcore {

class MoveFeed {
public:
    /// Before a sweep, by the thread that starts it: room for `moves` moves, nothing fed. A sweep
    /// moves each of its grains at most once (every move goes down into a layer it has passed),
    /// so room for every grain is enough; were that ever not so, the moves beyond the room would
    /// wait in an overflow until the sweep ends. Fresh room is not written until used.
    void start(std::size_t moves) {
        if (moves > capacity_) {
            moves_ = std::make_unique_for_overwrite<GrainMove[]>(moves);
            capacity_ = moves;
        }
        size_ = 0;
        sharedSize_ = 0;
        overflow_.clear();
        published_.store(0, std::memory_order_relaxed);
        done_.store(false, std::memory_order_relaxed);
    }

    /// Producer: appends a move, not yet visible to the consumer.
    void push(const GrainMove& move) {
        if (size_ < capacity_)
            moves_[size_++] = move;
        else
            overflow_.push_back(move); // after every move in the room: drained last, order kept
    }
    /// Producer: makes the moves appended so far visible, once enough have gathered (each store
    /// pulls the consumer's copy of the counter's cache line away).
    void publishSome() {
        if (size_ - sharedSize_ >= kBatch) publish();
    }
    /// Producer: the sweep is over; every move is visible.
    void finish() {
        publish();
        done_.store(true, std::memory_order_release);
    }

    /// Consumer: calls write(move) for every move in order, waiting for the producer's until it
    /// has finished. Returns at once for a finished feed.
    template <class Write> void drain(Write&& write) const {
        std::size_t next = 0;
        for (int idle = 0;;) {
            const bool done = done_.load(std::memory_order_acquire);
            const std::size_t end = published_.load(std::memory_order_acquire); // final once done
            if (next < end) idle = 0;
            for (; next < end; ++next) write(moves_[next]);
            if (done) {
                for (const GrainMove& move : overflow_) write(move);
                return;
            }
            // The producer is another thread that is running; yield only when it seems not to be.
            if (++idle % 4096 == 0) std::this_thread::yield();
#if defined(__x86_64__) || defined(__i386__)
            __builtin_ia32_pause();
#endif
        }
    }

private:
    static constexpr std::size_t kBatch = 32;

    void publish() {
        sharedSize_ = size_;
        published_.store(size_, std::memory_order_release);
    }

    // The producer's own fields, then (on a line of their own) the two the consumer polls.
    std::unique_ptr<GrainMove[]> moves_;
    std::size_t capacity_ = 0;
    std::size_t size_ = 0;       // moves appended
    std::size_t sharedSize_ = 0; // moves published, as the producer last stored it
    std::vector<GrainMove> overflow_; // moves beyond capacity_, read by the consumer once done_
    alignas(64) std::atomic<std::size_t> published_{0};
    std::atomic<bool> done_{false};
};

} // namespace sandcore
