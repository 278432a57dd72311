// SPDX-License-Identifier: MIT
#pragma once
// The hourglass's discharge in the granular level (SPEC PH4), private to sandcore.
//
// Real sand drains at a rate set at the orifice, independent of the fill height (Beverloo's law:
// W = C rho sqrt(g) (D - k d)^(5/2)); no cellular automaton gets that by emergence, because its
// cells carry no stress. So the neck is modelled: each step lets through the grains Beverloo's
// law allows for the neck's measured cross-section, with C = 0.58 and k = 1.5 (Beverloo, Leniger
// & van de Velde 1961; Mankoc et al. 2007 fit C = 0.58, k = 1.5 grain diameters), a cell being one
// grain (d = 1, rho = 1 grain per cell). The count is floor(n Q) - floor((n - 1) Q) at step n, so
// the rate is exact and deterministic; grains that are not let through wait in the neck row.
//
// The cells must carry that flow on both sides of the neck (docs/engine.md, Discharge): above
// it, the grain over an emptied neck cell follows at the flow's speed (Scene::drawIntoNeck) and
// the grains beside a draining column dive into it (GranularRules::slide); below it, the grains
// leave at exitSpeed(), fast enough that the stream under the neck is sparse, and a grain that
// catches up with a slower one glances off it (GranularRules::fall), so the stream spreads.

#include "sandcore/cell_grid.hpp"

#include <cstdint>

namespace sandcore {

/// Beverloo's constants as used here.
inline constexpr double kBeverlooC = 0.58; ///< discharge coefficient
inline constexpr double kBeverlooK = 1.5;  ///< empty annulus, grain diameters (cells)
/// The narrowest neck the law is applied to, cells across. The law holds for orifices several
/// grains wide and falls to nothing at D = k, but a model's neck may be one or two cells (a neck
/// narrower than a cell is opened to one): a narrower neck passes the law's rate per open cell
/// at this diameter, so every neck drains.
inline constexpr double kNarrowestLawDiameter = 4.0;

class NeckFlow {
public:
    /// Speed of the grains in the neck row, cells per step in 16.16 fixed point: one cell.
    static constexpr std::uint32_t kFlowSpeed = 1u << 16;

    NeckFlow() = default;
    /// The flow through `neckCells` open cells (the neck's cross-section) at `gravity` cells/step^2.
    NeckFlow(std::int64_t neckCells, double gravity);

    double area() const { return area_; }         ///< open cells of the neck row
    double diameter() const { return diameter_; } ///< 2 sqrt(area / pi), cells
    double rate() const { return rate_; }         ///< grains per step: C sqrt(g) (D - k)^2.5, see kNarrowestLawDiameter
    /// Speed of the grains let through, 16.16 cells per step: at least a cell a step, and enough
    /// that the stream under the neck carries rate() with at most one cell in kStreamCells holding
    /// a grain (rate() = A v / kStreamCells for the neck's area A). In a denser stream the grains
    /// meet, take each other's speed and jam into a slow column that stands on the heap below.
    std::uint32_t exitSpeed() const { return exitSpeed_; }
    static constexpr double kStreamCells = 4.0;
    /// Grains allowed through at step `step` (>= 1).
    std::int64_t allowance(std::uint64_t step) const;

private:
    double area_ = 0, diameter_ = 0, rate_ = 0;
    std::uint32_t exitSpeed_ = kFlowSpeed;
    std::uint64_t rateQ32_ = 0; // rate in 32.32 fixed point: the allowance uses integers only
};

} // namespace sandcore
