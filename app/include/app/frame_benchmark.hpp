// SPDX-License-Identifier: MIT
#pragma once
// SPEC B1, thesis §4.3 "Zeitmessungen": frames per second of every render mode with light off
// and on, inner grains drawn or skipped, 1 and 20 grains per cell, simulation and GUI on,
// written as the thesis's table (benchmark.txt) and as CSV (benchmark.csv).

#include "view/render/render_settings.hpp"

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace sandglass {

/// One row's display configuration.
struct BenchmarkCase {
    RenderMode mode = RenderMode::Points; ///< render mode
    int grainsPerCell = 1;                ///< sub-grains per cell (the thesis's PpZ)
    bool lighting = false;                ///< light on
    bool innerGrains = true;              ///< inner grains drawn
    /// The lights and the studio's elements: the thesis's rows draw its look (thesisLook()).
    LightRig light = LightRig::Thesis;
    bool occlusion = false, shadows = false, toneMapping = false, environment = false;
    std::string look; ///< the look rows' name ("default", "AO off", ...); empty in the thesis's rows
};

/// The display settings of a row: the case applied to base (which keeps size, palette, hull...).
RenderSettings benchmarkRenderSettings(const BenchmarkCase& setup, RenderSettings base);

/// The look rows (docs/rendering.md): the default look, the thesis's default (unlit points), the
/// default with each studio element off in turn (occlusion, shadows, tone mapping, sky in the
/// glass, the grains' lighting) and lit by the thesis's light.
std::vector<BenchmarkCase> lookBenchmarkCases();

/// The thesis's rows for one scene: inner grains drawn, then skipped; in each, every mode
/// for (1 grain, no light), (20 grains, no light), (20 grains, light), then the remaining mixes.
std::vector<BenchmarkCase> thesisBenchmarkCases();

/// One measured row.
struct BenchmarkRow {
    BenchmarkCase setup;            ///< what was drawn
    bool simulation = true;         ///< simulation running (the thesis's Sim)
    bool gui = true;                ///< panels drawn (the thesis's Gui)
    std::int64_t filledCells = 0;   ///< grains in the scene (the thesis's gZ)
    int frames = 0;                 ///< frames timed
    double seconds = 0.0;           ///< wall time of those frames
    double uploadBytesPerFrame = 0.0; ///< V8: grain bytes sent to the GPU per frame (mean)
    double movesPerStep = 0.0;      ///< grains moved per step while timed
    /// Main-thread CPU time per frame, the steps' time and the buffer swap taken out (a driver
    /// waits for the GPU in the swap, some spinning, which is no work of the frame's).
    double cpuMillisecondsPerFrame = 0.0;
    double appCpuMillisecondsPerFrame = 0.0; ///< of which outside the draw calls (the application's own work)
    double upkeepMillisecondsPerStep = 0.0; ///< surface upkeep and grain upload per step, ms
    double gpuMillisecondsPerFrame = 0.0;   ///< GPU time of the scene's drawing per frame (timer queries)
    double medianFrameMilliseconds = 0.0;   ///< wall time of the median timed frame, the step included
    double framesPerSecond() const { return seconds > 0.0 ? double(frames) / seconds : 0.0; } ///< FPS
};

/// The rows of one scene, with what they ran on.
struct BenchmarkReport {
    std::string scene;        ///< e.g. "hourglass, resolution 38"
    std::string glRenderer;   ///< GL_RENDERER
    std::string glVersion;    ///< GL_VERSION
    int width = 0, height = 0; ///< framebuffer, pixels
    std::vector<BenchmarkRow> rows; ///< in thesisBenchmarkCases order
    bool cancelled = false;    ///< stopped by Esc before every row ran (rows holds those that finished)
};

/// How long each row runs: at least minFrames, then until maxFrames or maxSeconds.
struct BenchmarkTiming {
    int minFrames = 3;         ///< always timed, however slow
    int maxFrames = 120;       ///< stop after this many frames
    double maxSeconds = 2.0;   ///< or after this much wall time (after minFrames)
    int warmupFrames = 2;      ///< untimed frames after switching configuration
};

/// The thesis's table form, grouped by inner grains drawn / skipped; reports of look rows as one
/// table of the looks with their median frame times.
void writeBenchmarkText(std::ostream& out, const std::vector<BenchmarkReport>& reports, const std::string& command);
/// One line per row: scene,gl_renderer,gl_version,width,height,sim,gui,mode,grains_per_cell,filled_cells,light,inner,frames,seconds,fps,
/// upload_bytes_per_frame,moves_per_step,cpu_ms_per_frame,app_cpu_ms_per_frame,upkeep_ms_per_step,gpu_ms_per_frame,
/// median_frame_ms,look.
void writeBenchmarkCsv(std::ostream& out, const std::vector<BenchmarkReport>& reports);
/// Writes folder/benchmark.txt and folder/benchmark.csv (creating the folder); throws std::runtime_error.
void writeBenchmarkFiles(const std::filesystem::path& folder, const std::vector<BenchmarkReport>& reports,
                         const std::string& command);

} // namespace sandglass
