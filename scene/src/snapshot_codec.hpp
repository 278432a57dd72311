// SPDX-License-Identifier: MIT
#pragma once
// A SceneSnapshot as bytes: shared by the state file (E1) and the compressed undo history (E3).

#include "byte_codec.hpp"

#include "sandcore/scene.hpp"

namespace sandglass {

/// Appends every field of the scene's snapshot (what Scene::snapshot() holds), read straight
/// from the scene without copying its grids first.
void writeSnapshot(ByteWriter& out, const sandcore::Scene& scene);

/// Every per-grain array of the scene's GrainStore, in one order; shared by state files and undo
/// snapshots. The fall states are written as Scene::fallOf reads them, up to date (a sleeping
/// fall keeps its state in the store as of an earlier step).
void writeGrains(ByteWriter& out, const sandcore::Scene& scene);
/// Reads what writeGrains wrote; throws FormatError when the data ends early or the arrays disagree.
sandcore::GrainStore readGrains(ByteReader& in);

/// Reads what writeSnapshot wrote. Sizes are checked (grid sizes valid, arrays no
/// longer than the input) but not the content: see requireConsistentSnapshot. Throws FormatError.
sandcore::SceneSnapshot readSnapshot(ByteReader& in);

/// Throws FormatError unless the snapshot fits layouts of its grids' sizes and is consistent:
/// every grain lies in an EMPTY layout cell that names it, every cell naming a grain is named
/// by it, counters match, move codes are valid. A snapshot that passes cannot make a step fail.
void requireConsistentSnapshot(const sandcore::SceneSnapshot& snapshot, const sandcore::CellGrid& upperLayout,
                               const sandcore::CellGrid& lowerLayout);

/// Bytes writeSnapshot appends for this scene (to reserve once).
std::size_t encodedSnapshotBytes(const sandcore::Scene& scene);

} // namespace sandglass
