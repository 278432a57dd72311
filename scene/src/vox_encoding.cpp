// SPDX-License-Identifier: MIT
// MagicaVoxel's .vox format (version 150): chunks of id, content size, children size; a MAIN
// chunk holding SIZE/XYZI pairs (one per model, at most 256 cells per axis), the scene graph
// that places the models, and the RGBA palette.
#include "scene/scene_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <string>
#include <unordered_map>

namespace sandglass {

namespace {

constexpr int kTile = 256; // MagicaVoxel's largest model per axis

struct Chunk {
    std::vector<std::uint8_t> bytes;
    void raw(const void* data, std::size_t size) {
        const std::size_t at = bytes.size();
        bytes.resize(at + size);
        if (size > 0) std::memcpy(bytes.data() + at, data, size);
    }
    void u32(std::uint32_t v) { raw(&v, 4); } // little-endian machines only, like the state file
    void i32(std::int32_t v) { u32(std::uint32_t(v)); }
    void text(const std::string& s) {
        u32(std::uint32_t(s.size()));
        raw(s.data(), s.size());
    }
    void dictionary(const std::vector<std::pair<std::string, std::string>>& entries) {
        u32(std::uint32_t(entries.size()));
        for (const auto& [key, value] : entries) {
            text(key);
            text(value);
        }
    }
};

void appendChunk(std::vector<std::uint8_t>& out, const char id[4], const Chunk& content) {
    Chunk header;
    header.raw(id, 4);
    header.u32(std::uint32_t(content.bytes.size()));
    header.u32(0);
    header.raw(content.bytes.data(), content.bytes.size());
    out.insert(out.end(), header.bytes.begin(), header.bytes.end());
}

struct Box {
    std::size_t begin, end; // range of entries
};

} // namespace

std::vector<std::uint8_t> quantiseColors(const std::vector<std::uint32_t>& colors, const std::vector<std::uint64_t>& counts,
                                         std::array<std::uint32_t, 256>& palette) {
    palette.fill(0);
    std::vector<std::uint8_t> indexOf(colors.size(), 1);
    if (colors.empty()) return indexOf;
    const auto channel = [](std::uint32_t c, int k) { return int((c >> (8 * k)) & 255u); };
    std::vector<std::size_t> order(colors.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    // Median cut: split the box with the widest channel range at its count-weighted median until
    // there are 255 boxes (or every box holds one colour).
    std::vector<Box> boxes{{0, order.size()}};
    const auto widest = [&](const Box& box, int& which) {
        int best = -1;
        for (int k = 0; k < 3; ++k) {
            int lo = 255, hi = 0;
            for (std::size_t i = box.begin; i < box.end; ++i) {
                lo = std::min(lo, channel(colors[order[i]], k));
                hi = std::max(hi, channel(colors[order[i]], k));
            }
            if (hi - lo > best) {
                best = hi - lo;
                which = k;
            }
        }
        return best;
    };
    while (boxes.size() < 255) {
        int splitAt = -1, channelOf = 0, bestRange = 0;
        for (std::size_t b = 0; b < boxes.size(); ++b) {
            if (boxes[b].end - boxes[b].begin < 2) continue;
            int k = 0;
            const int range = widest(boxes[b], k);
            if (range > bestRange) {
                bestRange = range;
                splitAt = int(b);
                channelOf = k;
            }
        }
        if (splitAt < 0) break;
        Box& box = boxes[std::size_t(splitAt)];
        std::sort(order.begin() + std::ptrdiff_t(box.begin), order.begin() + std::ptrdiff_t(box.end),
                  [&](std::size_t a, std::size_t b) { return channel(colors[a], channelOf) < channel(colors[b], channelOf); });
        std::uint64_t total = 0, running = 0;
        for (std::size_t i = box.begin; i < box.end; ++i) total += counts[order[i]];
        std::size_t middle = box.begin + 1;
        for (std::size_t i = box.begin; i + 1 < box.end; ++i) {
            running += counts[order[i]];
            middle = i + 1;
            if (2 * running >= total) break;
        }
        const Box upper{middle, box.end};
        box.end = middle;
        boxes.push_back(upper);
    }
    for (std::size_t b = 0; b < boxes.size(); ++b) {
        double sum[3] = {0, 0, 0}, weight = 0;
        for (std::size_t i = boxes[b].begin; i < boxes[b].end; ++i) {
            const double w = double(std::max<std::uint64_t>(counts[order[i]], 1));
            for (int k = 0; k < 3; ++k) sum[k] += w * channel(colors[order[i]], k);
            weight += w;
            indexOf[order[i]] = std::uint8_t(b + 1);
        }
        std::uint32_t rgba = 0xff000000u;
        for (int k = 0; k < 3; ++k) rgba |= std::uint32_t(std::lround(sum[k] / weight)) << (8 * k);
        palette[b + 1] = rgba;
    }
    return indexOf;
}

std::vector<std::uint8_t> encodeVox(const VoxelVolume& volume) {
    const sandcore::Int3 s = volume.size;
    // MagicaVoxel is z up and right-handed: (x, y, z) here is (x, size.z - 1 - z, y) there.
    const int voxX = s.x, voxY = s.z, voxZ = s.y;
    struct Model {
        int x0, y0, z0, sx, sy, sz;
        Chunk xyzi;
        std::uint32_t count = 0;
    };
    std::vector<Model> models;
    for (int z0 = 0; z0 < voxZ; z0 += kTile)
        for (int y0 = 0; y0 < voxY; y0 += kTile)
            for (int x0 = 0; x0 < voxX; x0 += kTile) {
                Model m{x0, y0, z0, std::min(kTile, voxX - x0), std::min(kTile, voxY - y0), std::min(kTile, voxZ - z0), {}, 0};
                for (int z = 0; z < m.sz; ++z)
                    for (int y = 0; y < m.sy; ++y)
                        for (int x = 0; x < m.sx; ++x) {
                            const int cx = x0 + x, cz = s.z - 1 - (y0 + y), cy = z0 + z;
                            const std::uint8_t index =
                                volume.index[std::size_t(cx) + std::size_t(s.x) * (std::size_t(cz) + std::size_t(s.z) * std::size_t(cy))];
                            if (index == 0) continue;
                            m.xyzi.bytes.insert(m.xyzi.bytes.end(), {std::uint8_t(x), std::uint8_t(y), std::uint8_t(z), index});
                            ++m.count;
                        }
                if (m.count > 0) models.push_back(std::move(m));
            }
    if (models.empty()) models.push_back({0, 0, 0, 1, 1, 1, {}, 0}); // MagicaVoxel needs one model
    Chunk children;
    std::vector<std::uint8_t> body;
    for (const Model& m : models) {
        Chunk size;
        size.i32(m.sx);
        size.i32(m.sy);
        size.i32(m.sz);
        appendChunk(body, "SIZE", size);
        Chunk xyzi;
        xyzi.u32(m.count);
        xyzi.bytes.insert(xyzi.bytes.end(), m.xyzi.bytes.begin(), m.xyzi.bytes.end());
        appendChunk(body, "XYZI", xyzi);
    }
    // Scene graph: root transform 0 -> group 1 -> per model a transform (2 + 2m) -> shape (3 + 2m).
    // MagicaVoxel centres a model on its translation (at size / 2, rounded down), so each tile's
    // translation is its corner plus half its size.
    Chunk root;
    root.i32(0);
    root.dictionary({});
    root.i32(1);
    root.i32(-1);
    root.i32(-1);
    root.u32(1);
    root.dictionary({});
    appendChunk(body, "nTRN", root);
    Chunk group;
    group.i32(1);
    group.dictionary({});
    group.u32(std::uint32_t(models.size()));
    for (std::size_t m = 0; m < models.size(); ++m) group.i32(int(2 + 2 * m));
    appendChunk(body, "nGRP", group);
    for (std::size_t m = 0; m < models.size(); ++m) {
        const Model& model = models[m];
        Chunk transform;
        transform.i32(int(2 + 2 * m));
        transform.dictionary({});
        transform.i32(int(3 + 2 * m));
        transform.i32(-1);
        transform.i32(0);
        transform.u32(1);
        transform.dictionary({{"_t", std::to_string(model.x0 + model.sx / 2) + " " + std::to_string(model.y0 + model.sy / 2) +
                                          " " + std::to_string(model.z0 + model.sz / 2)}});
        appendChunk(body, "nTRN", transform);
        Chunk shape;
        shape.i32(int(3 + 2 * m));
        shape.dictionary({});
        shape.u32(1);
        shape.i32(int(m));
        shape.dictionary({});
        appendChunk(body, "nSHP", shape);
    }
    Chunk rgba;
    for (int i = 1; i <= 256; ++i) rgba.u32(i < 256 ? volume.palette[std::size_t(i)] : 0u);
    appendChunk(body, "RGBA", rgba);

    Chunk file;
    file.bytes = {'V', 'O', 'X', ' '};
    file.u32(150);
    file.bytes.insert(file.bytes.end(), {'M', 'A', 'I', 'N'});
    file.u32(0);
    file.u32(std::uint32_t(body.size()));
    file.bytes.insert(file.bytes.end(), body.begin(), body.end());
    return std::move(file.bytes);
}

} // namespace sandglass
