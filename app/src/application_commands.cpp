// SPDX-License-Identifier: MIT
// The commands the panels and keys queue, served once per frame: builds, reset, turning over,
// the timer, undo, obstacles, quitting; and the frame benchmark the B key starts.
#include "app/application.hpp"

#include "app/frame_benchmark_runner.hpp"
#include "app/user_settings.hpp"

#include "scene/data_paths.hpp"
#include "scene/scene_export.hpp"

#include <chrono>
#include <cstdio>
#include <system_error>
#include <utility>

namespace sandglass {

namespace {

using Clock = std::chrono::steady_clock;

} // namespace

void Application::serveCommands() {
    if (const auto outcome = host_.pollBuild()) adoptBuild(*outcome);
    if (const std::optional<ChosenFile> chosen = fileChooser_.poll()) serveChosenFile(*chosen);
    // Screenshots and the benchmark wait for the frame; run() takes them.
    std::vector<Command> later;
    for (Command command : state_.commands.take()) {
        if (command == Command::Screenshot || command == Command::Benchmark)
            later.push_back(command);
        else
            serve(command);
    }
    for (Command command : later) state_.commands.push(command);
    state_.building = host_.building();
    if (const BuildProgress* progress = host_.buildProgress())
        state_.build = {buildPhaseName(progress->phase()), progress->shareDone(), host_.buildSeconds(),
                        progress->cancelRequested()};
    else
        state_.build = {};
    canvas_.publishUndoState(state_.painting);
}

void Application::serve(Command command) {
    switch (command) {
    case Command::Rebuild:
        try {
            SceneSettings settings = state_.scene;
            // The panel keeps the last model chosen when the user switches to the canvas; it has none.
            if (settings.request.kind == sandcore::SceneKind::Canvas) {
                settings.request.modelPath.clear();
                settings.request.shape.clear();
            }
            applySceneDefaults(settings);
            state_.statusLine.clear();
            host_.requestBuild(settings);
        } catch (const std::exception& error) {
            state_.statusLine = error.what();
            state_.scene = state_.loaded;
        }
        break;
    case Command::ApplyStepSettings: host_.applyStepSettings(state_.scene.step); break;
    case Command::Reset:
        host_.reset();
        canvas_.sceneReplaced();
        timer_.stop();
        state_.statusLine = "reset";
        break;
    case Command::Flip:
        if (!host_.flip()) {
            state_.statusLine = "only an hourglass turns over";
            break;
        }
        // The sand is already mirrored; the view starts upside down and turns back upright.
        turnStarted_ = Clock::now();
        updateTurnAnimation();
        timer_.sceneTurned(scene());
        state_.statusLine = "turned over";
        break;
    case Command::StartTimer:
        try {
            timer_.start(scene(), 60.0 * state_.timer.minutes + state_.timer.seconds);
            state_.statusLine = "timer set: measuring the drain...";
        } catch (const std::exception& error) {
            state_.statusLine = error.what();
        }
        break;
    case Command::StopTimer: timer_.stop(); break;
    case Command::SingleStep: host_.requestSingleStep(); break;
    case Command::CancelBuild:
        if (!host_.building()) break;
        host_.cancelBuild();
        state_.build.cancelling = true;
        state_.statusLine = "cancelling the build...";
        break;
    case Command::FrameCamera: frameCamera(); break;
    case Command::Undo:
    case Command::Redo: {
        const bool undo = command == Command::Undo;
        const bool changed = undo ? canvas_.undo(host_) : canvas_.redo(host_);
        if (changed) ++state_.files.unsavedEdits;
        state_.statusLine = changed ? (undo ? "undone" : "redone") : (undo ? "nothing to undo" : "nothing to redo");
        break;
    }
    case Command::SaveState: saveStateFile(); break;
    case Command::LoadState: loadStateFile(state_.files.statePath); break;
    case Command::Export:
        try {
            exportScene(state_.files.exportPath, host_.scene(),
                        {{state_.render.cellSize, state_.render.jitter}, host_.modelToWorld()});
            state_.statusLine = "exported to " + state_.files.exportPath;
        } catch (const std::exception& error) {
            state_.statusLine = error.what();
        }
        break;
    case Command::LoadDraft: loadDraft(state_.painting.draftPath); break;
    case Command::LoadDiggerBody: loadDiggerBody(state_.digger.modelPath); break;
    case Command::OpenFile: openFile(state_.files.openPath); break;
    case Command::AddObstacle: {
        const std::uint64_t layout = host_.layoutRevision();
        state_.statusLine = canvas_.addObstacle(host_, state_.painting.obstacleMin, state_.painting.obstacleMax);
        if (host_.layoutRevision() != layout) ++state_.files.unsavedEdits;
        break;
    }
    case Command::ClearObstacles:
        canvas_.clearObstacles(host_);
        if (host_.kind() == sandcore::SceneKind::Canvas) ++state_.files.unsavedEdits;
        state_.statusLine = "obstacles removed";
        break;
    case Command::Quit: askToQuit(); break;
    case Command::QuitNow: quitRequested_ = true; break;
    case Command::SaveAndQuit:
        if (saveStateFile()) quitRequested_ = true;
        else state_.files.confirmQuit = false; // the status line says why; the work stays open
        break;
    case Command::ChooseFile: chooseFile(); break;
    case Command::Screenshot:
    case Command::Benchmark: break; // served by run() after the frame
    }
}

void Application::adoptBuild(const BuildOutcome& outcome) {
    state_.statusLine = outcome.message;
    const std::string draft = std::exchange(draftAfterBuild_, {});
    if (!outcome.adopted) {
        // The running scene stays, and the panel shows it again rather than the choice that failed.
        state_.scene = state_.loaded;
        return;
    }
    rememberModel(host_.loaded().request.modelPath);
    state_.loaded = host_.loaded();
    state_.files.unsavedEdits = 0; // the edits went with the scene they were made in
    canvas_.sceneReplaced();
    timer_.stop();
    turnStarted_.reset();
    camera_.setTurn(0.0f);
    frameCamera();
    if (!draft.empty() && host_.kind() == sandcore::SceneKind::Canvas) loadDraft(draft);
}

void Application::rememberModel(const std::string& path) {
    // The bundled models have their own list in the Scene tab; recent files are the user's.
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::weakly_canonical(modelsFolder(), error);
    if (path.empty() || (!error && std::filesystem::weakly_canonical(path, error).parent_path() == folder)) return;
    addRecentFile(state_.files.recentFiles, path);
}

void Application::askToQuit() {
    // U5: edits not yet saved are not thrown away without a question; Esc again cancels it.
    if (state_.files.unsavedEdits == 0) {
        quitRequested_ = true;
        return;
    }
    state_.files.confirmQuit = !state_.files.confirmQuit;
}

void Application::runInteractiveBenchmark() {
    state_.statusLine = "benchmark running...";
    try {
        const BenchmarkReport report = runFrameBenchmark(*this, thesisBenchmarkCases(), BenchmarkTiming{});
        if (report.cancelled) {
            state_.statusLine = "benchmark cancelled";
            std::printf("%s\n", state_.statusLine.c_str());
            std::fflush(stdout);
            return;
        }
        writeBenchmarkFiles(options_.benchmarkFolder, {report}, "key B in the window");
        state_.statusLine = "benchmark written to " + (options_.benchmarkFolder / "benchmark.txt").string();
        std::printf("%s\n", state_.statusLine.c_str());
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        std::fprintf(stderr, "sandglass: %s\n", error.what());
    }
}

} // namespace sandglass
