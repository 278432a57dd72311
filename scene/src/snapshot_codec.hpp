#pragma once
// A SceneSnapshot as bytes: shared by the state file (E1) and the compressed undo history (E3).

#include "byte_codec.hpp"

#include "sandcore/scene.hpp"

namespace sandglass {

/// Appends every field of the snapshot.
void writeSnapshot(ByteWriter& out, const sandcore::SceneSnapshot& snapshot);

/// Reads a snapshot written by writeSnapshot. Sizes are checked (grid sizes valid, arrays no
/// longer than the input) but not the content: see requireConsistentSnapshot. Throws FormatError.
sandcore::SceneSnapshot readSnapshot(ByteReader& in);

/// Throws FormatError unless the snapshot fits layouts of its grids' sizes and is consistent:
/// every grain lies in an EMPTY layout cell that names it, every cell naming a grain is named
/// by it, counters match, move codes are valid. A snapshot that passes cannot make a step fail.
void requireConsistentSnapshot(const sandcore::SceneSnapshot& snapshot, const sandcore::CellGrid& upperLayout,
                               const sandcore::CellGrid& lowerLayout);

/// Bytes writeSnapshot appends for this snapshot (to reserve once).
std::size_t encodedSnapshotBytes(const sandcore::SceneSnapshot& snapshot);

} // namespace sandglass
