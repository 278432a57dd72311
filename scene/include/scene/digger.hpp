// SPDX-License-Identifier: MIT
#pragma once
// The digger: a moving body (sandcore/moving_body.hpp) driven along a path of cells through a
// scene's sand, a few cells a step, as `simulate --dig` and the tests drive it; and what it left
// behind, the trench's depth.

#include "sandcore/moving_body.hpp"
#include "sandcore/scene.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sandglass {

/// Unit moves a digger may make per step (--dig-speed).
inline constexpr int kMaxDigSpeed = 64;

/// "X,Y,Z X,Y,Z ..." (spaces or semicolons between points) to points; throws
/// std::invalid_argument with one line for anything else or an empty path.
std::vector<sandcore::Int3> parseDigPath(std::string_view text);

/// The body named by --dig-body for a canvas `width` cells wide: "blade" (width/4 wide, 2 thick,
/// bedDepth + width/8 high), "box" (width/8 a side), "ball" (width/8 across), or a model file
/// voxelized width/6 cells along its largest extent. Throws std::invalid_argument (or ModelError
/// for a file) with one line.
sandcore::InsideMask makeDigBodyShape(const std::string& body, int width, int bedDepth);

/// A model file voxelized as a sculpture is, width/6 cells along its largest extent and trimmed
/// to its cells: the digger's body for a canvas `width` cells wide. Throws ModelError with one line.
sandcore::InsideMask digBodyFromModel(const std::string& file, int width);

/// Quarter turns that put a blade (wide along x at heading 0) across a move from `from` to `to`.
int headingAcross(sandcore::Int3 from, sandcore::Int3 to);

/// Drives one body along a path: placed at the first point (turned across the first leg), then
/// moved to each next point in turn, at most `speed` unit moves before each step. A leg the body
/// cannot finish (a wall, the grid's edge, no room for the sand) is given up where it stopped.
class DigDrive {
public:
    /// Places the body in `scene`; throws std::invalid_argument when it does not fit there
    /// (outside the lower grid or on a wall) or the path is empty.
    DigDrive(sandcore::Scene& scene, sandcore::InsideMask shape, std::vector<sandcore::Int3> path, int speed);
    /// The moves before one step; does nothing once the path is done.
    void beforeStep(sandcore::Scene& scene);
    bool done() const { return leg_ >= path_.size(); } ///< the last point reached or given up
    std::int64_t grainsPushed() const { return pushed_; } ///< grains pushed, placing included
    std::int64_t cellsMoved() const { return moved_; }    ///< unit moves made
    int legsStopped() const { return stopped_; }          ///< legs given up short of their point
    std::size_t body() const { return body_; }            ///< the body's index in the scene

private:
    std::vector<sandcore::Int3> path_;
    std::size_t leg_ = 1; // the point it heads for
    int speed_;
    std::size_t body_ = 0;
    std::int64_t pushed_ = 0, moved_ = 0;
    int stopped_ = 0;
};

/// Sand height of every column of the lower grid (top grain + 1, 0 for none), x + sizeX * z.
std::vector<int> lowerColumnHeights(const sandcore::Scene& scene);

/// The trench a path left: over the columns the path's legs pass through (each once), the mean of
/// the height before minus the height after (positive: deeper). 0 for a path of one point.
double trenchDepth(const std::vector<int>& heightsBefore, const std::vector<int>& heightsAfter,
                   const std::vector<sandcore::Int3>& path, sandcore::Int3 gridSize);

} // namespace sandglass
