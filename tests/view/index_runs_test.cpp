// SPDX-License-Identifier: MIT
// IndexRuns (V8's uploads): marked entries come back as ascending runs, joined across gaps of at
// most maxGap, each mark once, every mark cleared; what the GPU store sends after a step.
#include "view/render/index_runs.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

using sandglass::IndexRuns;

namespace {

std::vector<std::pair<std::uint32_t, std::uint32_t>> takeAll(IndexRuns& runs, std::uint32_t maxGap) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    runs.take(maxGap, [&](std::uint32_t first, std::uint32_t end) { out.emplace_back(first, end); });
    return out;
}

} // namespace

TEST_CASE("index runs: runs of marks across word edges, ascending, cleared after taking") {
    IndexRuns runs;
    runs.resize(300);
    CHECK(runs.empty());
    for (std::uint32_t i : {5u, 6u, 7u, 60u, 61u, 62u, 63u, 64u, 65u, 130u, 299u, 6u}) runs.mark(i);
    CHECK(!runs.empty());
    using Runs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
    CHECK(takeAll(runs, 0) == Runs{{5, 8}, {60, 66}, {130, 131}, {299, 300}});
    CHECK(runs.empty());
    CHECK(takeAll(runs, 0).empty());
    for (std::uint32_t i = 0; i < 128; ++i) runs.mark(i); // two full words
    runs.mark(131);
    CHECK(takeAll(runs, 2) == Runs{{0, 128}, {131, 132}}); // 3 unmarked entries apart
    for (std::uint32_t i = 0; i < 128; ++i) runs.mark(i);
    runs.mark(130);
    CHECK(takeAll(runs, 2) == Runs{{0, 131}}); // 2 apart: joined
    runs.mark(0);
    runs.mark(131);
    CHECK(takeAll(runs, 2) == Runs{{0, 1}, {131, 132}});
    runs.mark(0);
    runs.mark(131);
    CHECK(takeAll(runs, 130) == Runs{{0, 132}});
}

TEST_CASE("index runs: random marks come back each once, gaps joined only up to maxGap") {
    std::mt19937 random(7);
    for (std::uint32_t maxGap : {0u, 1u, 4u, 16u}) {
        CAPTURE(maxGap);
        IndexRuns runs;
        runs.resize(5000);
        std::set<std::uint32_t> marked;
        for (int i = 0; i < 700; ++i) {
            const std::uint32_t index = random() % 5000;
            runs.mark(index);
            marked.insert(index);
        }
        const auto taken = takeAll(runs, maxGap);
        std::set<std::uint32_t> covered;
        for (std::size_t r = 0; r < taken.size(); ++r) {
            REQUIRE(taken[r].first < taken[r].second);
            REQUIRE(marked.count(taken[r].first) == 1);      // a run starts and ends on a mark
            REQUIRE(marked.count(taken[r].second - 1) == 1);
            if (r > 0) REQUIRE(taken[r].first > taken[r - 1].second + maxGap); // else joined
            for (std::uint32_t i = taken[r].first; i < taken[r].second; ++i) covered.insert(i);
        }
        for (std::uint32_t index : marked) REQUIRE(covered.count(index) == 1);
        if (maxGap == 0) CHECK(covered == marked);
        CHECK(runs.empty());
    }
}
