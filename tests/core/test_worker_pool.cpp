#include "sandcore/worker_pool.hpp"

#include <doctest/doctest.h>

#include <atomic>
#include <vector>

TEST_CASE("parallelFor runs every task exactly once, many times in a row") {
    for (int threads : {1, 2, 4}) {
        sandcore::WorkerPool pool(threads);
        CHECK(pool.threadCount() == threads);
        for (int round = 0; round < 500; ++round) {
            std::vector<std::atomic<int>> hits(37);
            pool.parallelFor(37, [&](int i) { hits[std::size_t(i)].fetch_add(1); });
            for (auto& h : hits) REQUIRE(h.load() == 1);
        }
    }
}
