// SPDX-License-Identifier: MIT
#pragma once
// The thesis's rules (R3) applied by the sweep, one strip of a layer at a time: a grain falls
// into the EMPTY cell below it, or else slips into one of the EMPTY cells of the 8 around that
// one, picked by a counter hash of (seed, step, grid, cell). It reads only the layer below, so a
// visit wakes nothing in its own layer and a row's awake bits are final when its turn comes.
// Private to sandcore.

#include "awake_cells.hpp"
#include "sweep_context.hpp"

namespace sandcore {

/// What the classic visits of one grid's sweep share, set up once per sweep.
struct ClassicStep {
    const SweepContext& context;
    AwakeCells& awake;
    OutletWakes& outlet;
    bool bottomIsOutlet; ///< layer 0 is the outlet row (the upper grid): its grains stay awake

    /// Visits the awake cells of strip `strip` of layer y (every cell, when not sleeping) and
    /// puts them to sleep; its moves go to `log` (or the context's feed or list).
    SweepResult sweepStrip(int y, int strip, StripLog& log) const;

private:
    /// The row a visit lies in, as the strip loop has it at hand.
    struct Row {
        int y, z;
        std::uint32_t firstCell;  ///< the index of cell (0, y, z)
        AwakeCells::Word* words; ///< the row's awake and occupied bits
    };
    SweepResult sweepRows(int y, int strip, StripLog& log) const;
    bool visit(StripLog& log, const Row& row, int x) const; // true when the grain moved
    void prefetchFirstAwake(int y, int z) const;
};

} // namespace sandcore
