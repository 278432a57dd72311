// SPDX-License-Identifier: MIT
#pragma once
// Tests that draw need an X display and an OpenGL 3.3 context (scripts/test runs them under
// xvfb-run). Without one they say so and return instead of failing, except in CI: there a
// drawing test that returns early would pass without checking anything, so it fails instead.

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <string_view>

namespace sandglass::testing {

/// True when an X display is named.
inline bool displayAvailable() {
    const char* display = std::getenv("DISPLAY");
    return display != nullptr && *display != '\0';
}

/// True when the environment variable CI is set to anything but "", "0" or "false" (CI services
/// set CI=true).
inline bool runningInCi() {
    const char* ci = std::getenv("CI");
    if (ci == nullptr) return false;
    const std::string_view value(ci);
    return !value.empty() && value != "0" && value != "false";
}

/// A drawing test cannot draw, for `reason`: in CI the test fails with that reason; elsewhere
/// it prints it and the caller returns.
inline void cannotDraw(const std::string& reason) {
    if (runningInCi()) FAIL("CI is set, so drawing tests must draw (run them under xvfb-run), but: " << reason);
    MESSAGE(reason << " (run under xvfb-run to check it)");
}

/// True when an X display is named; otherwise reports "no X display: `what` not checked"
/// through cannotDraw (a failure in CI) and returns false, so the test returns.
inline bool requireDisplay(std::string_view what) {
    if (displayAvailable()) return true;
    cannotDraw("no X display: " + std::string(what) + " not checked");
    return false;
}

} // namespace sandglass::testing
