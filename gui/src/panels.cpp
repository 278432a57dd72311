// SPDX-License-Identifier: MIT
#include "gui/panels.hpp"

#include "sandcore/scene_geometry.hpp"

#include "gui/model_shape_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

namespace sandglass {

namespace {

// The panel's tabs; each fits a 1280x800 window with all of its parts open.
struct PanelTab {
    const char* label;
    const char* name; // as AppState::openTab names it (gui --panel)
};
constexpr PanelTab kRunTab{"Run", "run"}, kViewTab{"View", "view"}, kSceneTab{"Scene", "scene"},
    kPaintTab{"Paint", "paint"}, kFileTab{"File", "file"};

ImGuiTabItemFlags tabFlags(AppState& state, const PanelTab& tab) {
    // A tab asked for (command line, or the canvas just loaded) is selected once.
    if (state.openTab != tab.name) return 0;
    state.openTab.clear();
    return ImGuiTabItemFlags_SetSelected;
}

} // namespace

void hint(const char* text) {
    // A hint in the lighter grey, wrapped so the narrow panel shows all of it.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
}

int openWhereRoomy() {
    // The folded parts start open where a tab has room for them (1280x800 at 100% text), and
    // folded on small windows.
    return ImGui::GetIO().DisplaySize.y >= 50.0f * ImGui::GetFontSize() ? ImGuiTreeNodeFlags_DefaultOpen : 0;
}

float panelWidth(float displayWidth, float fontSize) {
    // 25 text heights where there is room; down to 18 on small windows so the scene keeps most
    // of the width; never wider than the window.
    const float preferred = std::clamp(0.36f * displayWidth, 18.0f * fontSize, 25.0f * fontSize);
    return std::max(1.0f, std::min(preferred, displayWidth));
}

WindowPlacement placeOnScreen(const WindowPlacement& chosen, float width, float height, float displayWidth,
                              float displayHeight) {
    // The position the user chose, kept as chosen; shown clamped so the title bar stays on screen
    // however small the window became, and back in place when it grows again.
    return {std::clamp(chosen.x, 0.0f, std::max(0.0f, displayWidth - width)),
            std::clamp(chosen.y, 0.0f, std::max(0.0f, displayHeight - height))};
}

namespace {

void rememberPlacement(WindowPlacement& placement, ImVec2 shownAt) {
    // Moved by the user (dragged): that is the new place; otherwise the clamp shows it and the
    // chosen place stays.
    const ImVec2 now = ImGui::GetWindowPos();
    if (std::abs(now.x - shownAt.x) > 0.5f || std::abs(now.y - shownAt.y) > 0.5f) {
        placement.x = now.x;
        placement.y = now.y;
    }
}

} // namespace

void drawPanels(AppState& state) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float em = ImGui::GetFontSize();
    const float margin = std::round(0.6f * em);
    if (state.panelPlacement.x < 0.0f) state.panelPlacement = {margin, margin};
    const float width = panelWidth(display.x - 2.0f * margin, em);
    // The height follows the content, never more than the window: a scrollbar only when the
    // window is smaller than any layout can fit.
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, std::max(em * 4.0f, display.y - 2.0f * margin)));
    const WindowPlacement place = placeOnScreen(state.panelPlacement, state.panelSize.x > 0.0f ? state.panelSize.x : width,
                                                state.panelSize.y, display.x, display.y);
    const ImVec2 shownAt(place.x, place.y);
    ImGui::SetNextWindowPos(shownAt, ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.9f);
    const bool open = ImGui::Begin("sandglass", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    rememberPlacement(state.panelPlacement, shownAt);
    state.panelSize = {ImGui::GetWindowSize().x, ImGui::GetWindowSize().y};
    // The application centres the scene in the rest of the window.
    state.panelCoverage = open && display.x > 0.0f
                              ? std::clamp((ImGui::GetWindowPos().x + ImGui::GetWindowSize().x) / display.x, 0.0f, 0.6f)
                              : 0.0f;
    if (open) {
        // Labels sit right of their controls; leave them room in the narrow layout.
        ImGui::PushItemWidth(-std::min(9.0f * em, 0.42f * width));
        if (ImGui::Button("Help (F1)")) state.showHelp = !state.showHelp;
        ImGui::SameLine();
        ImGui::TextWrapped("%s", sceneSummary(state.loaded.request).c_str());
        const bool canvas = state.loaded.request.kind == sandcore::SceneKind::Canvas;
        // The canvas opens on its painting tools once per load.
        ImGuiStorage& storage = *ImGui::GetStateStorage();
        const ImGuiID shownKind = ImGui::GetID("##shown scene kind");
        if (storage.GetInt(shownKind, -1) != int(state.loaded.request.kind)) {
            storage.SetInt(shownKind, int(state.loaded.request.kind));
            if (canvas && state.openTab.empty()) state.openTab = kPaintTab.name;
        }
        if (ImGui::BeginTabBar("sections")) {
            if (ImGui::BeginTabItem(kRunTab.label, nullptr, tabFlags(state, kRunTab))) {
                drawControlSection(state);
                ImGui::Separator();
                drawStatisticsSection(state);
                ImGui::EndTabItem();
            }
            if (canvas && ImGui::BeginTabItem(kPaintTab.label, nullptr, tabFlags(state, kPaintTab))) {
                drawPaintingSection(state);
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem(kViewTab.label, nullptr, tabFlags(state, kViewTab))) {
                drawDisplaySection(state);
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem(kSceneTab.label, nullptr, tabFlags(state, kSceneTab))) {
                drawSceneSection(state);
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem(kFileTab.label, nullptr, tabFlags(state, kFileTab))) {
                drawFileSection(state);
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
        if (!state.statusLine.empty()) {
            ImGui::Separator();
            ImGui::TextWrapped("%s", state.statusLine.c_str());
        }
        ImGui::PopItemWidth();
    }
    ImGui::End();
}

std::string sceneSummary(const SceneRequest& loaded) {
    if (loaded.kind == sandcore::SceneKind::Canvas)
        return "canvas, resolution " + std::to_string(loaded.resolution);
    const std::string source = !loaded.modelPath.empty() ? std::filesystem::path(loaded.modelPath).filename().string()
                               : !loaded.shape.empty()   ? loaded.shape + " (built-in shape)"
                                                         : "built-in shape";
    return std::string(sceneKindName(loaded.kind)) + ": " + source + ", resolution " + std::to_string(loaded.resolution);
}

void drawTimer(AppState& state) {
    // The hourglass as a timer: minutes:seconds, then the drain is measured and the flow set.
    TimerState& timer = state.timer;
    if (!timer.set) {
        ImGui::PushItemWidth(ImGui::GetFontSize() * 2.5f);
        ImGui::InputInt("##minutes", &timer.minutes, 0);
        ImGui::SameLine(0.0f, 2.0f);
        ImGui::TextUnformatted(":");
        ImGui::SameLine(0.0f, 2.0f);
        ImGui::InputInt("##seconds", &timer.seconds, 0);
        ImGui::PopItemWidth();
        timer.minutes = std::clamp(timer.minutes, 0, 999);
        timer.seconds = std::clamp(timer.seconds, 0, 59);
        ImGui::SameLine();
        ImGui::BeginDisabled(timer.minutes == 0 && timer.seconds == 0);
        if (ImGui::Button("Start timer")) state.commands.push(Command::StartTimer);
        ImGui::EndDisabled();
        return;
    }
    if (ImGui::Button("Stop timer")) state.commands.push(Command::StopTimer);
    auto clock = [](double seconds) {
        const int whole = int(std::ceil(std::max(0.0, seconds)));
        char text[16];
        std::snprintf(text, sizeof text, "%d:%02d", whole / 60, whole % 60);
        return std::string(text);
    };
    if (timer.predicting)
        ImGui::TextUnformatted("measuring the drain...");
    else if (timer.finished)
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.2f, 1.0f), "time is up (%s)", clock(timer.elapsedSeconds).c_str());
    else
        ImGui::Text("elapsed %s   remaining %s", clock(timer.elapsedSeconds).c_str(), clock(timer.remainingSeconds).c_str());
}

