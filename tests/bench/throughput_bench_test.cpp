// SPDX-License-Identifier: MIT
// The throughput section of the bench report on a small configuration: what it measures is
// consistent (the drains agree move for move), whatever the machine's speed.
#include "bench/throughput_bench.hpp"

#include <doctest/doctest.h>

using namespace sandbench;

TEST_CASE("the memory ceiling is measured on a buffer of the size asked, rounded to a power of two") {
    const MemoryCeiling ceiling = measureMemoryCeiling(std::size_t{3} << 20, 2);
    CHECK(ceiling.bufferBytes == std::size_t{2} << 20);
    CHECK(ceiling.threads == 2);
    CHECK(ceiling.copyGigabytesPerSecond > 0.0);
    CHECK(ceiling.randomWritesPerSecond > 0.0);
    CHECK(ceiling.randomWritesPerSecondThreads > 0.0);
    const Table table = ceilingTable(ceiling);
    REQUIRE(table.rows.size() == 3);
    CHECK(table.rows[0][0].find("2 MiB") != std::string::npos);
}

TEST_CASE("moves per second on 1 and 2 threads come from drains that agree move for move") {
    const std::vector<MoveRate> runs = measureMoveRates(24, {1, 2}, [] {
        sandcore::StepSettings step;
        step.seed = 5;
        return step;
    }());
    REQUIRE(runs.size() == 2);
    CHECK(runs[0].threads == 1);
    CHECK(runs[1].threads == 2);
    CHECK(runs[0].grains > 100);
    CHECK(runs[0].moves >= runs[0].grains); // every grain left the upper bulb at least once
    CHECK(runs[0].moves == runs[1].moves);
    CHECK(runs[0].steps == runs[1].steps);
    CHECK(runs[0].hash == runs[1].hash);
    CHECK(runs[0].movesPerSecond > 0.0);
    const MemoryCeiling ceiling = measureMemoryCeiling(std::size_t{1} << 20, 2);
    const Table table = moveRateTable(runs, ceiling);
    REQUIRE(table.rows.size() == 2);
    CHECK(table.rows[0][9] == "1.00x");
    CHECK(table.rows[1][10].rfind("yes", 0) == 0);
}
