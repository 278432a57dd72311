#pragma once
// Tests that draw need an X display (scripts/test runs them under xvfb-run). Without one they
// say so and return instead of failing.

#include <cstdlib>

namespace sandglass::testing {

/// True when an X display is named; GL tests call it first and return when it is false.
inline bool displayAvailable() {
    const char* display = std::getenv("DISPLAY");
    return display != nullptr && *display != '\0';
}

} // namespace sandglass::testing