void drawControlSection(AppState& state) {
    // Thesis: a green/red button; here a coloured toggle with the same meaning.
    const bool running = state.simulationRunning;
    ImGui::PushStyleColor(ImGuiCol_Button, running ? ImVec4(0.20f, 0.60f, 0.25f, 1.0f) : ImVec4(0.65f, 0.20f, 0.20f, 1.0f));
    if (ImGui::Button(running ? "Simulation: on " : "Simulation: off")) state.simulationRunning = !running;
    ImGui::PopStyleColor();
    ImGui::SameLine();
    if (ImGui::Button("Step")) state.commands.push(Command::SingleStep);
    ImGui::SameLine();
    if (ImGui::Button("Reset")) state.commands.push(Command::Reset);
    ImGui::SameLine();
    if (ImGui::Button("Exit")) state.commands.push(Command::Quit);
    float speed = float(state.stepsPerSecond);
    if (ImGui::SliderFloat("flow (steps/s)", &speed, 1.0f, 240.0f, "%.0f", ImGuiSliderFlags_Logarithmic))
        state.stepsPerSecond = speed;
    if (state.stats.rateCapped)
        ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "frames too slow: capped at %d steps per frame",
                           state.stats.maxStepsPerFrame);
    if (state.loaded.request.kind == sandcore::SceneKind::Hourglass) {
        if (ImGui::Button("Turn over (T)")) state.commands.push(Command::Flip);
        // The timer on a line of its own, so it fits the narrow panel too.
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted("timer");
        ImGui::SameLine();
        drawTimer(state);
    }
    if (ImGui::Button("Screenshot (P)")) state.commands.push(Command::Screenshot);
    ImGui::SameLine();
    if (ImGui::Button("Benchmark (B)")) state.commands.push(Command::Benchmark);
}

