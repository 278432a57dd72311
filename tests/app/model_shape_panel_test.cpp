// SPDX-License-Identifier: MIT
// SPEC S9: the panel's "turn 90°" buttons walk the up axis through the four directions around
// the turn's axis, starting from +y when the axis is automatic.
#include "gui/model_shape_panel.hpp"

#include <doctest/doctest.h>

using namespace sandglass;

TEST_CASE("turn 90 degrees: four quarter turns bring the up axis back") {
    CHECK(upAxisAfterQuarterTurn("", 0) == "-z");
    CHECK(upAxisAfterQuarterTurn("+y", 2) == "+x");
    std::string up = "+z";
    for (int i = 0; i < 4; ++i) up = upAxisAfterQuarterTurn(up, 0);
    CHECK(up == "+z");
    CHECK(upAxisAfterQuarterTurn("+z", 0) == "+y");
    CHECK(upAxisAfterQuarterTurn("-x", 2) == "+y");
    CHECK(upAxisAfterQuarterTurn("+x", 0) == "+x"); // along the turn's own axis: unchanged
}
