// SPDX-License-Identifier: MIT
#include "worker_pool.hpp"

#include <doctest/doctest.h>

#include <atomic>
#include <stdexcept>
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

TEST_CASE("an exception in a task reaches the caller after every task has finished") {
    for (int threads : {1, 2, 4}) {
        sandcore::WorkerPool pool(threads);
        std::atomic<int> ran{0};
        CHECK_THROWS_AS(pool.parallelFor(64,
                                         [&](int i) {
                                             ran.fetch_add(1);
                                             if (i == 5) throw std::runtime_error("task 5 failed");
                                         }),
                        std::runtime_error);
        CHECK(ran.load() == 64);
        // The pool still works afterwards.
        std::atomic<int> again{0};
        pool.parallelFor(10, [&](int) { again.fetch_add(1); });
        CHECK(again.load() == 10);
    }
}
