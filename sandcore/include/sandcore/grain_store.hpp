#pragma once
// Per-grain records (structure of arrays), indexed by grain id. Ids are dense: [0, size()).
// Removing a grain moves the last grain into the freed id, so arrays stay packed for drawing.

#include <cstdint>
#include <vector>

namespace sandcore {

/// Which of a scene's two grids a cell belongs to (R4).
enum class GridLevel : std::uint8_t {
    Lower = 0, ///< the lower grid (lower bulb, sculpture floor box, painting box)
    Upper = 1, ///< the upper grid (upper bulb, sculpture, release layer)
};

/// The offset of the previous cell from the current one, packed as (dx+1) + 3(dy+1) + 9(dz+1).
using MoveCode = std::uint8_t;
inline constexpr MoveCode kNoMove = 13; ///< dx = dy = dz = 0

/// Packs a cell offset with components in {-1, 0, 1}.
constexpr MoveCode packMove(int dx, int dy, int dz) { return MoveCode((dx + 1) + 3 * (dy + 1) + 9 * (dz + 1)); }
constexpr int moveDx(MoveCode m) { return m % 3 - 1; }       ///< x component of a packed offset
constexpr int moveDy(MoveCode m) { return (m / 3) % 3 - 1; } ///< y component of a packed offset
constexpr int moveDz(MoveCode m) { return m / 9 - 1; }       ///< z component of a packed offset

/// Every grain's place, last move and look, one array per field (ids index all of them).
struct GrainStore {
    std::vector<GridLevel> level;            ///< grid holding the grain
    std::vector<std::uint32_t> cell;         ///< cell index in that grid
    std::vector<MoveCode> cameFrom;          ///< world offset of the cell it left in its last move
    std::vector<std::uint64_t> movedAtStep;  ///< step number of its last move (0 = never moved)
    std::vector<std::uint32_t> identity;     ///< stable per grain: picks its jitter and pattern
    std::vector<std::uint32_t> color;        ///< RGBA8 (R in the low byte); 0 = the default sand colours

    std::uint32_t size() const { return std::uint32_t(cell.size()); } ///< number of grains
    void clear();                                                      ///< removes every grain
    /// Appends a grain and returns its id.
    std::uint32_t add(GridLevel where, std::uint32_t cellIndex, std::uint32_t grainIdentity, std::uint32_t rgba);
    /// Moves the last grain into id (dropping id's record); returns the id the last grain had.
    std::uint32_t removeBySwap(std::uint32_t id);
};

} // namespace sandcore
