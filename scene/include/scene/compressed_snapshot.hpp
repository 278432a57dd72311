#pragma once
// SPEC E3: a SceneSnapshot kept zstd-compressed, so the undo and redo history hold many more
// strokes in the same memory (a 256-wide canvas is 55 MB raw, mostly EMPTY cells).

#include "sandcore/scene.hpp"

#include <cstdint>
#include <vector>

namespace sandglass {

/// A scene's whole state, compressed; expand() gives back exactly what was compressed.
class CompressedSnapshot {
public:
    /// Compresses a snapshot (zstd, the state file's codec).
    explicit CompressedSnapshot(const sandcore::SceneSnapshot& snapshot);
    /// The snapshot as it was taken.
    sandcore::SceneSnapshot expand() const;
    /// Memory the compressed form uses, bytes.
    std::size_t bytes() const { return compressed_.capacity(); }
    /// Bytes of the snapshot before compression (its encoded size).
    std::uint64_t rawBytes() const { return rawBytes_; }

private:
    std::vector<std::uint8_t> compressed_;
    std::uint64_t rawBytes_ = 0;
};

} // namespace sandglass
