#include "scene/compressed_snapshot.hpp"

#include "byte_codec.hpp"
#include "compression.hpp"
#include "snapshot_codec.hpp"

namespace sandglass {

namespace {
// Undo snapshots are taken when a stroke begins, so speed matters more than the last percent.
constexpr int kUndoCompressionLevel = 1;
} // namespace

CompressedSnapshot::CompressedSnapshot(const sandcore::SceneSnapshot& snapshot) {
    ByteWriter out;
    writeSnapshot(out, snapshot);
    rawBytes_ = out.bytes().size();
    compressed_ = compressBytes(out.bytes(), kUndoCompressionLevel);
}

sandcore::SceneSnapshot CompressedSnapshot::expand() const {
    const std::vector<std::uint8_t> raw = decompressBytes(compressed_, rawBytes_);
    ByteReader in(raw);
    return readSnapshot(in);
}

} // namespace sandglass
