// SPDX-License-Identifier: MIT
#pragma once
// SPEC V8: the grains as the GPU keeps them between frames, in buffer textures indexed by grain
// id: its cell, grid, last move (cameFrom) and the step of that move (16 bytes, "place"); its
// identity and colour (8 bytes) and jitter (16 bytes), changed only by edits; its surface key
// (4 bytes: gradient normal and occlusion level, when lit by that method or occluded); per column the thesis's column normal (a 2D texture); and
// the list of visible (not inner) grain ids, the instances drawn when inner grains are hidden.
// After a step only what changed goes up: the moved grains' places (taken from the upkeep's list,
// not gathered again from the grain store), the changed entries of the visible list, the changed
// normals. Where the GL maps buffers persistently (MappedBuffer) each is one store into mapped
// memory; else they go up in runs of consecutive entries found in a bitset (no sort), several
// runs through one mapped range. The vertex
// shader (grain_gpu.vert) works out the display position from the place and the step fraction,
// as sandcore::grainDisplayPosition does on the CPU.
//
// From a surface that keeps no per-grain flags (SurfaceTracking::grainFlags off) the store holds
// the cells' occupancy instead, one bit per cell (the upkeep's grain and hide bits of both grids,
// in one buffer texture of 32-bit words): after a step only the words of the cells that changed
// go up, a few thousand where tens of thousands of grains moved, and the vertex shader works out
// each grain's inner flag and gradient normal from them (dropping inner grains itself, so every
// grain is an instance and no visible list is kept). SANDGLASS_GPU_CELL_BITS=0 in the environment
// keeps the per-grain flags instead (to compare the two).

#include "view/render/gl_objects.hpp"
#include "view/render/index_runs.hpp"
#include "view/render/mapped_buffer.hpp"
#include "view/render/render_settings.hpp"

#include "sandcore/scene.hpp"
#include "sandcore/surface_upkeep.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace sandglass {

/// True for the GL_RENDERER strings of renderers that run on the CPU: Mesa's llvmpipe, softpipe
/// and swrast, SwiftShader, and the "Software Rasterizer" / "GDI Generic" fallbacks.
bool isSoftwareRenderer(std::string_view glRenderer);

/// The vertex shader's runs per grain drawn: one per sub-grain, four (the corners) for quads.
int verticesPerGrain(const RenderSettings& settings);

/// Vertices per grain from which a GPU draws hidden inner grains faster from the visible list
/// than from the cell bits, dearer upkeep included (docs/rendering.md, "Which path draws").
inline constexpr int kVisibleListVertices = 8;

/// True when, with inner grains hidden, the visible list (per-grain flags) should serve rather
/// than the cell bits: always on a software GL, whose vertex work runs on the CPU; on a GPU when
/// a grain costs kVisibleListVertices vertex runs or more. From the bits every grain is an
/// instance and runs the vertex shader to find out it is inner (at a million grains 9 in 10
/// are); from the list only the visible ones are instances, but the CPU keeps their flags.
bool hiddenInnerGrainsFromList(bool softwareRenderer, const RenderSettings& settings);

/// A grain's place as the vertex shader reads it (RGBA32UI).
struct GrainPlace {
    std::uint32_t cell = 0;      ///< cell index in its grid
    std::uint32_t level = 0;     ///< 0 lower grid, 1 upper grid
    std::uint32_t cameFrom = 0;  ///< sandcore::MoveCode of its last move
    std::uint32_t movedStep = 0; ///< low 32 bits of the step of its last move
};
static_assert(sizeof(GrainPlace) == 16);

class GrainGpuStore {
public:
    /// Buffers and textures; needs a current GL 3.3 context.
    GrainGpuStore();
    /// After each draw that reads the store (persistently mapped buffers are not written while
    /// the GPU may still read them).
    void drawn() {
        if (persistent_) fence_.drawn();
    }
    /// True when changes are written into persistently mapped buffers (see MappedBuffer).
    bool persistent() const { return persistent_; }

    /// Uploads everything from the scene and its upkeep. Returns the bytes sent.
    std::int64_t uploadAll(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface,
                           const RenderSettings& settings);
    /// Uploads only what the upkeep lists as changed since its last clearChanges(). Returns the bytes sent.
    std::int64_t uploadChanges(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface);
    /// True when uploadChanges can follow the last upload of this surface under these settings
    /// (same grains, same jitter and palette, same kind of surface, the normals the lighting needs already there).
    bool canUpdate(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface, const RenderSettings& settings) const;
    /// False when the scene has more grains than this GL's buffer textures hold (draw another way).
    bool holds(const sandcore::Scene& scene) const { return std::int64_t(scene.grains().size()) <= maxTexels_; }
    /// True when the grains are drawn from the occupancy bits under these settings (then a
    /// surface without per-grain flags will do): the bits of the scene's grids fit in one buffer
    /// texture of this GL, and inner grains are drawn or hiddenInnerGrainsFromList says the bits
    /// serve. SANDGLASS_GPU_CELL_BITS=0 or 1 in the environment when the store is made forces
    /// either path (to compare them).
    bool usesCellBits(const sandcore::Scene& scene, const RenderSettings& settings) const;
    /// True when GL_RENDERER names a renderer that rasterizes on the CPU.
    bool softwareRenderer() const { return softwareRenderer_; }
    /// What a surface must keep for this store to draw under these settings: the bits alone where
    /// they fit (column normals too when lit by that method), else per-grain flags and normals.
    sandcore::SurfaceTracking trackingFor(const sandcore::Scene& scene, const RenderSettings& settings) const;
    /// True when this surface (as kept now) has what drawing under these settings needs.
    bool drawsFrom(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface, const RenderSettings& settings) const;

