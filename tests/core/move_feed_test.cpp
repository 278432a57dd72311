// MoveFeed (sandcore's private hand-over of one sweep's moves to the thread that writes the
// grain records): every move arrives once and in order while the producer still runs, also the
// moves beyond the room given at start, which wait in an overflow until the sweep ends. A sweep
// never moves more grains than it has, so no scene reaches the overflow: only this test does.
#include "move_feed.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <thread>
#include <vector>

using namespace sandcore;

namespace {

GrainMove moveNumber(std::uint32_t n) {
    return {n, 1000 + n, MoveCode(n % 27), n % 2 == 0 ? GridLevel::Lower : GridLevel::Upper};
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
    feed.drain([&](const GrainMove& move) { drained.push_back(move); });
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
    feed.drain([&](const GrainMove& move) { drained.push_back(move); });
    checkInOrder(drained, 9);
}
