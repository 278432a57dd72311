// SPDX-License-Identifier: MIT
#pragma once
// Draws a scene's sand and hull with OpenGL 3.3 (SPEC V1-V6). All per-grain work runs in the
// vertex shader: the grains go up in one buffer update per frame (none when nothing moved) and
// are drawn with one instanced call, k sub-grains per instance.

#include "view/camera.hpp"
#include "view/render/body_surfaces.hpp"
#include "view/render/draft_overlay.hpp"
#include "view/render/gl_objects.hpp"
#include "view/render/gpu_frame_timer.hpp"
#include "view/render/grain_gpu_store.hpp"
#include "view/render/grain_instances.hpp"
#include "view/render/model_surfaces.hpp"
#include "view/render/render_settings.hpp"
#include "view/render/studio_look.hpp"

#include "sandcore/scene.hpp"
#include "sandcore/surface_upkeep.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace sandglass {

/// What the last frame drew.
struct RenderStats {
    std::int64_t grainsDrawn = 0;   ///< grain instances (inner grains skipped when hidden)
    std::int64_t subGrainsDrawn = 0; ///< grainsDrawn * grains per cell
    std::int64_t innerGrains = 0;   ///< grains hidden by their 6 neighbours (R13)
    bool uploaded = false;          ///< the grain buffer was updated this frame
    bool fullUpload = false;        ///< everything went up (new scene, edit, settings), not just changes
    std::int64_t uploadBytes = 0;   ///< bytes sent to the GPU for the grains this frame
    double uploadMilliseconds = 0;  ///< CPU time of this frame's grain upload (preparation and GL calls)
    /// This thread's CPU time inside the draw calls: with a software GL that is the driver's vertex
    /// processing, not the application's; a frame's CPU time less this is what the application spent.
    double drawCallCpuMilliseconds = 0;
};


class SceneRenderer {
public:
    /// Loads the shaders from a folder and makes the pattern textures; needs a current GL 3.3
    /// context. Throws std::runtime_error with one line on a shader problem.
    explicit SceneRenderer(const std::filesystem::path& shaderFolder);

    /// Takes a new scene of `kind`: rebuilds the hull mesh and forgets cached grain data. With a model
    /// drawing (S10) the vessel is drawn as modelled instead of the voxel hull, unless the
    /// settings ask for the voxel hull; the drawing is mirrored when the scene is turned over.
    void setScene(const sandcore::Scene& scene, sandcore::SceneKind kind, float cellSize,
                  const ModelDrawing* drawing = nullptr);
    /// True when the hull was built with exactly the scene's obstacles (same boxes, same order,
    /// both grids); after an edit that may have changed them, false means setScene is due.
    bool hullShowsObstaclesOf(const sandcore::Scene& scene) const;
    /// The scene's grains changed in a way the surface upkeep does not show (without a surface
    /// from useSurface: any change): everything goes up again at the next draw.
    void sceneChanged();
    /// The flags and normals to draw with, kept by the scene's owner step by step (SceneHost);
    /// the renderer uploads what it lists as changed and clears its changes. A different
    /// surface than before means everything goes up. Without one, the renderer keeps its own,
    /// rebuilt after every sceneChanged().
    void useSurface(sandcore::SurfaceUpkeep* surface);
    /// Every grain's display position as the GPU path's vertex shader computes it at stepFraction,
    /// read back by transform feedback (uploads first, as a draw would). For tests of R8 on the GPU.
    std::vector<sandcore::Vec3> captureGpuPositions(const sandcore::Scene& scene, float stepFraction,
                                                    const RenderSettings& settings);
    /// As captureGpuPositions without uploading: what the GPU holds since the last draw.
    std::vector<sandcore::Vec3> readBackGpuPositions(const sandcore::Scene& scene, float stepFraction,
                                                     const RenderSettings& settings) const;
    /// The GPU's copy of the grains (GpuInterpolated).
    const GrainGpuStore& gpuStore() const { return gpuStore_; }

