// SPDX-License-Identifier: MIT
#pragma once
// The per-grain records the GPU draws from (SPEC V1): one array per frame, uploaded in one
// buffer update. The simulation's answers (R8 positions, R12 normals, R13 inner flags) are
// packed here; nothing in this file decides how sand moves.

#include "view/render/render_settings.hpp"

#include "sandcore/scene.hpp"
#include "sandcore/vec3.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace sandglass {

/// One grain as the vertex shader reads it (24 bytes, tightly packed).
struct GrainInstance {
    float x = 0, y = 0, z = 0;     ///< R8 display position, world units
    std::uint32_t normal = 0;      ///< unit normal packed as signed 10:10:10:2 (GL_INT_2_10_10_10_REV)
    std::uint32_t identity = 0;    ///< stable grain identity: picks the sand pattern
    std::uint32_t color = 0;       ///< RGBA8 (R low byte); 0 = the pattern's sand colours
    std::uint32_t occlusion = 0;   ///< sandcore::occlusionLevel of its occupied neighbours (0 without occlusion)
};
static_assert(sizeof(GrainInstance) == 28);

/// The colour grain `id` is drawn in, on either grain path (RGBA8, 0 = its pattern's sand colours):
/// its own colour where it has one (painted, loaded), else under the layers palette (S12) the band
/// of its identity, six bands over the scene's grains (the hourglass fills from the bottom up).
std::uint32_t drawnGrainColor(const sandcore::GrainStore& grains, std::uint32_t id, SandPalette palette);

/// Packs a unit vector into signed normalised 10:10:10:2 (x in the low bits).
std::uint32_t packNormal(sandcore::Vec3 normal);
/// Unpacks packNormal's result (for tests).
sandcore::Vec3 unpackNormal(std::uint32_t packed);

/// Builds the instance array of a scene, reusing its storage between frames. Normals and
/// inner flags only change when grains move, so they are recomputed only after a step.
class GrainInstanceBuilder {
public:
    /// Marks the cached normals and inner flags stale (call after a step, reset or edit).
    void sceneChanged() { cacheValid_ = false; }
    /// Fills instances for the scene at stepFraction (0..1) of the current step; skips inner
    /// grains unless settings.innerGrains. Returns the instances to draw.
    std::span<const GrainInstance> build(const sandcore::Scene& scene, float stepFraction,
                                         const RenderSettings& settings);
    /// The instances the last build returned (empty before the first).
    std::span<const GrainInstance> lastBuilt() const { return {instances_.data(), builtCount_}; }
    /// Inner grains counted by the last build that refreshed the cache.
    std::int64_t innerGrainCount() const { return innerCount_; }

private:
    void refreshCache(const sandcore::Scene& scene, const RenderSettings& settings);

    std::vector<sandcore::Vec3> positions_;
    std::vector<sandcore::Vec3> normals_;
    std::vector<std::uint32_t> packedNormals_;
    std::vector<std::uint8_t> inner_;
    std::vector<GrainInstance> instances_;
    std::size_t builtCount_ = 0;
    std::int64_t innerCount_ = 0;
    bool cacheValid_ = false;
    sandcore::NormalMethod cachedMethod_ = sandcore::NormalMethod::ColumnHeights;
    bool cachedWithNormals_ = false;
    bool cachedWithOcclusion_ = false;
    std::vector<std::uint8_t> occlusion_; // per grain: its occlusion level (when occluded)
};

} // namespace sandglass
