// SPDX-License-Identifier: MIT
#include "view/render/grain_instances.hpp"

#include "sandcore/display_positions.hpp"
#include "sandcore/inner_grains.hpp"
#include "sandcore/normals.hpp"

#include <algorithm>
#include <cmath>

namespace sandglass {

namespace {
std::uint32_t packComponent(float value) {
    const int quantised = int(std::lround(std::clamp(value, -1.0f, 1.0f) * 511.0f));
    return std::uint32_t(quantised) & 0x3ffu;
}
float unpackComponent(std::uint32_t bits) {
    const int value = (bits & 0x200u) ? int(bits) - 1024 : int(bits);
    return std::max(float(value) / 511.0f, -1.0f);
}
} // namespace

std::uint32_t drawnGrainColor(const sandcore::GrainStore& grains, std::uint32_t id, SandPalette palette) {
    if (grains.color[id] != 0) return grains.color[id];
    const std::uint32_t grainsPerBand = std::max(grains.size() / 6, 1u);
    return layerColor(palette, grains.identity[id], grainsPerBand);
}

std::uint32_t packNormal(sandcore::Vec3 normal) {
    return packComponent(normal.x) | (packComponent(normal.y) << 10) | (packComponent(normal.z) << 20);
}

sandcore::Vec3 unpackNormal(std::uint32_t packed) {
    return {unpackComponent(packed & 0x3ffu), unpackComponent((packed >> 10) & 0x3ffu),
            unpackComponent((packed >> 20) & 0x3ffu)};
}

void GrainInstanceBuilder::refreshCache(const sandcore::Scene& scene, const RenderSettings& settings) {
    const std::size_t count = scene.grains().size();
    inner_.resize(count);
    innerCount_ = sandcore::flagInnerGrains(scene, inner_);
    packedNormals_.resize(count);
    if (settings.lighting) {
        normals_.resize(count);
        sandcore::estimateGrainNormals(scene, settings.normals, normals_);
        for (std::size_t i = 0; i < count; ++i) packedNormals_[i] = packNormal(normals_[i]);
    } else {
        // Unlit frames never read normals: skip the estimate, which costs more than the upload.
        std::fill(packedNormals_.begin(), packedNormals_.end(), packNormal({0.0f, 1.0f, 0.0f}));
    }
    // Ambient occlusion: each grain's occupied neighbours, as the upkeep and the GPU count them.
    occlusion_.assign(count, 0);
    if (grainOcclusion(settings)) {
        const sandcore::GrainStore& grains = scene.grains();
        for (std::uint32_t id = 0; id < count; ++id)
            occlusion_[id] = std::uint8_t(sandcore::occlusionLevel(
                sandcore::occupiedNeighbours(scene.grid(grains.level[id]), grains.place[id].cell)));
    }
    cachedMethod_ = settings.normals;
    cachedWithNormals_ = settings.lighting;
    cachedWithOcclusion_ = grainOcclusion(settings);
    cacheValid_ = true;
}

std::span<const GrainInstance> GrainInstanceBuilder::build(const sandcore::Scene& scene, float stepFraction,
                                                           const RenderSettings& settings) {
    const std::size_t count = scene.grains().size();
    const bool normalsStale = (settings.lighting && (!cachedWithNormals_ || cachedMethod_ != settings.normals)) ||
                              grainOcclusion(settings) != cachedWithOcclusion_;
    if (!cacheValid_ || normalsStale || inner_.size() != count) refreshCache(scene, settings);

    positions_.resize(count);
    sandcore::writeDisplayPositions(scene, stepFraction, {settings.cellSize, settings.jitter}, positions_);
    const sandcore::GrainStore& grains = scene.grains();
    instances_.resize(count);
    std::size_t written = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!settings.innerGrains && inner_[i]) continue;
        GrainInstance& out = instances_[written++];
        out.x = positions_[i].x;
        out.y = positions_[i].y;
        out.z = positions_[i].z;
        out.normal = packedNormals_[i];
        out.identity = grains.identity[i];
        out.color = drawnGrainColor(grains, std::uint32_t(i), settings.palette);
        out.occlusion = occlusion_[i];
    }
    builtCount_ = written;
    return {instances_.data(), written};
}

} // namespace sandglass
