// SPDX-License-Identifier: MIT
#pragma once
// R6: a step's result never depends on the thread count. Shared by the classic and granular tests.

#include "sandcore/scene.hpp"

#include <doctest/doctest.h>

#include <functional>
#include <initializer_list>

namespace fixtures {

/// Runs each scene on 1, 2 and 4 threads, sleeping grains skipped and not, and requires the same
/// state hash after every one of `steps` steps.
inline void requireThreadCountsAgree(std::initializer_list<std::function<sandcore::Scene()>> makers, int steps) {
    for (const auto& make : makers)
        for (bool sleeping : {true, false}) {
            CAPTURE(sleeping);
            sandcore::Scene one = make(), two = make(), four = make();
            for (sandcore::Scene* s : {&one, &two, &four}) s->setSleeping(sleeping);
            two.setThreads(2);
            four.setThreads(4);
            for (int i = 0; i < steps; ++i) {
                one.step();
                two.step();
                four.step();
                REQUIRE(one.stateHash() == two.stateHash());
                REQUIRE(one.stateHash() == four.stateHash());
            }
        }
}

} // namespace fixtures
