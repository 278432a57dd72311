// SPDX-License-Identifier: MIT
// MoveFeed (sandcore's private hand-over of one sweep's moves to the thread that writes the
// grain records): every move arrives once and in order while the producer still runs, also the
// moves beyond the room given at start, which wait in an overflow until the sweep ends. A sweep
// never moves more grains than it has, so no scene reaches the overflow: only this test does.
// A helper that claims chunks of a finished feed's records shares the writes: each record is
// written exactly once, by one of the two, and the consumer still lists every move in order.
#include "move_feed.hpp"

#include <doctest/doctest.h>

#include <atomic>
#include <cstdint>
#include <span>
#include <thread>
#include <vector>

using namespace sandcore;

namespace {

GrainMove moveNumber(std::uint32_t n) {
    return {n, 1000 + n, MoveCode(n % 27), n % 2 == 0 ? GridLevel::Lower : GridLevel::Upper};
}

// A recorder for tests that look only at the listed moves.
struct NoRecords {
    void operator()(const GrainMove&) const {}
    void ask(const GrainMove&) const {}
};

// Counts the record writes of each move (by grain) and the look-aheads.
struct CountingRecorder {
    std::vector<std::atomic<int>>* writes;
    std::atomic<int>* asked;
    void operator()(const GrainMove& move) const { (*writes)[move.grain].fetch_add(1, std::memory_order_relaxed); }
    void ask(const GrainMove&) const { asked->fetch_add(1, std::memory_order_relaxed); }
};

auto appendTo(std::vector<GrainMove>& drained) {
    return [&drained](std::span<const GrainMove> moves) { drained.insert(drained.end(), moves.begin(), moves.end()); };
}

// Feeds `count` moves from another thread (publishing as a sweep does) while this thread drains
// them; returns what the drain saw.
std::vector<GrainMove> feedAndDrain(MoveFeed& feed, std::size_t room, std::uint32_t count) {
    feed.start(room);
    std::thread producer([&] {
        for (std::uint32_t n = 0; n < count; ++n) {
            feed.push(moveNumber(n));
            feed.publishSome();
        }
        feed.finish();
    });
    std::vector<GrainMove> drained;
    feed.drain(appendTo(drained), NoRecords{});
    producer.join();
    return drained;
}

void checkInOrder(const std::vector<GrainMove>& drained, std::uint32_t count) {
    REQUIRE(drained.size() == count);
    for (std::uint32_t n = 0; n < count; ++n) {
        const GrainMove expected = moveNumber(n);
        CHECK(drained[n].grain == expected.grain);
        CHECK(drained[n].cell == expected.cell);
        CHECK(drained[n].cameFrom == expected.cameFrom);
        CHECK(drained[n].level == expected.level);
    }
}

} // namespace

TEST_CASE("a move feed hands every move over once and in order while its producer runs") {
    MoveFeed feed;
    checkInOrder(feedAndDrain(feed, 5000, 5000), 5000);
}

TEST_CASE("moves beyond a move feed's room wait in its overflow and come last, in order") {
    MoveFeed feed;
    checkInOrder(feedAndDrain(feed, 40, 1000), 1000); // 960 past the room
    // The next start forgets the overflow: only the new sweep's moves come out.
    checkInOrder(feedAndDrain(feed, 40, 7), 7);
    // A larger room is made when asked for, and nothing of before is drained again.
    checkInOrder(feedAndDrain(feed, 3000, 2500), 2500);
}

TEST_CASE("a finished move feed drains at once, and an empty one gives nothing") {
    MoveFeed feed;
    CHECK(feedAndDrain(feed, 16, 0).empty());
    feed.start(4);
    for (std::uint32_t n = 0; n < 9; ++n) feed.push(moveNumber(n));
    feed.finish();
    std::vector<GrainMove> drained;
    feed.drain(appendTo(drained), NoRecords{});
    checkInOrder(drained, 9);
}

TEST_CASE("a helper shares a move feed's record writes: each record is written once, every move listed in order") {
    constexpr std::uint32_t count = 20000;
    for (const std::size_t room : {std::size_t(count), std::size_t(5000)}) { // 15,000 past the room
        CAPTURE(room);
        MoveFeed feed;
        feed.start(room);
        std::vector<std::atomic<int>> writes(count);
        std::atomic<int> asked{0};
        const CountingRecorder record{&writes, &asked};
        // The producer finishes, then helps, as the thread whose sweep ends last does with its
        // own feed; a third thread helps once it has seen the producer finish, as that thread
        // does with the other grid's feed.
        std::atomic<bool> finished{false};
        std::thread producer([&] {
            for (std::uint32_t n = 0; n < count; ++n) {
                feed.push(moveNumber(n));
                feed.publishSome();
            }
            feed.finish();
            finished.store(true, std::memory_order_release);
            feed.help(record);
        });
        std::thread helper([&] {
            while (!finished.load(std::memory_order_acquire)) std::this_thread::yield();
            feed.help(record);
        });
        std::vector<GrainMove> drained;
        feed.drain(appendTo(drained), record);
        producer.join();
        helper.join();
        checkInOrder(drained, count);
        int wrongCounts = 0;
        for (const std::atomic<int>& n : writes) wrongCounts += n.load() == 1 ? 0 : 1;
        CHECK(wrongCounts == 0);
        // Each record written from the room (not the overflow) had its line asked for first.
        CHECK(asked.load() == int(std::min<std::size_t>(room, count)));
    }
}

TEST_CASE("a helper that comes first writes every record of the room, and the consumer lists all and writes the overflow's") {
    constexpr std::uint32_t count = 6000, room = 5000;
    MoveFeed feed;
    feed.start(room);
    for (std::uint32_t n = 0; n < count; ++n) feed.push(moveNumber(n));
    feed.finish();
    std::vector<std::atomic<int>> byHelper(count), byConsumer(count);
    std::atomic<int> asked{0};
    feed.help(CountingRecorder{&byHelper, &asked});
    std::vector<GrainMove> drained;
    feed.drain(appendTo(drained), CountingRecorder{&byConsumer, &asked});
    checkInOrder(drained, count);
    int wrong = 0;
    for (std::uint32_t n = 0; n < count; ++n)
        wrong += (n < room ? byHelper[n].load() == 1 && byConsumer[n].load() == 0
                           : byHelper[n].load() == 0 && byConsumer[n].load() == 1)
                     ? 0
                     : 1;
    CHECK(wrong == 0);
}

TEST_CASE("a helper of a feed drained already, or of an empty one, writes nothing") {
    MoveFeed feed;
    std::vector<std::atomic<int>> writes(100);
    std::atomic<int> asked{0};
    const CountingRecorder record{&writes, &asked};
    feed.start(100);
    for (std::uint32_t n = 0; n < 100; ++n) feed.push(moveNumber(n));
    feed.finish();
    std::vector<GrainMove> drained;
    feed.drain(appendTo(drained), record);
    feed.help(record);
    checkInOrder(drained, 100);
    for (const std::atomic<int>& n : writes) CHECK(n.load() == 1);
    feed.start(100);
    feed.finish();
    feed.help(record);
    drained.clear();
    feed.drain(appendTo(drained), record);
    CHECK(drained.empty());
    for (const std::atomic<int>& n : writes) CHECK(n.load() == 1);
}
