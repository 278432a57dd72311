// SPDX-License-Identifier: MIT
#include "scene/sand_painter.hpp"

#include <algorithm>
#include <cstdlib>

namespace sandglass {

using sandcore::GridLevel;

std::vector<CanvasColumn> columnsOnLine(CanvasColumn from, CanvasColumn to) {
    // Bresenham: every next column touches the previous one (8-connected), so no gaps.
    std::vector<CanvasColumn> line;
    const int dx = std::abs(to.x - from.x), dz = -std::abs(to.z - from.z);
    const int sx = from.x < to.x ? 1 : -1, sz = from.z < to.z ? 1 : -1;
    int error = dx + dz;
    CanvasColumn c = from;
    for (;;) {
        line.push_back(c);
        if (c == to) break;
        const int twice = 2 * error;
        if (twice >= dz) {
            error += dz;
            c.x += sx;
        }
        if (twice <= dx) {
            error += dx;
            c.z += sz;
        }
    }
    return line;
}

std::vector<CanvasColumn> brushColumns(CanvasColumn centre, int radius, int sizeX, int sizeZ) {
    std::vector<CanvasColumn> columns;
    radius = std::max(radius, 0);
    for (int z = centre.z - radius; z <= centre.z + radius; ++z)
        for (int x = centre.x - radius; x <= centre.x + radius; ++x) {
            const int dx = x - centre.x, dz = z - centre.z;
            if (x < 0 || z < 0 || x >= sizeX || z >= sizeZ || dx * dx + dz * dz > radius * radius) continue;
            columns.push_back({x, z});
        }
    return columns;
}

bool releaseGrain(sandcore::Scene& scene, CanvasColumn column, std::uint32_t rgba) {
    const sandcore::CellGrid& upper = scene.grid(GridLevel::Upper);
    const sandcore::Int3 s = upper.size();
    if (column.x < 0 || column.z < 0 || column.x >= s.x || column.z >= s.z) return false;
    return scene.addGrain(GridLevel::Upper, upper.index(column.x, s.y - 1, column.z), rgba) >= 0;
}

bool eraseTopGrain(sandcore::Scene& scene, CanvasColumn column) {
    const sandcore::CellGrid& lower = scene.grid(GridLevel::Lower);
    const sandcore::Int3 s = lower.size();
    if (column.x < 0 || column.z < 0 || column.x >= s.x || column.z >= s.z) return false;
    for (int y = s.y - 1; y >= 0; --y) {
        const std::uint32_t cell = lower.index(column.x, y, column.z);
        if (lower[cell] >= 0) return scene.removeGrain(GridLevel::Lower, cell); // only grains, never INVALID
    }
    return false;
}

std::size_t snapshotBytes(const sandcore::SceneSnapshot& snapshot) {
    const auto bytesOf = [](const auto& vector) { return vector.size() * sizeof(vector[0]); };
    const sandcore::GrainStore& grains = snapshot.grains;
    return snapshot.upper.cells().size_bytes() + snapshot.lower.cells().size_bytes() + bytesOf(grains.level) +
           bytesOf(grains.place) + bytesOf(grains.identity) +
           bytesOf(grains.color) + bytesOf(snapshot.upperObstacles) + bytesOf(snapshot.lowerObstacles);
}

void SandPainter::paintSample(sandcore::Scene& scene, CanvasColumn column, const PaintSettings& settings,
                              const DraftImage* draft) {
    const sandcore::Int3 s = scene.grid(GridLevel::Lower).size();
    for (const CanvasColumn& c : brushColumns(column, settings.brushRadius, s.x, s.z)) {
        if (settings.action == PaintAction::Erase) {
            erased_ += eraseTopGrain(scene, c) ? 1 : 0;
            continue;
        }
        std::uint32_t rgba = settings.color;
        if (settings.colorFromDraft && draft)
            rgba = draft->colorAt((c.x + 0.5) / double(s.x), (c.z + 0.5) / double(s.z));
        released_ += releaseGrain(scene, c, rgba) ? 1 : 0;
    }
}

void SandPainter::pushHistory(const sandcore::Scene& scene) {
    history_.emplace_back(scene);
    historyBytes_ += history_.back().bytes();
    // Oldest strokes go first; the one just saved always stays, so Undo takes it back.
    const std::size_t maxStrokes = std::max<std::size_t>(limits_.maxStrokes, 1);
    while (history_.size() > maxStrokes || (history_.size() > 1 && historyBytes_ > limits_.maxBytes)) {
        historyBytes_ -= history_.front().bytes();
        history_.pop_front();
    }
}

void SandPainter::beginStroke(sandcore::Scene& scene, CanvasColumn column, const PaintSettings& settings,
                              const DraftImage* draft) {
    pushHistory(scene);
    redo_.clear(); // a new stroke starts a new future
    released_ = erased_ = 0;
    last_ = column;
    paintSample(scene, column, settings, draft);
}

void SandPainter::continueStroke(sandcore::Scene& scene, CanvasColumn column, const PaintSettings& settings,
                                 const DraftImage* draft) {
    if (!last_) return beginStroke(scene, column, settings, draft);
    if (column == *last_) {
        // Thick lines pour on while the mouse rests; thin lines give one grain per distinct column.
        if (!settings.thinLines) paintSample(scene, column, settings, draft);
        return;
    }
    const std::vector<CanvasColumn> line = columnsOnLine(*last_, column);
    for (std::size_t i = 1; i < line.size(); ++i) paintSample(scene, line[i], settings, draft); // line[0] is painted
    last_ = column;
}

void SandPainter::endStroke() { last_.reset(); }

bool SandPainter::undo(sandcore::Scene& scene) {
    if (history_.empty()) return false;
    endStroke();
    redo_.emplace_back(scene);
    scene.restore(history_.back().expand(scene));
    historyBytes_ -= history_.back().bytes();
    history_.pop_back();
    return true;
}

bool SandPainter::redo(sandcore::Scene& scene) {
    if (redo_.empty()) return false;
    endStroke();
    pushHistory(scene);
    scene.restore(redo_.back().expand(scene));
    redo_.pop_back();
    return true;
}

std::size_t SandPainter::redoBytes() const {
    std::size_t bytes = 0;
    for (const CompressedSnapshot& snapshot : redo_) bytes += snapshot.bytes();
    return bytes;
}

} // namespace sandglass