void drawDisplaySection(AppState& state) {
    RenderSettings& render = state.render;
    // Thesis "+"/"-": more or fewer grains drawn per cell.
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("grains per cell");
    ImGui::SameLine();
    if (ImGui::Button(" - ") && render.grainsPerCell > 1) --render.grainsPerCell;
    ImGui::SameLine();
    ImGui::Text("%2d", render.grainsPerCell);
    ImGui::SameLine();
    if (ImGui::Button(" + ") && render.grainsPerCell < kMaxGrainsPerCell) ++render.grainsPerCell;

    int mode = int(render.mode);
    const char* labels[] = {renderModeLabel(kRenderModes[0]), renderModeLabel(kRenderModes[1]),
                            renderModeLabel(kRenderModes[2]), renderModeLabel(kRenderModes[3])};
    if (ImGui::Combo("mode", &mode, labels, 4)) render.mode = kRenderModes[mode];
    int background = render.blackBackground ? 1 : 0;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("background");
    ImGui::SameLine();
    ImGui::RadioButton("white", &background, 0);
    ImGui::SameLine();
    ImGui::RadioButton("black", &background, 1);
    render.blackBackground = background == 1;
    ImGui::Checkbox("lighting", &render.lighting);
    ImGui::SameLine();
    ImGui::Checkbox("inner grains", &render.innerGrains);
    ImGui::SameLine();
    ImGui::Checkbox("glass", &render.hull);
    ImGui::SameLine();
    ImGui::Checkbox("voxel hull", &render.voxelHull); // S10: the model's cells, not its triangles
    // The studio look (docs/rendering.md): each element can be switched off to compare.
    int rig = int(render.light);
    const char* rigs[] = {"studio (warm key, cool fill)", "thesis (light at the camera)"};
    if (ImGui::Combo("lights", &rig, rigs, 2)) render.light = LightRig(rig);
    if (render.light == LightRig::Studio) {
        ImGui::Checkbox("occlusion", &render.ambientOcclusion);
        ImGui::SameLine();
        ImGui::Checkbox("shadows", &render.shadows);
        ImGui::Checkbox("tone mapping", &render.toneMapping);
        ImGui::SameLine();
        ImGui::Checkbox("sky in glass", &render.glassEnvironment);
    }
    if (render.lighting) {
        int method = int(render.normals);
        const char* methods[] = {"column heights (thesis)", "occupancy gradient"};
        if (ImGui::Combo("normals", &method, methods, 2)) render.normals = sandcore::NormalMethod(method);
    }
    if (render.mode == RenderMode::Points || render.mode == RenderMode::Sprites)
        ImGui::SliderFloat("point size (px)", &render.pointSize, 1.0f, 16.0f, "%.1f");
    else
        ImGui::SliderFloat("grain size (cells)", &render.quadSize, 0.2f, 2.0f, "%.2f");
    ImGui::SliderFloat("jitter", &render.jitter, 0.0f, 1.0f, "%.2f");
    drawPaletteChoice(state);

    // SPEC U2: larger text and controls, on top of the monitor's own scale.
    constexpr float sizes[] = {0.85f, 1.0f, 1.15f, 1.3f, 1.5f, 2.0f};
    char current[16];
    std::snprintf(current, sizeof current, "%.0f%%", double(state.uiScale) * 100.0);
    if (ImGui::BeginCombo("text size", current)) {
        for (float size : sizes) {
            char label[16];
            std::snprintf(label, sizeof label, "%.0f%%", double(size) * 100.0);
            if (ImGui::Selectable(label, std::abs(size - state.uiScale) < 0.01f)) state.uiScale = size;
        }
        ImGui::EndCombo();
    }
}