    /// Binds the buffer textures to units firstUnit.. (places, looks, jitters, gradient normals,
    /// cell bits, the normal of each gradient) and the column normals to columnUnit, and the
    /// vertex array of the visible list (none when the flags come from the bits).
    void bind(int firstUnit, int columnUnit) const;
    std::int64_t grainCount() const { return grainCount_; }                    ///< all grains
    std::int64_t visibleCount() const { return std::int64_t(visible_.size()); } ///< grains not inner
    /// True when the last upload holds the cell bits (the shader works out flags and gradient normals).
    bool flagsFromBits() const { return bitsMode_; }
    /// Word offsets in the cell-bits texture: lower grains, upper grains, lower hides, upper hides.
    const std::array<std::int32_t, 4>& cellBitsOffsets() const { return bitsOffsets_; }
    /// The words of the cell-bits texture as the GL holds them (read back, to check them).
    std::vector<std::uint32_t> readCellBits() const;

private:
    struct BufferTexture {
        MappedBuffer buffer;
        GlTexture texture;
        GLenum format;
    };
    void makeVisibleList(const sandcore::SurfaceUpkeep& surface);
    void setVisible(std::uint32_t grain, bool visible);
    std::int64_t uploadColumns(const sandcore::SurfaceUpkeep& surface);
    std::int64_t writeChanges(const sandcore::SurfaceUpkeep& surface, sandcore::WorkerPool* workers);
    std::int64_t sendChangesInRuns(const sandcore::SurfaceUpkeep& surface);
    void allocate(BufferTexture& texture, std::size_t bytes, const void* data);
    std::int64_t uploadCellBits(const sandcore::SurfaceUpkeep& surface);
    std::int64_t writeCellBitChanges(const sandcore::SurfaceUpkeep& surface, sandcore::WorkerPool* workers);

    bool persistent_ = false;
    DrawFence fence_;
    BufferTexture places_gpu_, looks_gpu_, jitters_gpu_, normals_gpu_;
    BufferTexture cellBits_gpu_;     // lower grains, upper grains, lower hides, upper hides
    BufferTexture gradientTable_gpu_; // packNormal of each gradient key (fixed)
    MappedBuffer visibleBuffer_;
    GlVertexArray visibleArray_;
    GlVertexArray everyGrainArray_;   // no attributes: instances are grain ids
    GlTexture columnNormals_;
    std::int64_t maxTexels_ = 0;
    bool softwareRenderer_ = false;             // GL_RENDERER is a CPU rasterizer (isSoftwareRenderer)
    enum class CellBitsChoice { ByRenderer, WhereTheyFit, Never };
    CellBitsChoice cellBitsChoice_ = CellBitsChoice::ByRenderer; // SANDGLASS_GPU_CELL_BITS unset, 1, 0
    std::int64_t grainCount_ = 0;
    std::vector<std::uint32_t> packedByKey_;    // packNormal of each surface key (the shader's table)
    std::vector<std::uint32_t> packedColumns_;  // column normals as uploaded, texel order
    std::vector<std::uint32_t> visible_;        // ids of the visible grains, as uploaded
    std::vector<std::uint32_t> slotOf_;         // per grain: its index in visible_, or kNotListed
    std::int64_t visibleBytes_ = 0;             // visible-list bytes written since the last upload
    // Without persistent mapping: the buffers' contents as sent, and what to send.
    std::vector<GrainPlace> places_;
    std::vector<std::uint32_t> packedNormals_;  // per grain: its surface key (gradient and occlusion), a texel of the normal table
    IndexRuns changedIds_;                      // places to send: the moved grains
    IndexRuns changedSlots_;                    // entries of visible_ to send
    IndexRuns changedNormals_;                  // gradient normals to send
    IndexRuns changedTexels_;                   // column normals to send, texel order
    std::vector<std::pair<std::uint32_t, std::uint32_t>> runs_; // scratch: runs of one upload
    bool bitsMode_ = false;                     // the last upload holds cell bits, not flags
    std::array<std::int32_t, 4> bitsOffsets_{};  // word offsets of the four bit sets
    std::vector<std::uint32_t> cellBitWords_;   // without persistent mapping: the words as sent
    IndexRuns changedWords_;                    // cell-bit words to send
    bool columnsUploaded_ = false;              // the column normals are there
    int columnsX_ = 0, columnsZ_ = 0;
    float uploadedJitter_ = -1.0f;
    SandPalette uploadedPalette_ = SandPalette::Desert; // the grains' colours depend on it (drawnGrainColor)
    bool gradientUploaded_ = false;
};

} // namespace sandglass
