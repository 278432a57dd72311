// SPDX-License-Identifier: MIT
#pragma once
// The frame-rate benchmark (thesis §4.3) inside the window: the same frames the user sees
// (simulation and panels on), timed per display configuration. It builds its own copy of the
// running scene and drives that host, so the user's scene, drawing and settings are never touched.

#include "app/application.hpp"
#include "app/frame_benchmark.hpp"

#include <functional>
#include <vector>

namespace sandglass {

/// Runs each case on a fresh scene built from the settings of the application's running scene,
/// for the frames `timing` asks; returns the rows with the GPU named. Used by the B key and by
/// `sandglass bench --render`. Esc in the window stops it (BenchmarkReport::cancelled);
/// `afterEachFrame` runs after every frame (tests press keys there). Throws what building the
/// scene throws.
BenchmarkReport runFrameBenchmark(Application& app, const std::vector<BenchmarkCase>& cases,
                                  const BenchmarkTiming& timing, const std::function<void()>& afterEachFrame = {});

} // namespace sandglass