    /// Clears the bound framebuffer (width x height pixels) and draws the scene at stepFraction
    /// of the current step. pixelScale multiplies point sizes (HiDPI content scale).
    void draw(const sandcore::Scene& scene, float stepFraction, const RenderSettings& settings,
              const OrbitCamera& camera, int width, int height, float pixelScale);

    const RenderStats& stats() const { return stats_; } ///< what the last draw did
    /// Triangles of the moving bodies' meshes as the last draw drew them.
    std::int64_t bodyTriangles() const { return bodies_.triangles(); }
    /// Times every later draw() on the GPU (timer queries), until switched off; the benchmarks do.
    void timeGpu(bool on) { timeGpu_ = on; }
    /// The GPU time of the draws timed since the last call (waits for those still running).
    GpuTime takeGpuTime() { return gpuTimer_.take(); }
    /// The grain instances in the GPU buffer now, as the last upload sent them.
    std::span<const GrainInstance> uploadedInstances() const { return builder_.lastBuilt(); }

    /// P5: the draft image drawn over the canvas (uploaded once per image).
    void setDraftImage(const DraftImage& image) { draft_.setImage(image); }
    /// P5: where the draft lies and how opaque; drawn by every later draw() while visible.
    void setDraftPlacement(const DraftPlacement& placement) { draftPlacement_ = placement; }

private:
    void uploadGrains(const sandcore::Scene& scene, float stepFraction, const RenderSettings& settings);
    void uploadGpuGrains(const sandcore::Scene& scene, const RenderSettings& settings);
    /// Sets the GPU path's uniforms, binds its grains; returns the instances to draw.
    std::int64_t setGpuUniforms(const sandcore::Scene& scene, float stepFraction, const RenderSettings& settings) const;
    void drawGrains(const RenderSettings& settings, const OrbitCamera& camera, const float* viewProjection,
                    float pixelScale);
    void drawHull(const RenderSettings& settings, const OrbitCamera& camera, const float* viewProjection);
    /// Renders the key light's shadow map (look_.lightMatrix is set for the frame's shaders).
    void drawShadowMap(const sandcore::Scene& scene, float stepFraction, const RenderSettings& settings, bool modelled);
    void uploadPatternColors(SandPalette palette); // S12: the pattern colours of a palette

    GlProgram grainProgram_, grainGpuProgram_, hullProgram_;
    GlVertexArray grainArray_, hullArray_, lineArray_;
    GlBuffer grainBuffer_, hullBuffer_, lineBuffer_;
    GlBuffer quadCorners_; // indices of the quads' triangles: 0 1 2, 0 2 3 per sub-grain
    ModelSurfaces model_; // S10: the model as modelled
    BodySurfaces bodies_; // the moving bodies as solids
    GlTexture patternOffsets_, patternColors_;
    GrainInstanceBuilder builder_;
    GrainGpuStore gpuStore_;
    GrainPath path_ = GrainPath::GpuInterpolated;
    sandcore::SurfaceUpkeep* surface_ = nullptr; // the owner's; null: ownSurface_
    sandcore::SurfaceUpkeep ownSurface_;
    DraftOverlay draft_;
    DraftPlacement draftPlacement_;
    std::int64_t instanceCount_ = 0;
    std::int64_t hullVertices_ = 0, lineVertices_ = 0;
    std::vector<sandcore::CellBox> hullUpperObstacles_, hullLowerObstacles_; // what the hull shows
    SandPalette patternPalette_ = SandPalette::Desert; // the palette the colour texture holds
    bool grainsStale_ = true;
    RenderSettings uploadedWith_;
    RenderStats stats_;
    GpuFrameTimer gpuTimer_;
    StudioLook look_;      // this frame's lights and switches
    ShadowMap shadowMap_;  // the key light's depth
    bool timeGpu_ = false;
};

} // namespace sandglass