void drawSceneSection(AppState& state) {
    SceneSettings& scene = state.scene;
    // What runs now, whatever the controls below are set to.
    const SceneRequest& loaded = state.loaded.request;
    if (state.building)
        ImGui::TextWrapped("building: %s... (%s runs until it is done or cancelled)", state.build.phase.c_str(),
                           sceneSummary(loaded).c_str());
    int kind = int(scene.request.kind);
    const char* kinds[] = {"hourglass", "sculpture", "canvas"};
    if (ImGui::Combo("scene", &kind, kinds, 3)) {
        scene.request.kind = sandcore::SceneKind(kind);
        scene.request.shape.clear(); // each scene has its own default model
        scene.request.modelPath = defaultModelFor(scene.request.kind);
        state.commands.push(Command::Rebuild);
    }
    if (scene.request.kind != sandcore::SceneKind::Canvas) {
        const char* shapes[] = {"hourglass", "sphere", "cube"};
        const bool hourglass = scene.request.kind == sandcore::SceneKind::Hourglass;
        const std::string current =
            !scene.request.shape.empty() ? scene.request.shape : hourglass ? "hourglass" : "sphere";
        // A model file and a procedural shape exclude each other; the combo says which is chosen.
        const std::string shown = scene.request.modelPath.empty() ? current : "(a model file, below)";
        if (ImGui::BeginCombo("built-in shape", shown.c_str())) {
            for (const char* shape : shapes)
                if (ImGui::Selectable(shape, scene.request.modelPath.empty() && current == shape)) {
                    scene.request.shape = shape;
                    scene.request.modelPath.clear();
                    state.commands.push(Command::Rebuild);
                }
            ImGui::EndCombo();
        }
        if (ImGui::BeginListBox("models/", ImVec2(0.0f, ImGui::GetTextLineHeightWithSpacing() * 4.0f))) {
            for (const std::string& file : state.modelFiles) {
                const bool isLoaded = loaded.kind == scene.request.kind && loaded.modelPath == file;
                if (ImGui::Selectable(std::filesystem::path(file).filename().string().c_str(), isLoaded)) {
                    scene.request.modelPath = file;
                    state.commands.push(Command::Rebuild);
                }
                if (isLoaded && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY(); // the loaded model in view
            }
            if (state.modelFiles.empty()) ImGui::TextDisabled("(no model files)");
            ImGui::EndListBox();
        }
        char path[512] = {};
        scene.request.modelPath.copy(path, sizeof path - 1);
        if (ImGui::InputText("model path", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue)) {
            scene.request.modelPath = path;
            state.commands.push(Command::Rebuild);
        }
        if (ImGui::Button("Open model...")) {
            state.files.choosing = FileChoice::Model;
            state.commands.push(Command::ChooseFile);
        }
        ImGui::SameLine();
        hint("Enter loads a typed path; or drop a model file on the window");
        drawModelOptions(state);
    }
    // The slider spans the useful resolutions; the command line takes the whole range.
    ImGui::SliderInt("resolution", &scene.request.resolution, kResolutionRange.min, 512);
    if (ImGui::IsItemDeactivatedAfterEdit()) state.commands.push(Command::Rebuild);
    // Seed and threads apply to the next step; the scene is not rebuilt.
    if (ImGui::InputScalar("seed", ImGuiDataType_U64, &scene.step.seed)) state.commands.push(Command::ApplyStepSettings);
    if (ImGui::SliderInt("threads", &scene.step.threads, kThreadsRange.min, 16))
        state.commands.push(Command::ApplyStepSettings);
    // PH1: the rules, from the next step on; the scene is not rebuilt.
    sandcore::PhysicsSettings& physics = scene.step.physics;
    int level = int(physics.level);
    if (ImGui::Combo("physics", &level, "classic\0granular\0")) {
        physics.level = sandcore::PhysicsLevel(level);
        state.commands.push(Command::ApplyStepSettings);
    }
    ImGui::BeginDisabled(physics.level != sandcore::PhysicsLevel::Granular);
    ImGui::SliderFloat("repose angle", &physics.reposeDegrees, float(kReposeRange.min), float(kReposeRange.max), "%.0f deg");
    if (ImGui::IsItemDeactivatedAfterEdit()) state.commands.push(Command::ApplyStepSettings);
    ImGui::SliderFloat("gravity", &physics.gravity, 0.005f, 4.0f, "%.3f cells/step^2", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemDeactivatedAfterEdit()) state.commands.push(Command::ApplyStepSettings);
    ImGui::EndDisabled();
    if (ImGui::Button("Rebuild scene")) state.commands.push(Command::Rebuild);
    ImGui::SameLine();
    if (ImGui::Button("Frame camera")) state.commands.push(Command::FrameCamera);
}

void drawModelOptions(AppState& state) {
    // S2, S3, S5: how a model file becomes cells; every change builds the scene again.
    if (!ImGui::TreeNodeEx("model options", openWhereRoomy())) return;
    SceneRequest& request = state.scene.request;
    ImGui::BeginDisabled(request.modelPath.empty()); // procedural shapes are solid already
    if (ImGui::Checkbox("robust inside test (open meshes)", &request.robust)) state.commands.push(Command::Rebuild);
    if (ImGui::Checkbox("stretch to resolution", &request.stretch)) state.commands.push(Command::Rebuild);
    // The thesis's noNoise: inside cells with at most this many inside face neighbours go, repeatedly.
    ImGui::SliderInt("remove stray cells", &request.noiseThreshold, -1, 3, request.noiseThreshold < 0 ? "off" : "with <= %d neighbours");
    // Rebuild when the slider is let go, not on every value dragged past.
    if (ImGui::IsItemDeactivatedAfterEdit()) state.commands.push(Command::Rebuild);
    ImGui::EndDisabled();
    ImGui::BeginDisabled(request.kind != sandcore::SceneKind::Hourglass);
    if (ImGui::Checkbox("carve the upper bulb to drain", &request.drainCompletely)) state.commands.push(Command::Rebuild);
    ImGui::EndDisabled();
    drawModelShapeOptions(state);
    ImGui::TreePop();
}

void drawPaintingSection(AppState& state) {
    PaintingSettings& painting = state.painting;
    // What the left button does, in one line, so a first stroke is no guess.
    ImGui::TextWrapped(painting.erase ? "Left button: erase the top grain under the ring; Alt + drag: camera."
                                      : "Left button: pour sand where the ring is; Alt + drag: camera.");
    int erase = painting.erase ? 1 : 0;
    ImGui::RadioButton("draw", &erase, 0);
    ImGui::SameLine();
    ImGui::RadioButton("erase", &erase, 1);
    painting.erase = erase == 1;
    int target = painting.pickAtTarget ? 1 : 0;
    ImGui::RadioButton("source", &target, 0);
    ImGui::SameLine();
    ImGui::RadioButton("target", &target, 1);
    painting.pickAtTarget = target == 1;
    int thin = painting.thinLines ? 1 : 0;
    ImGui::RadioButton("thick", &thin, 0);
    ImGui::SameLine();
    ImGui::RadioButton("thin", &thin, 1);
    painting.thinLines = thin == 1;
    ImGui::SliderInt("brush radius", &painting.brushRadius, 0, 8);

    // P6: the colour of new grains.
    ImGui::Checkbox("default sand", &painting.defaultSandColor);
    if (!painting.defaultSandColor) {
        ImGui::SameLine();
        ImGui::ColorEdit3("##sand colour", painting.sandColor.data(), ImGuiColorEditFlags_NoInputs);
    }
    ImGui::BeginDisabled(painting.loadedDraft.empty());
    ImGui::Checkbox("colour from draft", &painting.colorFromDraft);
    ImGui::EndDisabled();

    // P5: the draft image, from models/draft_*, a path or a file dropped on the window. The
    // choosers fold away so the panel fits a 1280x800 window.
    ImGui::BeginDisabled(painting.loadedDraft.empty());
    ImGui::Checkbox("draft image", &painting.showDraft);
    ImGui::EndDisabled();
    if (ImGui::TreeNodeEx("choose draft", openWhereRoomy())) {
        const std::string shown =
            painting.loadedDraft.empty() ? "(none)" : std::filesystem::path(painting.loadedDraft).filename().string();
        if (ImGui::BeginCombo("draft", shown.c_str())) {
            for (const std::string& file : painting.draftFiles)
                if (ImGui::Selectable(std::filesystem::path(file).filename().string().c_str(),
                                      painting.loadedDraft == file)) {
                    painting.draftPath = file;
                    state.commands.push(Command::LoadDraft);
                }
            ImGui::EndCombo();
        }
        char path[512] = {};
        painting.draftPath.copy(path, sizeof path - 1);
        if (ImGui::InputText("draft path", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue)) {
            painting.draftPath = path;
            state.commands.push(Command::LoadDraft);
        }
        if (ImGui::Button("Open draft...")) {
            state.files.choosing = FileChoice::Draft;
            state.commands.push(Command::ChooseFile);
        }
        ImGui::SameLine();
        hint("or drop a PNG or JPEG on the window");
        ImGui::TreePop();
    }

    // P7
    ImGui::BeginDisabled(painting.undoSteps == 0);
    if (ImGui::Button("Undo stroke (Ctrl+Z)")) state.commands.push(Command::Undo);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::SameLine();
    ImGui::BeginDisabled(painting.redoSteps == 0);
    if (ImGui::Button("Redo (Ctrl+Y)")) state.commands.push(Command::Redo);
    ImGui::EndDisabled();
    ImGui::Text("%zu kept (%.1f MiB compressed)", painting.undoSteps, double(painting.undoBytes) / double(1 << 20));

    // SPEC G2 / R11: a box of INVALID cells in the lower grid; sand piles on it.
    if (ImGui::TreeNodeEx("obstacles", openWhereRoomy())) {
        ObstacleDrag& drag = state.obstacleDrag;
        if (!drag.armed && !drag.dragging) {
            if (ImGui::Button("Place with the mouse")) drag.armed = true;
        } else {
            if (ImGui::Button("Cancel placing")) drag = {};
            ImGui::SameLine();
            ImGui::TextWrapped("drag a box on the canvas floor");
        }
        hint("or type it, in lower-grid cells (max exclusive; y: height)");
        ImGui::InputInt3("min x y z", painting.obstacleMin.data());
        ImGui::InputInt3("max x y z", painting.obstacleMax.data());
        if (ImGui::Button("Add obstacle")) state.commands.push(Command::AddObstacle);
        ImGui::SameLine();
        if (ImGui::Button("Clear obstacles")) state.commands.push(Command::ClearObstacles);
        ImGui::TreePop();
    }

    // The digger: a body dragged through the sand; it pushes the grains out of its way.
    if (ImGui::TreeNodeEx("digger", openWhereRoomy())) {
        DiggerSettings& digger = state.digger;
        ImGui::Checkbox("Dig with the mouse", &digger.active);
        hint("drag on the floor; the arrow keys move it a cell");
        // "model file..." opens the file dialog until a model is loaded, then names that file.
        const std::string model = digger.loadedModel.empty()
                                      ? std::string("model file...")
                                      : std::filesystem::path(digger.loadedModel).filename().string();
        const char* bodies[] = {"blade", "box", "ball", model.c_str()};
        int body = digger.body;
        if (ImGui::Combo("body", &body, bodies, 4)) {
            if (body == 3 && digger.loadedModel.empty()) {
                state.files.choosing = FileChoice::DiggerBody; // the body becomes the model once it loads
                state.commands.push(Command::ChooseFile);
            } else {
                digger.body = body;
            }
        }
        hint("a new body is placed at the next drag; Undo takes a whole drag back");
        char path[512] = {};
        digger.modelPath.copy(path, sizeof path - 1);
        if (ImGui::InputText("body model", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue)) {
            digger.modelPath = path;
            state.commands.push(Command::LoadDiggerBody);
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("Open...##diggerbody")) {
            state.files.choosing = FileChoice::DiggerBody;
            state.commands.push(Command::ChooseFile);
        }
        const int boxHeight = sandcore::canvasBoxHeight(state.loaded.request.resolution);
        ImGui::SliderInt("depth", &digger.depth, 0, std::max(0, boxHeight - 1));
        ImGui::SliderInt("heading", &digger.heading, 0, 3, "%d quarter turns");
        ImGui::TreePop();
    }
}

void drawFileSection(AppState& state) {
    // SPEC E1, E2, E4: typed paths, each with the desktop's file dialog beside it (a file
    // dropped on the window still opens: .sand states, drafts on the canvas, models).
    FileSettings& files = state.files;
    auto browse = [&](const char* id, FileChoice choice, bool sameLine = true) {
        if (sameLine) ImGui::SameLine();
        if (ImGui::Button(id)) {
            files.choosing = choice;
            state.commands.push(Command::ChooseFile);
        }
    };
    char path[512] = {};
    files.statePath.copy(path, sizeof path - 1);
    if (ImGui::InputText("state file", path, sizeof path)) files.statePath = path;
    if (ImGui::Button("Save (Ctrl+S)")) state.commands.push(Command::SaveState);
    browse("Save as...", FileChoice::SaveState);
    ImGui::SameLine();
    if (ImGui::Button("Open (Ctrl+O)")) state.commands.push(Command::LoadState);
    browse("Open...", FileChoice::OpenState);
    if (files.unsavedEdits > 0) ImGui::TextUnformatted("unsaved changes");
    // I4: the files opened or saved lately, in this run and the ones before.
    if (!files.recentFiles.empty() && ImGui::BeginCombo("recent", "open a recent file")) {
        for (const std::string& recent : files.recentFiles) {
            if (ImGui::Selectable(recent.c_str())) {
                files.openPath = recent;
                state.commands.push(Command::OpenFile);
            }
        }
        ImGui::EndCombo();
    }
    char exportPath[512] = {};
    files.exportPath.copy(exportPath, sizeof exportPath - 1);
    if (ImGui::InputText("export file", exportPath, sizeof exportPath)) files.exportPath = exportPath;
    if (ImGui::Button("Export")) state.commands.push(Command::Export);
    browse("Export as...", FileChoice::Export);
    ImGui::TextUnformatted(".ply points, .vox voxels, .obj .stl .glb surface");
    char folder[512] = {};
    files.screenshotFolder.copy(folder, sizeof folder - 1);
    if (ImGui::InputText("screenshots", folder, sizeof folder)) files.screenshotFolder = folder;
    browse("Folder...", FileChoice::ScreenshotFolder, false);
    ImGui::SameLine();
    ImGui::Checkbox("with the panels", &files.screenshotWithPanel);
    if (!files.lastScreenshot.empty()) ImGui::TextWrapped("last screenshot: %s", files.lastScreenshot.c_str());
}

void drawStatisticsSection(AppState& state) {
    const FrameStatistics& stats = state.stats;
    ImGui::Text("%.1f fps   %.2f ms per frame", stats.framesPerSecond, stats.millisecondsPerFrame);
    // The ring buffer starts at the oldest frame, so the plot scrolls left.
    // The label above the plot, never over the curve.
    // The scale grows in steps of 50 ms so slow frames stay on the plot and the caption stays still.
    const float slowest = *std::max_element(stats.frameMilliseconds.begin(), stats.frameMilliseconds.end());
    const float top = 50.0f * std::ceil(std::max(slowest, 1.0f) / 50.0f);
    ImGui::TextDisabled("frame time (0 to %.0f ms)", double(top));
    ImGui::PlotLines("##frametimes", stats.frameMilliseconds.data(), FrameStatistics::kHistory, stats.historyNext,
                     nullptr, 0.0f, top,
                     ImVec2(ImGui::GetWindowWidth() - 2.0f * ImGui::GetStyle().WindowPadding.x, 3.0f * ImGui::GetFontSize()));
    ImGui::Text("grains %lld (upper %lld, lower %lld)", (long long)stats.grains, (long long)stats.grainsUpper,
                (long long)stats.grainsLower);
    ImGui::Text("moving %lld   inner %lld", (long long)stats.movingGrains, (long long)stats.innerGrains);
    ImGui::Text("steps %llu   %.1f steps/s", (unsigned long long)stats.stepsDone, stats.stepsPerSecond);
    // Steps run before the window opens (--steps) are not timed: say so rather than show 0 ms.
    if (stats.millisecondsPerStep > 0.0f)
        ImGui::Text("%.3f ms per step", stats.millisecondsPerStep);
    else
        ImGui::TextDisabled("ms per step: no step timed yet");
    ImGui::Text("drawn %lld %s", (long long)stats.subGrainsDrawn,
                state.render.mode == RenderMode::Points || state.render.mode == RenderMode::Sprites ? "points"
                                                                                                     : "quads");
    ImGui::TextDisabled("%s", state.glRenderer.c_str());
}

} // namespace sandglass
