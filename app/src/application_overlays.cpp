// SPDX-License-Identifier: MIT
// The application's per-frame extras: the view's turn after a flip, the timer's readout, the
// banners and brush ring drawn over the scene, and the statistics the panel shows.
#include "app/application.hpp"

#include "scene/canvas_surface.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace sandglass {

namespace {

using Clock = std::chrono::steady_clock;
constexpr float kPi = 3.14159265f;
constexpr double kTurnSeconds = 0.8; // the view turns over this long after a flip

} // namespace

void Application::updateTurnAnimation() {
    if (!turnStarted_) return;
    const double t = std::chrono::duration<double>(Clock::now() - *turnStarted_).count() / kTurnSeconds;
    if (t >= 1.0) {
        turnStarted_.reset();
        camera_.setTurn(0.0f);
        return;
    }
    const double eased = t * t * (3.0 - 2.0 * t); // starts and stops gently
    camera_.setTurn(kPi * float(1.0 - eased));
}

void Application::updateTimer() {
    if (const std::optional<double> rate = timer_.update(scene())) {
        // The drain is measured: run at the rate that makes it last the duration.
        state_.stepsPerSecond = *rate;
        state_.simulationRunning = true;
        state_.statusLine = "timer running";
    }
    TimerState& timer = state_.timer;
    const HourglassTimer::Phase phase = timer_.phase();
    timer.set = phase != HourglassTimer::Phase::Off;
    timer.predicting = phase == HourglassTimer::Phase::Predicting;
    const bool finishedNow = phase == HourglassTimer::Phase::Finished && !timer.finished;
    timer.finished = phase == HourglassTimer::Phase::Finished;
    timer.elapsedSeconds = timer.set ? timer_.elapsedSeconds(scene()) : 0.0;
    timer.remainingSeconds = timer.set ? timer_.remainingSeconds(scene()) : 0.0;
    if (finishedNow) {
        state_.statusLine = "time is up";
        std::printf("\atime is up\n"); // the terminal's bell, where there is one
        std::fflush(stdout);
    }
}

void Application::drawOverlays() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    auto banner = [&](const char* id, const char* text, ImVec4 colour) {
        ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, 20.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
        ImGui::PushStyleColor(ImGuiCol_WindowBg, colour);
        ImGui::Begin(id, nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
        ImGui::TextUnformatted(text);
        ImGui::End();
        ImGui::PopStyleColor();
    };
    // A build in the background shows its own window in this place (drawBuildProgress).
    if (!host_.building() && state_.timer.finished) {
        // The end of the timer, blinking so it is seen from across the room.
        const bool on = int(ImGui::GetTime() * 2.0) % 2 == 0;
        banner("##timeup", "  Time is up  ", on ? ImVec4(0.80f, 0.25f, 0.10f, 0.95f) : ImVec4(0.45f, 0.12f, 0.05f, 0.95f));
    }
    if (host_.kind() == sandcore::SceneKind::Canvas) {
        if (state_.obstacleDrag.armed || state_.obstacleDrag.dragging)
            drawObstacleBox();
        else if (!state_.digger.active)
            drawBrushOutline();
    }
}

void Application::drawBenchmarkProgress() {
    // The frame benchmark takes a minute: which row runs, and how to stop it.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("##benchmark", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
    ImGui::Text("Frame benchmark: setting %d of %d", std::min(benchmark_.rowsDone + 1, benchmark_.rows), benchmark_.rows);
    const float done = benchmark_.rows > 0 ? float(benchmark_.rowsDone) / float(benchmark_.rows) : 0.0f;
    ImGui::ProgressBar(done, ImVec2(ImGui::GetFontSize() * 16.0f, 0.0f));
    ImGui::TextUnformatted(benchmark_.cancelRequested ? "stopping..." : "Esc cancels");
    ImGui::End();
}

void Application::drawBrushOutline() {
    // A ring on the canvas surface around the column under the cursor, as wide as the brush.
    // Hidden windows (render, tests) have no cursor to follow.
    if (!options_.window.visible || ImGui::GetIO().WantCaptureMouse || host_.building()) return;
    const std::optional<CanvasColumn> column = columnUnderCursor(lastCursorX_, lastCursorY_);
    if (!column) return;
    const CanvasView view = canvasView();
    const CanvasSurface surface =
        canvasSurface(scene(), state_.painting.pickAtTarget ? PaintTarget::Bottom : PaintTarget::Top, view.cellSize);
    const float radius = (float(std::max(0, state_.painting.brushRadius)) + 0.5f) * surface.cellSize;
    const float centreX = surface.originX + (float(column->x) + 0.5f) * surface.cellSize;
    const float centreZ = surface.originZ + (float(column->z) + 0.5f) * surface.cellSize;
    const glm::mat4 toClip = view.projection * view.view;
    const float toWindowX = view.framebufferWidth > 0 ? float(view.windowWidth) / float(view.framebufferWidth) : 1.0f;
    const float toWindowY = view.framebufferHeight > 0 ? float(view.windowHeight) / float(view.framebufferHeight) : 1.0f;
    ImVec2 points[48];
    int count = 0;
    for (int i = 0; i < 48; ++i) {
        const float angle = 2.0f * kPi * float(i) / 48.0f;
        const glm::vec4 clip = toClip * glm::vec4(centreX + radius * std::cos(angle), surface.y,
                                                  centreZ + radius * std::sin(angle), 1.0f);
        if (clip.w <= 0.0f) return;
        // ImGui draws in window units; the framebuffer may have more pixels (HiDPI).
        points[count++] = ImVec2((clip.x / clip.w * 0.5f + 0.5f) * float(view.framebufferWidth) * toWindowX,
                                 (0.5f - clip.y / clip.w * 0.5f) * float(view.framebufferHeight) * toWindowY);
    }
    const ImU32 colour = state_.painting.erase ? IM_COL32(220, 60, 40, 230) : IM_COL32(40, 40, 40, 230);
    ImGui::GetForegroundDrawList()->AddPolyline(points, count, colour, ImDrawFlags_Closed, 2.0f);
}

void Application::updateStatistics(double elapsedSeconds) {
    FrameStatistics& stats = state_.stats;
    const float milliseconds = float(elapsedSeconds * 1000.0);
    stats.frameMilliseconds[std::size_t(stats.historyNext)] = milliseconds;
    stats.historyNext = (stats.historyNext + 1) % FrameStatistics::kHistory;
    if (milliseconds > 0.0f) {
        stats.millisecondsPerFrame =
            stats.millisecondsPerFrame == 0.0f ? milliseconds : 0.9f * stats.millisecondsPerFrame + 0.1f * milliseconds;
        stats.framesPerSecond = 1000.0f / stats.millisecondsPerFrame;
    }
    stats.stepsPerSecond = float(host_.stepsPerSecond());
    stats.millisecondsPerStep = float(host_.millisecondsPerStep());
    stats.rateCapped = host_.rateCapped();
    stats.maxStepsPerFrame = SceneHost::kMaxStepsPerFrame;
    const sandcore::SceneCounters& counters = scene().counters();
    stats.grains = scene().grainCount();
    stats.grainsUpper = counters.grainsUpper;
    stats.grainsLower = counters.grainsLower;
    stats.movingGrains = counters.movesLastStep;
    stats.stepsDone = counters.stepsDone;
    stats.innerGrains = renderer_.stats().innerGrains;
    stats.subGrainsDrawn = renderer_.stats().subGrainsDrawn;
}

} // namespace sandglass
