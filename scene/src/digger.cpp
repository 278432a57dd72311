// SPDX-License-Identifier: MIT
#include "scene/digger.hpp"

#include "scene/mesh_loader.hpp"
#include "scene/model_voxelizer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <utility>

namespace sandglass {

using sandcore::Int3;

namespace {

int parseCoordinate(std::string_view point, std::string_view text) {
    int value = 0;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (first != last && *first == '+') ++first;
    const auto [end, error] = std::from_chars(first, last, value);
    if (first == last || error != std::errc{} || end != last)
        throw std::invalid_argument("--dig: '" + std::string(point) + "' is not a point X,Y,Z of whole cells");
    return value;
}

// The mask cut to the box of its inside cells, so a model's padding does not lift it off its anchor.
sandcore::InsideMask trimmed(const sandcore::InsideMask& mask) {
    Int3 low{mask.size.x, mask.size.y, mask.size.z}, high{-1, -1, -1};
    for (int y = 0; y < mask.size.y; ++y)
        for (int z = 0; z < mask.size.z; ++z)
            for (int x = 0; x < mask.size.x; ++x)
                if (mask.at(x, y, z)) {
                    low = {std::min(low.x, x), std::min(low.y, y), std::min(low.z, z)};
                    high = {std::max(high.x, x), std::max(high.y, y), std::max(high.z, z)};
                }
    if (high.x < 0) throw std::invalid_argument("--dig-body: the model has no inside cells at this size");
    sandcore::InsideMask out = sandcore::InsideMask::empty({high.x - low.x + 1, high.y - low.y + 1, high.z - low.z + 1});
    for (int y = 0; y < out.size.y; ++y)
        for (int z = 0; z < out.size.z; ++z)
            for (int x = 0; x < out.size.x; ++x) out.set(x, y, z, mask.at(x + low.x, y + low.y, z + low.z));
    return out;
}

// The columns a straight leg passes over, from `from` to `to` inclusive.
void addLegColumns(Int3 from, Int3 to, std::set<std::pair<int, int>>& columns) {
    const int steps = std::max(std::abs(to.x - from.x), std::abs(to.z - from.z));
    for (int t = 0; t <= steps; ++t) {
        const double share = steps == 0 ? 0.0 : double(t) / steps;
        columns.insert({int(std::lround(from.x + (to.x - from.x) * share)), int(std::lround(from.z + (to.z - from.z) * share))});
    }
}

} // namespace

std::vector<Int3> parseDigPath(std::string_view text) {
    std::vector<Int3> path;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = std::min(text.find_first_of(" ;", at), text.size());
        const std::string_view point = text.substr(at, end - at);
        at = end + 1;
        if (point.empty()) continue;
        const std::size_t comma1 = point.find(','), comma2 = point.find(',', comma1 + 1);
        if (comma1 == std::string_view::npos || comma2 == std::string_view::npos ||
            point.find(',', comma2 + 1) != std::string_view::npos)
            throw std::invalid_argument("--dig: '" + std::string(point) + "' is not a point X,Y,Z of whole cells");
        path.push_back({parseCoordinate(point, point.substr(0, comma1)),
                        parseCoordinate(point, point.substr(comma1 + 1, comma2 - comma1 - 1)),
                        parseCoordinate(point, point.substr(comma2 + 1))});
    }
    if (path.empty()) throw std::invalid_argument("--dig wants at least one point X,Y,Z");
    return path;
}

sandcore::InsideMask digBodyFromModel(const std::string& file, int width) {
    sandcore::VoxelizeSettings settings;
    settings.resolution = std::max(2, width / 6);
    return trimmed(voxelizeModelFile(file, settings, ModelUse::MaskOnly).voxels.mask);
}

sandcore::InsideMask makeDigBodyShape(const std::string& body, int width, int bedDepth) {
    const int eighth = std::max(2, width / 8);
    if (body == "blade") return sandcore::makeBladeShape(std::max(3, width / 4), bedDepth + eighth, 2);
    if (body == "box") return sandcore::makeBoxShape({eighth, eighth, eighth});
    if (body == "ball") return sandcore::makeBallShape(eighth);
    if (body.empty()) throw std::invalid_argument("--dig-body wants blade, box, ball or a model file");
    try {
        return digBodyFromModel(body, width);
    } catch (const ModelError& error) {
        throw std::invalid_argument(std::string("--dig-body: ") + error.what() + " (blade, box, ball or a model file)");
    }
}

