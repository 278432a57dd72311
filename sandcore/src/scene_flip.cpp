// SPDX-License-Identifier: MIT
// Turning the hourglass over (T1) and copying a scene. The sand is mirrored in y across both
// grids: the world height of the two grids together stays, so the shared row stays shared and
// a cell at world height h goes to height H - 1 - h.
#include "sandcore/scene.hpp"

#include "grid_sweep.hpp"
#include "layout_bits.hpp"

#include <algorithm>
#include <utility>

namespace sandcore {

namespace {

std::vector<CellBox> mirroredInY(const std::vector<CellBox>& boxes, int sizeY) {
    std::vector<CellBox> out;
    out.reserve(boxes.size());
    for (const CellBox& box : boxes)
        out.push_back({{box.min.x, sizeY - box.max.y, box.min.z}, {box.max.x, sizeY - box.min.y, box.max.z}});
    return out;
}

} // namespace

// Layouts, obstacle lists and sweeps turn over; the live grids and grains are the caller's.
void Scene::flipLayouts() {
    const int upperHeight = upperLayout_->size().y, lowerHeight = lowerLayout_->size().y;
    LayoutBits upperLayout(mirroredInY(lowerLayout_->grid())), lowerLayout(mirroredInY(upperLayout_->grid()));
    std::vector<CellBox> upperObstacles = mirroredInY(lowerObstacles_, lowerHeight);
    std::vector<CellBox> lowerObstacles = mirroredInY(upperObstacles_, upperHeight);
    upperLayout_ = std::make_unique<LayoutBits>(std::move(upperLayout));
    lowerLayout_ = std::make_unique<LayoutBits>(std::move(lowerLayout));
    upperObstacles_ = std::move(upperObstacles);
    lowerObstacles_ = std::move(lowerObstacles);
    makeSweeps();
    flipped_ = !flipped_;
}

bool Scene::flip() {
    if (!shape_.turnsOver) return false;
    CellGrid upper = mirroredInY(lower_), lower = mirroredInY(upper_);
    const CellGrid& oldUpper = upper_;
    const CellGrid& oldLower = lower_;
    for (std::uint32_t id = 0; id < grains_.size(); ++id) {
        const bool wasUpper = grains_.level[id] == GridLevel::Upper;
        const CellGrid& from = wasUpper ? oldUpper : oldLower;
        const CellGrid& to = wasUpper ? lower : upper;
        const Int3 c = from.coordinate(grains_.place[id].cell);
        grains_.level[id] = wasUpper ? GridLevel::Lower : GridLevel::Upper;
        grains_.place[id].cell = to.index(c.x, from.size().y - 1 - c.y, c.z);
        // No glide across the turn: the view's turning animation carries the eye.
        grains_.place[id].cameFrom = kNoMove;
        grains_.place[id].movedAtStep = counters_.stepsDone;
    }
    flipLayouts();
    upper_ = std::move(upper);
    lower_ = std::move(lower);
    std::swap(counters_.grainsUpper, counters_.grainsLower);
    // Turning over stops every fall (granular): what fell down would now fall up.
    for (FallStates& grid : grains_.fall) std::fill(grid.begin(), grid.end(), FallState{});
    // Every grain changed its cell, so the scene is no longer settled.
    counters_.movesLastStep = grains_.size();
    movedGrains_.clear();
    for (std::uint32_t id = 0; id < grains_.size(); ++id) movedGrains_.push_back({id, grains_.place[id].cell, kNoMove, grains_.level[id]});
    markEverythingAwake();
    return true;
}

Scene Scene::clone() const {
    // Built upright, as its fill expects; restore() turns it as this scene is turned.
    Scene copy(shape_, flipped_ ? mirroredInY(lowerLayout_->grid()) : upperLayout_->grid(),
               flipped_ ? mirroredInY(upperLayout_->grid()) : lowerLayout_->grid(), upperFill_, settings_);
    copy.restore(snapshot());
    return copy;
}

} // namespace sandcore
