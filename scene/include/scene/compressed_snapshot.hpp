// SPDX-License-Identifier: MIT
#pragma once
// SPEC E3: a scene's state kept small, so the undo and redo history hold many more strokes in the
// same memory. A 256-wide canvas is 55 MB of cells, nearly all EMPTY or INVALID; but every cell
// follows from the scene's layouts, its obstacles and its grains (a grain's cell names it, an
// obstacle's cells are INVALID, every other cell is as laid out), so only the grain records,
// obstacles and counters are kept, zstd-compressed, and the grids are rebuilt on expand().

#include "sandcore/scene.hpp"

#include <cstdint>
#include <vector>

namespace sandglass {

/// A scene's whole state, compressed; expand() gives back exactly Scene::snapshot() of the time.
class CompressedSnapshot {
public:
    /// The scene's current state (grains, obstacles, counters), compressed with zstd.
    explicit CompressedSnapshot(const sandcore::Scene& scene);
    /// The snapshot as it was taken, its grids rebuilt from `scene`'s layouts: pass the same
    /// scene (or one built the same way). Scene::restore takes it.
    sandcore::SceneSnapshot expand(const sandcore::Scene& scene) const;
    /// Memory the compressed form uses, bytes.
    std::size_t bytes() const { return compressed_.capacity(); }
    /// Bytes of the state before compression.
    std::uint64_t rawBytes() const { return rawBytes_; }

private:
    std::vector<std::uint8_t> compressed_;
    std::uint64_t rawBytes_ = 0;
};

} // namespace sandglass
