// SPDX-License-Identifier: MIT
#pragma once
// A small MagicaVoxel (.vox) reader for the export tests, written from the format's description,
// independent of the writer: models (SIZE + XYZI), the scene graph's translations (nTRN "_t" over
// nSHP) and the palette (RGBA). Returns filled cells in MagicaVoxel's own coordinates (z up).

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace support {

struct VoxFile {
    std::map<std::tuple<int, int, int>, std::uint8_t> voxels; ///< world position (x, y, z up) -> palette index
    std::array<std::uint32_t, 256> palette{};                  ///< RGBA8 of index i at palette[i]
    int models = 0;                                            ///< SIZE/XYZI pairs
    int largestModelSide = 0;                                  ///< cells, should be <= 256
};

inline VoxFile readVox(const std::vector<std::uint8_t>& bytes) {
    std::size_t at = 0;
    const auto need = [&](std::size_t n) {
        if (at + n > bytes.size()) throw std::runtime_error("vox: ends early");
    };
    const auto u32 = [&] {
        need(4);
        std::uint32_t v;
        std::memcpy(&v, bytes.data() + at, 4);
        at += 4;
        return v;
    };
    const auto id = [&] {
        need(4);
        std::string s(reinterpret_cast<const char*>(bytes.data() + at), 4);
        at += 4;
        return s;
    };
    const auto text = [&] {
        const std::uint32_t n = u32();
        need(n);
        std::string s(reinterpret_cast<const char*>(bytes.data() + at), n);
        at += n;
        return s;
    };
    const auto dictionary = [&] {
        std::map<std::string, std::string> d;
        const std::uint32_t n = u32();
        for (std::uint32_t i = 0; i < n; ++i) {
            std::string key = text();
            d[key] = text();
        }
        return d;
    };
    if (id() != "VOX ") throw std::runtime_error("vox: no signature");
    if (u32() != 150) throw std::runtime_error("vox: not version 150");
    if (id() != "MAIN") throw std::runtime_error("vox: no MAIN chunk");
    u32();
    const std::uint32_t children = u32();
    const std::size_t end = at + children;
    struct Model {
        int sx, sy, sz;
        std::vector<std::array<std::uint8_t, 4>> cells;
    };
    std::vector<Model> models;
    std::map<int, std::array<int, 3>> translation; // transform node -> _t
    std::map<int, int> childOf;                    // transform node -> child node
    std::map<int, int> modelOfShape;               // shape node -> model id
    VoxFile out;
    while (at < end) {
        const std::string chunk = id();
        const std::uint32_t content = u32();
        u32();
        const std::size_t next = at + content;
        need(content);
        if (chunk == "SIZE") {
            Model m;
            m.sx = int(u32());
            m.sy = int(u32());
            m.sz = int(u32());
            models.push_back(m);
            out.largestModelSide = std::max({out.largestModelSide, m.sx, m.sy, m.sz});
        } else if (chunk == "XYZI") {
            const std::uint32_t n = u32();
            for (std::uint32_t i = 0; i < n; ++i) {
                need(4);
                models.back().cells.push_back({bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]});
                at += 4;
            }
        } else if (chunk == "nTRN") {
            const int node = int(u32());
            dictionary();
            childOf[node] = int(u32());
            u32();
            u32();
            const std::uint32_t frames = u32();
            std::array<int, 3> t{0, 0, 0};
            for (std::uint32_t f = 0; f < frames; ++f) {
                auto d = dictionary();
                if (d.count("_t")) std::sscanf(d["_t"].c_str(), "%d %d %d", &t[0], &t[1], &t[2]);
            }
            translation[node] = t;
        } else if (chunk == "nSHP") {
            const int node = int(u32());
            dictionary();
            const std::uint32_t count = u32();
            for (std::uint32_t i = 0; i < count; ++i) {
                modelOfShape[node] = int(u32());
                dictionary();
            }
        } else if (chunk == "RGBA") {
            for (int i = 1; i <= 256; ++i) {
                const std::uint32_t c = u32();
                if (i < 256) out.palette[std::size_t(i)] = c;
            }
        }
        at = next;
    }
    out.models = int(models.size());
    // Each transform whose child is a shape places that shape's model, centred on _t.
    for (const auto& [node, child] : childOf) {
        const auto shape = modelOfShape.find(child);
        if (shape == modelOfShape.end()) continue;
        const Model& m = models.at(std::size_t(shape->second));
        const auto t = translation[node];
        for (const auto& c : m.cells)
            out.voxels[{t[0] + c[0] - m.sx / 2, t[1] + c[1] - m.sy / 2, t[2] + c[2] - m.sz / 2}] = c[3];
    }
    return out;
}

} // namespace support
