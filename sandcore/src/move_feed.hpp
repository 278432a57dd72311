// SPDX-License-Identifier: MIT
#pragma once
// The moves of one grid's sweep, handed while the sweep runs to the thread that writes
// their grain records (one producer, one consumer, and once the producer has finished any number
// of helpers that share the record writes). Private to sandcore.
//
// When the two grids are swept side by side, grains moving in both at once have nearby ids, so
// two threads writing grain records would keep stealing each other's cache lines (writing them
// from both threads made a two-thread step slower than one thread). So neither sweep writes a
// record: each feeds its moves here, and the thread whose sweep ends first writes the records of
// both, the other's while that one still sweeps. The longer sweep is then relieved of its own
// record writes, which balances the two threads. The writes left when the longer sweep ends
// (in the million-grain classic drain, most steps) are shared: that thread claims chunks of
// them too, while the first lists every move (a helper). Then no sweep runs any more; the two
// threads write records of neighbouring chunks, whose ids lie apart but for a shared line now
// and then, which the timings show no cost of.

#include "sandcore/grain_store.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <thread>
#include <vector>

namespace sandcore {

/// What writes the records of a feed's moves: record(move) writes one, and record.ask(move) asks
/// for the cache line that record(move) will write.
template <class Record>
concept MoveRecorder = requires(Record& record, const GrainMove& move) {
    record(move);
    record.ask(move);
};

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
        claimedChunks_.store(0, std::memory_order_relaxed);
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

    /// Consumer: calls list(moves) for every move in order, a span of moves at a time, waiting
    /// for the producer's until it has finished, and record(move) for each move in a chunk of
    /// kChunk moves that no helper claimed first; the chunks it records it claims itself.
    /// Returns at once for a finished feed that is all claimed, having listed every move.
    template <class List, MoveRecorder Record> void drain(List&& list, Record&& record) {
        std::size_t next = 0;
        for (int idle = 0;;) {
            const bool done = done_.load(std::memory_order_acquire);
            const std::size_t end = published_.load(std::memory_order_acquire); // final once done
            const std::size_t whole = done ? end : end / kChunk * kChunk;       // chunks that may be claimed
            if (next < whole) idle = 0;
            for (; next < whole; next += kChunk) {
                const std::size_t chunkEnd = std::min(next + kChunk, end);
                std::size_t chunk = next / kChunk; // every chunk before it is claimed
                if (claimedChunks_.compare_exchange_strong(chunk, chunk + 1, std::memory_order_relaxed))
                    recordChunk(next, chunkEnd, record);
                list(std::span<const GrainMove>(moves_.get() + next, chunkEnd - next));
            }
            if (done) {
                for (const GrainMove& move : overflow_) record(move);
                list(std::span<const GrainMove>(overflow_));
                return;
            }
            // The producer is another thread that is running; yield only when it seems not to be.
            if (++idle % 4096 == 0) std::this_thread::yield();
#if defined(__x86_64__) || defined(__i386__)
            __builtin_ia32_pause();
#endif
        }
    }
    /// Any thread, once the producer has finished (and the caller has seen it finish): calls
    /// record(move) for the moves of each chunk it claims before the consumer does, until none is
    /// left, so a thread with nothing else to do shares the consumer's writes. Lists nothing; the
    /// overflow stays the consumer's.
    template <MoveRecorder Record> void help(Record&& record) {
        const std::size_t end = published_.load(std::memory_order_acquire);
        for (;;) {
            const std::size_t begin = claimedChunks_.fetch_add(1, std::memory_order_relaxed) * kChunk;
            if (begin >= end) return;
            recordChunk(begin, std::min(begin + kChunk, end), record);
        }
    }

private:
    static constexpr std::size_t kBatch = 32;
    // Moves claimed at once by the consumer or a helper; each record write misses the cache, so
    // the line of the record kAhead moves on is asked for first and several misses overlap.
    static constexpr std::size_t kChunk = 64;
    static constexpr std::size_t kAhead = 16;

    template <class Record> void recordChunk(std::size_t begin, std::size_t end, Record& record) const {
        for (std::size_t n = begin; n < std::min(begin + kAhead, end); ++n) record.ask(moves_[n]);
        for (std::size_t n = begin; n < end; ++n) {
            if (n + kAhead < end) record.ask(moves_[n + kAhead]);
            record(moves_[n]);
        }
    }

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
    alignas(64) std::atomic<std::size_t> claimedChunks_{0}; // chunks whose records are taken, in order
};

} // namespace sandcore
