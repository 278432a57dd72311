// SPDX-License-Identifier: MIT
#pragma once
// Per-grain records (structure of arrays), indexed by grain id. Ids are dense: [0, size()).
// Removing a grain moves the last grain into the freed id, so arrays stay packed for drawing.

#include "sandcore/large_pages.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace sandcore {

/// Which of a scene's two grids a cell belongs to (R4).
enum class GridLevel : std::uint8_t {
    Lower = 0, ///< the lower grid (lower bulb, sculpture floor box, painting box)
    Upper = 1, ///< the upper grid (upper bulb, sculpture, release layer)
};

/// The offset of the previous cell from the current one: x and z in 8 bits each (the granular
/// rules move grains up to 3 cells sideways), y in 16 bits (a fast grain falls many cells a step).
using MoveCode = std::uint32_t;

/// Largest |dx| and |dz| a MoveCode holds, cells.
inline constexpr int kMaxMoveSideways = 127;
/// Largest |dy| a MoveCode holds, cells: the granular rules cap a fall per step below this.
inline constexpr int kMaxMoveVertical = 32767;

/// Packs a cell offset with |dx|, |dz| <= kMaxMoveSideways and |dy| <= kMaxMoveVertical.
constexpr MoveCode packMove(int dx, int dy, int dz) {
    return MoveCode(dx + 128) | MoveCode(dz + 128) << 8 | MoveCode(dy + 32768) << 16;
}
constexpr int moveDx(MoveCode m) { return int(m & 0xffu) - 128; }         ///< x component of a packed offset
constexpr int moveDy(MoveCode m) { return int(m >> 16) - 32768; }         ///< y component of a packed offset
constexpr int moveDz(MoveCode m) { return int((m >> 8) & 0xffu) - 128; }  ///< z component of a packed offset
inline constexpr MoveCode kNoMove = packMove(0, 0, 0); ///< dx = dy = dz = 0

/// Where a step moved a grain: what its record holds after the move. A step lists these as it
/// moves grains (Scene::movedGrains), so whoever follows the moves reads them in one sequential
/// list instead of three per-grain arrays at random ids.
struct GrainMove {
    std::uint32_t grain = 0;            ///< its id
    std::uint32_t cell = 0;             ///< the cell it is in, in grid `level`
    MoveCode cameFrom = kNoMove;        ///< world offset back to the cell it left (as PlaceRecord::cameFrom)
    GridLevel level = GridLevel::Lower; ///< the grid holding it
};

/// A granular grain's fall, kept in one record: the rules read both fields of every grain they
/// visit, and one cache line a grain costs half as much as two.
struct FallState {
    std::uint32_t speed = 0;    ///< downward speed, cells per step in 16.16 fixed point (0 = at rest)
    std::uint16_t fraction = 0; ///< the part of a cell fallen beyond the grain's cell, 1/65536 cells
    /// The sweeps' own bookkeeping of a grain asleep in its fall (0: speed and fraction are
    /// current; else they are as of an earlier step, granular_rules.hpp). Read a grain's fall up
    /// to date with Scene::fallOf; files and embedders need only speed and fraction.
    std::uint16_t gatheringSince = 0;
    bool operator==(const FallState&) const = default;
};
static_assert(sizeof(FallState) == 8, "the sleep step fills the record's padding");

/// Where a grain is and how it got there: the three fields a step writes for every grain it
/// moves, together in 16 bytes. The moved grains lie all over the id range, so each write is a
/// cache miss; one record a move costs one line where three arrays cost three.
struct PlaceRecord {
    std::uint32_t cell = 0;         ///< cell index in the grain's grid
    MoveCode cameFrom = kNoMove;    ///< world offset of the cell it left in its last move
    std::uint64_t movedAtStep = 0;  ///< step number of its last move (0 = never moved)
    bool operator==(const PlaceRecord&) const = default;
};
static_assert(sizeof(PlaceRecord) == 16, "four records a cache line, none across two");

/// One grid's fall states, indexed by grain id (huge pages: read at random by id).
using FallStates = std::vector<FallState, LargePageAllocator<FallState>>;

/// Every grain's place, last move and look, one array per field except the place record (ids index all of them).
struct GrainStore {
    std::vector<GridLevel> level;            ///< grid holding the grain
    std::vector<PlaceRecord, LargePageAllocator<PlaceRecord>> place; ///< its cell, last move and the step of that move
    std::vector<std::uint32_t> identity;     ///< stable per grain: picks its jitter and pattern
    std::vector<std::uint32_t> color;        ///< RGBA8 (R in the low byte); 0 = the default sand colours
    /// granular: how each grain falls (classic keeps them at rest; no display effect), one array
    /// per grid indexed by GridLevel, each indexed by id: a grain's state is in its own grid's
    /// array (fallOf), the other array's entry means nothing. The two grids are swept side by
    /// side, and with one array their threads would keep writing the same cache lines.
    std::array<FallStates, 2> fall;
    /// A grain's fall state, in the array of the grid that holds it.
    FallState& fallOf(std::uint32_t id) { return fall[std::size_t(level[id])][id]; }
    const FallState& fallOf(std::uint32_t id) const { return fall[std::size_t(level[id])][id]; } ///< as above

    std::uint32_t size() const { return std::uint32_t(place.size()); } ///< number of grains
    void clear();                                                      ///< removes every grain
    void reserve(std::uint32_t count); ///< room for count grains without reallocating
    /// Writes a move into grain id's record: the cell it entered, the offset back to the one it
    /// left, and the step it moved in (what the display glides from).
    void recordMove(std::uint32_t id, std::uint32_t to, MoveCode back, std::uint64_t step) {
        place[id] = {to, back, step};
    }
    /// Appends a grain and returns its id.
    std::uint32_t add(GridLevel where, std::uint32_t cellIndex, std::uint32_t grainIdentity, std::uint32_t rgba);
    /// Moves the last grain into id (dropping id's record); returns the id the last grain had.
    std::uint32_t removeBySwap(std::uint32_t id);
};

} // namespace sandcore