int headingAcross(Int3 from, Int3 to) {
    // At heading 0 the blade is wide along x and pushes along z; a quarter turn pushes along x.
    return std::abs(to.x - from.x) > std::abs(to.z - from.z) ? 1 : 0;
}

DigDrive::DigDrive(sandcore::Scene& scene, sandcore::InsideMask shape, std::vector<Int3> path, int speed)
    : path_(std::move(path)), speed_(speed) {
    if (path_.empty()) throw std::invalid_argument("--dig wants at least one point X,Y,Z");
    if (speed < 1 || speed > kMaxDigSpeed)
        throw std::invalid_argument("--dig-speed must lie in 1.." + std::to_string(kMaxDigSpeed) + ", got " +
                                    std::to_string(speed));
    const Int3 start = path_.front();
    const Int3 size = scene.grid(sandcore::GridLevel::Lower).size();
    for (const Int3& p : path_)
        if (p.x < 0 || p.y < 0 || p.z < 0 || p.x >= size.x || p.y >= size.y || p.z >= size.z)
            throw std::invalid_argument("--dig: the point " + std::to_string(p.x) + "," + std::to_string(p.y) + "," +
                                        std::to_string(p.z) + " lies outside the sand box (0.." +
                                        std::to_string(size.x - 1) + ", 0.." + std::to_string(size.y - 1) + ", 0.." +
                                        std::to_string(size.z - 1) + ")");
    const int heading = path_.size() > 1 ? headingAcross(start, path_[1]) : 0;
    const std::int64_t pushedBefore = scene.grainsPushedTotal();
    const std::int64_t body = scene.addBody({std::move(shape), start, heading});
    if (body < 0)
        throw std::invalid_argument("--dig: the body does not fit at " + std::to_string(start.x) + "," +
                                    std::to_string(start.y) + "," + std::to_string(start.z) +
                                    " (it would reach past the box or into a wall)");
    body_ = std::size_t(body);
    pushed_ = scene.grainsPushedTotal() - pushedBefore;
}

void DigDrive::beforeStep(sandcore::Scene& scene) {
    int budget = speed_;
    while (budget > 0 && !done()) {
        const Int3 target = path_[leg_];
        const sandcore::BodyMove move = scene.moveBody(body_, target, budget);
        budget -= move.cellsMoved;
        moved_ += move.cellsMoved;
        pushed_ += move.grainsPushed;
        if (move.reached == target || move.stopped) {
            stopped_ += move.stopped ? 1 : 0;
            ++leg_;
            // A blade turns across its next leg where it stands (a turn that does not fit is skipped).
            if (!done()) {
                const sandcore::BodyMove turn = scene.turnBody(body_, headingAcross(move.reached, path_[leg_]));
                pushed_ += turn.grainsPushed;
            }
        }
        if (move.stopped) break; // the rest of this step's budget would hit the same wall
    }
}

std::vector<int> lowerColumnHeights(const sandcore::Scene& scene) {
    const sandcore::CellGrid& grid = scene.grid(sandcore::GridLevel::Lower);
    const Int3 size = grid.size();
    std::vector<int> heights(std::size_t(size.x) * std::size_t(size.z), 0);
    for (int y = 0; y < size.y; ++y)
        for (int z = 0; z < size.z; ++z)
            for (int x = 0; x < size.x; ++x)
                if (grid.at(x, y, z) >= 0) heights[std::size_t(x + size.x * z)] = y + 1;
    return heights;
}

double trenchDepth(const std::vector<int>& heightsBefore, const std::vector<int>& heightsAfter,
                   const std::vector<Int3>& path, Int3 gridSize) {
    std::set<std::pair<int, int>> columns;
    for (std::size_t i = 1; i < path.size(); ++i) addLegColumns(path[i - 1], path[i], columns);
    if (columns.empty()) return 0.0;
    double sum = 0.0;
    for (const auto& [x, z] : columns) {
        const std::size_t n = std::size_t(x + gridSize.x * z);
        sum += heightsBefore[n] - heightsAfter[n];
    }
    return sum / double(columns.size());
}

} // namespace sandglass
