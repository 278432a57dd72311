// SPDX-License-Identifier: MIT
#include "wild_models/wild_checks.hpp"

#include "scene/mesh_loader.hpp"
#include "scene/scene_request.hpp"

#include "sandcore/cell_grid.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <regex>

namespace sandglass::wild {

namespace {

using sandcore::GridLevel;

// Calls visit(model point) for the centre of every grain's cell.
void forEachGrain(const BuiltScene& built, const std::function<bool(sandcore::Vec3)>& visit) {
    for (GridLevel level : {GridLevel::Upper, GridLevel::Lower}) {
        const sandcore::CellGrid& grid = built.scene.grid(level);
        const sandcore::Int3 origin = built.scene.gridOrigin(level);
        const sandcore::Int3 s = grid.size();
        for (int y = 0; y < s.y; ++y)
            for (int z = 0; z < s.z; ++z)
                for (int x = 0; x < s.x; ++x) {
                    if (grid[grid.index(x, y, z)] < 0) continue;
                    const sandcore::Vec3 world{float(origin.x + x) + 0.5f, float(origin.y + y) + 0.5f, float(origin.z + z) + 0.5f};
                    const std::array<double, 3> file = built.modelToWorld->toFile(world);
                    if (!visit({float(file[0]), float(file[1]), float(file[2])})) return;
                }
    }
}

int axisOf(int upAxis) { return upAxis / 2; }

std::string where(sandcore::Vec3 p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", double(p.x), double(p.y), double(p.z));
    return text;
}

// The first grain outside the glass (more than `tolerance` model units), or "".
std::string grainOutside(const BuiltScene& built, const WildModel& model, double tolerance) {
    std::string found;
    forEachGrain(built, [&](sandcore::Vec3 p) {
        if (model.insideGlass(p, tolerance)) return true;
        found = "a grain outside the glass at " + where(p);
        if (model.neckHeight() > 0) {
            // Where along the glass: a grain beside the neck or under the base reads at once.
            const AxisPosition at = model.axisPositionOf({double(p.x), double(p.y), double(p.z)});
            char text[160];
            std::snprintf(text, sizeof text, ", %g up the axis and %g from it, where the glass is %g wide (neck at %g)", at.height,
                          at.distance, model.innerRadiusAt(at.height), model.neckHeight());
            found += text;
        }
        return false;
    });
    return found;
}

BuiltScene build(const std::filesystem::path& file, sandcore::SceneKind kind, const CheckSettings& checks, int resolution,
                 double& milliseconds) {
    SceneSettings settings;
    settings.request.kind = kind;
    settings.request.modelPath = file.string();
    settings.request.resolution = resolution;
    settings.step.physics.level = checks.physics;
    const auto start = std::chrono::steady_clock::now();
    BuiltScene built = buildSceneWithReport(settings);
    milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return built;
}

// The volume of the model's lower bulb, model units cubed: the profile turned about the axis below the neck.
double lowerBulbVolume(const WildModel& model) {
    const int slices = 2000;
    const double neck = model.neckHeight(), step = neck / slices;
    double volume = 0.0;
    for (int i = 0; i < slices; ++i) {
        const double r = std::max(0.0, model.innerRadiusAt((i + 0.5) * step));
        volume += 3.141592653589793 * r * r * step;
    }
    return volume;
}

void checkHourglass(const WildModel& model, const BuiltScene& first, const CheckSettings& settings, ModelCheck& out) {
    BuiltScene built(first.scene.clone());
    built.modelToWorld = first.modelToWorld;
    const double cell = 1.0 / first.modelToWorld->placement.scale[0]; // model units per cell
    const double tolerance = 1.0 * cell;
    const bool funnel = model.modelClass == ModelClass::Funnel;
    if (funnel) {
        if (out.note.empty()) out.failure = "no note that the funnel is no hourglass";
    } else {
        const int found = int(*first.upAxis);
        if (axisOf(found) != axisOf(model.upAxis)) out.failure = "up axis " + std::string(sandcore::upAxisName(*first.upAxis)) + " found";
        else if (model.hasModelledSand() && found != model.upAxis) out.failure = "upside down despite the modelled sand";
        if (!out.note.empty() && out.failure.empty()) out.failure = "no hourglass found: " + out.note;
    }
    if (!out.failure.empty()) return;
    if (std::string outside = grainOutside(built, model, tolerance); !outside.empty()) {
        out.failure = "at the start, " + outside;
        out.grainOutside = true;
        return;
    }
    if (funnel) return;
    // Without modelled sand a symmetric hourglass may stand either way up: then the model's lower
    // bulb is the scene's upper one.
    const bool turned = int(*first.upAxis) != model.upAxis;
    std::int64_t inUpper = 0;
    forEachGrain(built, [&](sandcore::Vec3 p) {
        inUpper += (turned ? model.inLowerBulb(p) : model.inUpperBulb(p)) ? 1 : 0;
        return true;
    });
    out.upperFillShare = double(inUpper) * cell * cell * cell / (turned ? lowerBulbVolume(model) : model.upperBulbVolume());
    if (out.upperFillShare < 0.4) {
        out.failure = "only " + std::to_string(int(100 * out.upperFillShare)) + "% of the upper bulb starts as sand";
        return;
    }
    if (!settings.drain) return;
    const double rate = built.scene.neckFlowRate();
    const double stepsAtRate = rate > 0.0 ? 2.0 * double(built.scene.grainCount()) / rate : 0.0;
    const int maxSteps = int(std::max(double(settings.maxSteps), stepsAtRate));
    int steps = 0;
    while (built.scene.counters().grainsUpper > 0 && !built.scene.settled() && steps < maxSteps) {
        built.scene.step();
        ++steps;
        if (steps % settings.checkEvery == 0)
            if (std::string outside = grainOutside(built, model, tolerance); !outside.empty()) {
                out.failure = "after " + std::to_string(steps) + " steps, " + outside;
                out.grainOutside = true;
                return;
            }
    }
    for (int extra = 0; extra < 200 && !built.scene.settled(); ++extra) built.scene.step();
    if (std::string outside = grainOutside(built, model, tolerance); !outside.empty()) {
        out.failure = "at the end, " + outside;
        out.grainOutside = true;
        return;
    }
    // At the end every grain has passed the neck into the lower bulb's grid.
    out.grainsLeftAbove = built.scene.counters().grainsUpper;
    if (out.grainsLeftAbove > 0)
        out.failure = "after the drain (" + std::to_string(steps) + " steps) " + std::to_string(built.scene.counters().grainsUpper) +
                      " grains stay above the neck";
}

void checkSculpture(const WildModel& model, const BuiltScene& built, ModelCheck& out) {
    const double cell = 1.0 / built.modelToWorld->placement.scale[0];
    const int found = int(*built.upAxis);
    // A figure stands along its up axis; a keyboard lies any way.
    if (model.modelClass == ModelClass::Character && found != model.upAxis) {
        out.failure = std::string("stands along ") + sandcore::upAxisName(*built.upAxis);
        return;
    }
    if (std::string outside = grainOutside(built, model, cell); !outside.empty()) {
        out.failure = "a sand cell outside the body: " + outside;
        out.grainOutside = true;
    }
}

} // namespace

ModelCheck checkModel(const WildModel& model, const std::filesystem::path& file, const CheckSettings& settings) {
    ModelCheck out;
    if (file.extension() == ".stl") writeStl(model, file);
    else writeObj(model, file);
    const bool sculpture = model.modelClass == ModelClass::Character || model.modelClass == ModelClass::Keyboard;
    const sandcore::SceneKind kind = sculpture ? sandcore::SceneKind::Sculpture : sandcore::SceneKind::Hourglass;
    int resolution = settings.resolution;
    if (model.modelClass == ModelClass::Keyboard) {
        // Keys thinner than a cell: the refusal must name the resolution that holds them.
        try {
            double ignored = 0.0;
            build(file, kind, settings, resolution, ignored);
        } catch (const ModelError& e) {
            std::smatch match;
            const std::string message = e.what();
            if (!std::regex_search(message, match, std::regex("--res ([0-9]+)"))) {
                out.failure = "the refusal names no resolution: " + message;
                return out;
            }
            resolution = std::stoi(match[1]);
        }
    }
    // Keys under a cell thin hold a cell centre or not depending on where they lie: sand in some
    // of them must come with a note that names the resolution that holds them all.
    const bool thinnerThanACell = model.smallestPartExtent() < model.largestExtent() / resolution;
    const bool expectThinNote = model.modelClass == ModelClass::Keyboard && resolution == settings.resolution && thinnerThanACell;
    try {
        const BuiltScene built = build(file, kind, settings, resolution, out.loadMilliseconds);
        out.loaded = true;
        out.note = built.note;
        out.grains = built.scene.grainCount();
        if (expectThinNote && !std::regex_search(out.note, std::regex("--res [0-9]+"))) {
            out.failure = "keys thinner than a cell gave sand at resolution " + std::to_string(resolution) +
                          " with no note naming the resolution that holds them";
            return out;
        }
        if (sculpture) checkSculpture(model, built, out);
        else checkHourglass(model, built, settings, out);
    } catch (const std::exception& e) {
        out.failure = std::string("cannot build it: ") + e.what();
    }
    return out;
}

} // namespace sandglass::wild
