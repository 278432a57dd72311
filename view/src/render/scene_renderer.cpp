// SPDX-License-Identifier: MIT
#include "view/render/scene_renderer.hpp"

#include "view/render/hull_mesh.hpp"
#include "scene/sand_patterns.hpp"
#include "view/render/shader_program.hpp"
#include "view/render/thread_cpu_clock.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sandglass {

namespace {

GLint uniform(const GlProgram& program, const char* name) { return glGetUniformLocation(program.get(), name); }

void hullAttributes(GLuint vertexArray, GLuint buffer) {
    glBindVertexArray(vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(HullVertex), reinterpret_cast<void*>(0));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(HullVertex),
                          reinterpret_cast<void*>(offsetof(HullVertex, nx)));
}

// Texture units of the GPU path (0 and 1 hold the patterns).
constexpr int kColumnNormalsUnit = 2;
constexpr int kGrainTexturesUnit = 3; // places, looks, jitters, gradient normals, cell bits, normal table

// Display settings whose change invalidates the uploaded grains even when nothing moved.
bool sameGrainInputs(const RenderSettings& a, const RenderSettings& b) {
    return a.innerGrains == b.innerGrains && a.lighting == b.lighting && a.normals == b.normals &&
           a.jitter == b.jitter && a.cellSize == b.cellSize && a.palette == b.palette &&
           grainOcclusion(a) == grainOcclusion(b);
}

} // namespace

SceneRenderer::SceneRenderer(const std::filesystem::path& shaderFolder)
    : grainProgram_(loadShaderProgram(shaderFolder / "grain.vert", shaderFolder / "grain.frag")),
      grainGpuProgram_(loadShaderProgram(shaderFolder / "grain_gpu.vert", shaderFolder / "grain.frag", "displayPosition")),
      hullProgram_(loadShaderProgram(shaderFolder / "hull.vert", shaderFolder / "hull.frag")),
      grainArray_(newVertexArray()), hullArray_(newVertexArray()), lineArray_(newVertexArray()),
      grainBuffer_(newBuffer()), hullBuffer_(newBuffer()), lineBuffer_(newBuffer()), quadCorners_(newBuffer()),
      model_(shaderFolder), bodies_(shaderFolder), patternOffsets_(newTexture()), patternColors_(newTexture()), draft_(shaderFolder) {
    // Per-instance attributes; the vertex shader needs no per-vertex data (it uses gl_VertexID).
    glBindVertexArray(grainArray_.get());
    glBindBuffer(GL_ARRAY_BUFFER, grainBuffer_.get());
    const auto stride = GLsizei(sizeof(GrainInstance));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(GrainInstance, x)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_INT_2_10_10_10_REV, GL_TRUE, stride,
                          reinterpret_cast<void*>(offsetof(GrainInstance, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribIPointer(2, 1, GL_UNSIGNED_INT, stride, reinterpret_cast<void*>(offsetof(GrainInstance, identity)));
    glEnableVertexAttribArray(3);
    glVertexAttribIPointer(3, 1, GL_UNSIGNED_INT, stride, reinterpret_cast<void*>(offsetof(GrainInstance, color)));
    glEnableVertexAttribArray(4);
    glVertexAttribIPointer(4, 1, GL_UNSIGNED_INT, stride, reinterpret_cast<void*>(offsetof(GrainInstance, occlusion)));
    for (GLuint location = 0; location < 5; ++location) glVertexAttribDivisor(location, 1);
    hullAttributes(hullArray_.get(), hullBuffer_.get());
    hullAttributes(lineArray_.get(), lineBuffer_.get());
    glBindVertexArray(0);
    // Billboards and pseudo-billboards draw each sub-grain's quad from 4 corners, not 6 vertices:
    // the two triangles share a diagonal, and an indexed draw lets the GPU reuse its corners.
    std::vector<std::uint16_t> quadCorners;
    for (std::uint16_t k = 0; k < kMaxGrainsPerCell; ++k)
        for (std::uint16_t corner : {0, 1, 2, 0, 2, 3}) quadCorners.push_back(std::uint16_t(4 * k + corner));
    // Filled through the array target: the element target belongs to a vertex array, none is bound here.
    glBindBuffer(GL_ARRAY_BUFFER, quadCorners_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(quadCorners.size() * sizeof(std::uint16_t)), quadCorners.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    // The Scribble patterns as two small textures: 32 sub-grains wide, one row per pattern.
    const std::vector<SandPattern> patterns = makeSandPatterns();
    std::vector<float> offsets;
    for (const SandPattern& pattern : patterns)
        for (std::size_t i = 0; i < pattern.offsets.size(); ++i)
            offsets.insert(offsets.end(), {pattern.offsets[i][0], pattern.offsets[i][1], pattern.offsets[i][2], 0.0f});
    const auto rows = GLsizei(patterns.size());
    glBindTexture(GL_TEXTURE_2D, patternOffsets_.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kMaxGrainsPerCell, rows, 0, GL_RGBA, GL_FLOAT, offsets.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    uploadPatternColors(SandPalette::Desert);

    for (const GlProgram* program : {&grainProgram_, &grainGpuProgram_}) {
        glUseProgram(program->get());
        glUniform1i(uniform(*program, "patternOffsets"), 0);
        glUniform1i(uniform(*program, "patternColors"), 1);
        glUniform1i(uniform(*program, "patternCount"), GLint(patterns.size()));
    }
    glUniform1i(uniform(grainGpuProgram_, "columnNormals"), kColumnNormalsUnit);
    const char* grainTextures[] = {"grainPlaces", "grainLooks", "grainJitters", "grainSurfaceKeys", "cellBits", "gradientNormalTable"};
    for (int i = 0; i < 6; ++i) glUniform1i(uniform(grainGpuProgram_, grainTextures[i]), kGrainTexturesUnit + i);
    glUseProgram(0);
}

void SceneRenderer::uploadPatternColors(SandPalette palette) {
    const std::vector<SandPattern> patterns = makeSandPatterns(kSandPatternCount, palette);
    std::vector<std::uint32_t> colors;
    for (const SandPattern& pattern : patterns) colors.insert(colors.end(), pattern.colors.begin(), pattern.colors.end());
    glBindTexture(GL_TEXTURE_2D, patternColors_.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kMaxGrainsPerCell, GLsizei(patterns.size()), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 colors.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    patternPalette_ = palette;
}

void SceneRenderer::setScene(const sandcore::Scene& scene, sandcore::SceneKind kind, float cellSize,
                             const ModelDrawing* drawing) {
    model_.set(drawing, scene.flipped(), cellSize);
    const HullMesh mesh = buildHullMesh(scene, kind, cellSize);
    hullUpperObstacles_ = scene.obstacles(sandcore::GridLevel::Upper);
    hullLowerObstacles_ = scene.obstacles(sandcore::GridLevel::Lower);
    glBindBuffer(GL_ARRAY_BUFFER, hullBuffer_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.triangles.size() * sizeof(HullVertex)), mesh.triangles.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, lineBuffer_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.lines.size() * sizeof(HullVertex)), mesh.lines.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    hullVertices_ = std::int64_t(mesh.triangles.size());
    lineVertices_ = std::int64_t(mesh.lines.size());
    sceneChanged();
}

bool SceneRenderer::hullShowsObstaclesOf(const sandcore::Scene& scene) const {
    const auto same = [](const std::vector<sandcore::CellBox>& a, const std::vector<sandcore::CellBox>& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const sandcore::CellBox& x, const sandcore::CellBox& y) {
            return x.min == y.min && x.max == y.max;
        });
    };
    return same(scene.obstacles(sandcore::GridLevel::Upper), hullUpperObstacles_) &&
           same(scene.obstacles(sandcore::GridLevel::Lower), hullLowerObstacles_);
}

void SceneRenderer::sceneChanged() {
    builder_.sceneChanged();
    grainsStale_ = true;
}

void SceneRenderer::useSurface(sandcore::SurfaceUpkeep* surface) {
    if (surface != surface_) sceneChanged();
    surface_ = surface;
}


void SceneRenderer::uploadGrains(const sandcore::Scene& scene, float stepFraction, const RenderSettings& settings) {
    stats_.uploaded = false;
    stats_.fullUpload = false;
    stats_.uploadBytes = 0;
    stats_.uploadMilliseconds = 0.0;
    if (path_ == GrainPath::GpuInterpolated) {
        uploadGpuGrains(scene, settings);
        return;
    }
    // The reference path: the owner's surface lists every change of the grains.
    if (surface_ != nullptr && (surface_->rebuilt() || surface_->movedPlaceCount() != 0 || !surface_->placesComplete() ||
                                !surface_->changedInnerFlags().empty() || !surface_->changedCells().empty())) {
        builder_.sceneChanged();
        grainsStale_ = true;
        surface_->clearChanges();
    }
    // Grains glide while the last step moved any; otherwise the uploaded positions still hold.
    const bool gliding = scene.counters().movesLastStep > 0;
    if (!gliding && !grainsStale_ && sameGrainInputs(settings, uploadedWith_)) return;
    const auto start = std::chrono::steady_clock::now();
    const std::span<const GrainInstance> instances = builder_.build(scene, stepFraction, settings);
    glBindBuffer(GL_ARRAY_BUFFER, grainBuffer_.get());
    // Orphan the old storage so the driver need not wait for the previous frame's draw.
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(instances.size_bytes()), nullptr, GL_STREAM_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(instances.size_bytes()), instances.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    instanceCount_ = std::int64_t(instances.size());
    uploadedWith_ = settings;
    grainsStale_ = false;
    stats_.uploaded = true;
    stats_.fullUpload = true;
    stats_.uploadBytes = std::int64_t(instances.size_bytes());
    stats_.innerGrains = builder_.innerGrainCount();
    stats_.uploadMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// V8: everything after a change the surface cannot describe, else only what it lists.
void SceneRenderer::uploadGpuGrains(const sandcore::Scene& scene, const RenderSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    sandcore::SurfaceUpkeep* surface = surface_;
    if (surface == nullptr || !gpuStore_.drawsFrom(scene, *surface, settings)) {
        // Without an owner keeping it up to date step by step, any move makes it stale; an
        // owner's that lacks what these settings need leaves it stale every frame.
        const bool stale = surface != nullptr || grainsStale_ || scene.counters().movesLastStep > 0;
        surface = &ownSurface_;
        const sandcore::SurfaceTracking needed = gpuStore_.trackingFor(scene, settings);
        if (stale || ownSurface_.kept() != needed) {
            ownSurface_.setTracking(needed);
            ownSurface_.rebuild(scene);
        }
    }
    const bool full = grainsStale_ || surface->rebuilt() || !surface->placesComplete() ||
                      !gpuStore_.canUpdate(scene, *surface, settings);
    stats_.uploadBytes = full ? gpuStore_.uploadAll(scene, *surface, settings) : gpuStore_.uploadChanges(scene, *surface);
    surface->clearChanges();
    grainsStale_ = false;
    stats_.uploaded = stats_.uploadBytes > 0;
    stats_.fullUpload = full;
    stats_.innerGrains = surface->innerCount();
    stats_.uploadMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::int64_t SceneRenderer::setGpuUniforms(const sandcore::Scene& scene, float stepFraction,
                                           const RenderSettings& settings) const {
    const GlProgram& program = grainGpuProgram_;
    const sandcore::Int3 lower = scene.grid(sandcore::GridLevel::Lower).size();
    const sandcore::Int3 upper = scene.grid(sandcore::GridLevel::Upper).size();
    const sandcore::Int3 origin = scene.gridOrigin(sandcore::GridLevel::Upper);
    glUniform3i(uniform(program, "lowerSize"), lower.x, lower.y, lower.z);
    glUniform3i(uniform(program, "upperSize"), upper.x, upper.y, upper.z);
    glUniform3i(uniform(program, "upperOrigin"), origin.x, origin.y, origin.z);
    glUniform1ui(uniform(program, "currentStep"), GLuint(std::uint32_t(scene.counters().stepsDone)));
    // The same expression as grainDisplayPosition's, so both get the same float.
    glUniform1f(uniform(program, "stepRemaining"), stepFraction < 1.0f ? 1.0f - stepFraction : 0.0f);
    glUniform1i(uniform(program, "showInner"), settings.innerGrains ? 1 : 0);
    const bool fromBits = gpuStore_.flagsFromBits();
    const bool gradient = settings.normals == sandcore::NormalMethod::OccupancyGradient;
    // The surface key holds the gradient normal and the occlusion level: read when either is used.
    const bool keyUsed = (settings.lighting && gradient) || grainOcclusion(settings);
    glUniform1i(uniform(program, "keySource"), keyUsed ? (fromBits ? 2 : 1) : 0);
    glUniform1i(uniform(program, "normalFromKey"), gradient ? 1 : 0);
    glUniform1i(uniform(program, "flagsFromBits"), fromBits ? 1 : 0);
    const std::array<std::int32_t, 4>& offsets = gpuStore_.cellBitsOffsets();
    glUniform4i(uniform(program, "cellBitsOffsets"), offsets[0], offsets[1], offsets[2], offsets[3]);
    gpuStore_.bind(kGrainTexturesUnit, kColumnNormalsUnit);
    // Every grain an instance (from the bits the shader drops inner ones), or the visible list's.
    return settings.innerGrains || fromBits ? gpuStore_.grainCount() : gpuStore_.visibleCount();
}

void SceneRenderer::draw(const sandcore::Scene& scene, float stepFraction, const RenderSettings& settings,
                         const OrbitCamera& camera, int width, int height, float pixelScale) {
    glViewport(0, 0, width, height);
    const float background = settings.blackBackground ? 0.0f : 1.0f;
    glClearColor(background, background, background, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (width <= 0 || height <= 0) return;
    if (timeGpu_) gpuTimer_.begin(); // from the upload to the last draw call

    if (settings.palette != patternPalette_) uploadPatternColors(settings.palette);
    // Past what this GL's buffer textures hold, the grains go the earlier way.
    const GrainPath path = gpuStore_.holds(scene) ? settings.grainPath : GrainPath::CpuFullUpload;
    if (path != path_) sceneChanged(); // the other path's buffers are stale
    path_ = path;
    uploadGrains(scene, stepFraction, settings);
    const glm::mat4 viewProjection = camera.projection(float(width) / float(height)) * camera.view();
    const bool modelled = settings.hull && !settings.voxelHull && !model_.empty();
    look_ = studioLookFor(settings, settings.cellSize);
    bodies_.update(scene, settings.cellSize);
    if (look_.shadows) drawShadowMap(scene, stepFraction, settings, modelled);
    look_.shadows = look_.shadows && shadowMap_.usable(); // a GL that cannot draw depth textures: no shadows
    shadowMap_.bind(look_.shadows);
    if (path_ == GrainPath::GpuInterpolated) {
        glUseProgram(grainGpuProgram_.get());
        instanceCount_ = setGpuUniforms(scene, stepFraction, settings);
    }
    // The draw calls are timed apart from the application's own work (see RenderStats).
    stats_.drawCallCpuMilliseconds = 0.0;
    auto timedDraw = [&](auto&& drawCalls) {
        const double start = threadCpuMilliseconds();
        drawCalls();
        stats_.drawCallCpuMilliseconds += threadCpuMilliseconds() - start;
    };
    timedDraw([&] { drawGrains(settings, camera, glm::value_ptr(viewProjection), pixelScale); });
    // S10: the model as modelled, its opaque parts with the sand, its glass over both.
    const ModelLight frame{glm::value_ptr(viewProjection), camera.position(),
                           camera.position() - camera.up() * (0.15f * camera.distance()), settings.blackBackground, &look_};
    if (modelled) model_.sortGlassFor(frame.eye); // the application's work, outside the timed calls
    timedDraw([&] {
        if (modelled) model_.drawOpaque(frame);
        bodies_.draw(frame);
        draft_.draw(draftPlacement_, glm::value_ptr(viewProjection));
        if (modelled) model_.drawGlass(frame);
        else if (settings.hull) drawHull(settings, camera, glm::value_ptr(viewProjection));
    });
    glBindVertexArray(0);
    glUseProgram(0);
    if (timeGpu_) gpuTimer_.end();
}

void SceneRenderer::drawGrains(const RenderSettings& settings, const OrbitCamera& camera,
                               const float* viewProjection, float pixelScale) {
    const int perCell = drawnGrainsPerCell(settings);
    // From the bits every grain is an instance and the shader drops the inner ones.
    const bool dropsInner = path_ == GrainPath::GpuInterpolated && gpuStore_.flagsFromBits() && !settings.innerGrains;
    stats_.grainsDrawn = dropsInner ? instanceCount_ - stats_.innerGrains : instanceCount_;
    stats_.subGrainsDrawn = stats_.grainsDrawn * perCell;
    if (instanceCount_ == 0) return;
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glEnable(GL_PROGRAM_POINT_SIZE);
    const GlProgram& program = path_ == GrainPath::GpuInterpolated ? grainGpuProgram_ : grainProgram_;
    glUseProgram(program.get());
    const int mode = int(settings.mode);
    glUniformMatrix4fv(uniform(program, "viewProjection"), 1, GL_FALSE, viewProjection);
    glUniform1i(uniform(program, "mode"), mode);
    glUniform1f(uniform(program, "cellSize"), settings.cellSize);
    glUniform1f(uniform(program, "pointSize"), std::max(1.0f, settings.pointSize * pixelScale));
    // Sub-grains share the cell's volume, so a quad's edge shrinks with the cube root of k.
    glUniform1f(uniform(program, "quadHalfSize"),
                0.5f * settings.quadSize * settings.cellSize / std::cbrt(float(perCell)));
    const glm::vec3 eye = camera.position(), up = camera.up(), right = camera.right();
    glUniform3fv(uniform(program, "cameraPosition"), 1, glm::value_ptr(eye));
    glUniform3fv(uniform(program, "cameraUp"), 1, glm::value_ptr(up));
    // Thesis §3.8 pseudo-billboards: one orientation per frame from the camera's rotation.
    glUniform3fv(uniform(program, "pseudoRight"), 1, glm::value_ptr(right));
    glUniform3fv(uniform(program, "pseudoUp"), 1, glm::value_ptr(up));
    glUniform1i(uniform(program, "lighting"), settings.lighting ? 1 : 0);
    glUniform1i(uniform(program, "occlusion"), grainOcclusion(settings) ? 1 : 0);
    setLookUniforms(program.get(), look_);
    // Thesis §3.8: a white point light a little below the camera, so every view is lit.
    const glm::vec3 light = eye - up * (0.15f * camera.distance());
    glUniform3fv(uniform(program, "lightPosition"), 1, glm::value_ptr(light));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, patternOffsets_.get());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, patternColors_.get());
    glActiveTexture(GL_TEXTURE0);
    if (path_ == GrainPath::GpuInterpolated)
        gpuStore_.bind(kGrainTexturesUnit, kColumnNormalsUnit);
    else
        glBindVertexArray(grainArray_.get());
    const bool quads = drawsQuads(settings.mode);
    if (quads) {
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, quadCorners_.get()); // kept by the bound vertex array
        // Both triangles (0 1 2, 0 2 3) take their flat colour from corner 0, the one that shades.
        glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
        glDrawElementsInstanced(GL_TRIANGLES, 6 * perCell, GL_UNSIGNED_SHORT, nullptr, GLsizei(instanceCount_));
        glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    }
    else
        glDrawArraysInstanced(GL_POINTS, 0, perCell, GLsizei(instanceCount_));
    if (path_ == GrainPath::GpuInterpolated) gpuStore_.drawn();
}

// The key light's view of the casters: the opaque model parts and the moving bodies (offset back a little, as
// triangles seen edge-on would shadow themselves) and one point per grain, 1.5 cells wide,
// so neighbouring grains close the surface. Glass casts nothing.
void SceneRenderer::drawShadowMap(const sandcore::Scene& scene, float stepFraction, const RenderSettings& settings,
                                  bool modelled) {
    const sandcore::Int3 lower = scene.grid(sandcore::GridLevel::Lower).size();
    const sandcore::Int3 upper = scene.grid(sandcore::GridLevel::Upper).size();
    const sandcore::Int3 origin = scene.gridOrigin(sandcore::GridLevel::Upper);
    WorldBox box{glm::vec3(0.0f), glm::max(glm::vec3(float(lower.x), float(lower.y), float(lower.z)),
                                            glm::vec3(float(origin.x + upper.x), float(origin.y + upper.y),
                                                      float(origin.z + upper.z))) * settings.cellSize};
    if (modelled) {
        box.min = glm::min(box.min, model_.bounds().min);
        box.max = glm::max(box.max, model_.bounds().max);
    }
    const glm::mat4 lightClip = shadowMap_.begin(box, settings.cellSize, look_);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    if (modelled) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.5f, 2.0f);
        model_.drawShadowCasters(glm::value_ptr(lightClip));
        glDisable(GL_POLYGON_OFFSET_FILL);
    }
    glEnable(GL_POLYGON_OFFSET_FILL); // as the model's: a body's side seen edge-on casts on no one
    glPolygonOffset(1.5f, 2.0f);
    bodies_.drawShadowCasters(glm::value_ptr(lightClip));
    glDisable(GL_POLYGON_OFFSET_FILL);
    const bool gpu = path_ == GrainPath::GpuInterpolated;
    const GlProgram& program = gpu ? grainGpuProgram_ : grainProgram_;
    glUseProgram(program.get());
    const std::int64_t instances = gpu ? setGpuUniforms(scene, stepFraction, settings) : instanceCount_;
    if (instances > 0) {
        if (gpu) glUniform1i(uniform(program, "keySource"), 0); // no light, no occlusion: no key
        setLookUniforms(program.get(), StudioLook{});           // reads no shadow map while drawing one
        glUniformMatrix4fv(uniform(program, "viewProjection"), 1, GL_FALSE, glm::value_ptr(lightClip));
        glUniform1i(uniform(program, "mode"), 0);
        glUniform1f(uniform(program, "cellSize"), settings.cellSize);
        glUniform1f(uniform(program, "pointSize"), std::max(1.0f, 1.5f * settings.cellSize * shadowMap_.texelsPerUnit()));
        glUniform1i(uniform(program, "lighting"), 0);
        glUniform1i(uniform(program, "occlusion"), 0);
        glEnable(GL_PROGRAM_POINT_SIZE);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, patternOffsets_.get());
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, patternColors_.get());
        glActiveTexture(GL_TEXTURE0);
        if (gpu)
            gpuStore_.bind(kGrainTexturesUnit, kColumnNormalsUnit);
        else
            glBindVertexArray(grainArray_.get());
        glDrawArraysInstanced(GL_POINTS, 0, 1, GLsizei(instances)); // one sub-grain per grain
    }
    glBindVertexArray(0);
    shadowMap_.end();
}

void SceneRenderer::drawHull(const RenderSettings& settings, const OrbitCamera& camera, const float* viewProjection) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE); // glass never hides sand behind it
    glUseProgram(hullProgram_.get());
    glUniformMatrix4fv(uniform(hullProgram_, "viewProjection"), 1, GL_FALSE, viewProjection);
    const glm::vec3 eye = camera.position();
    glUniform3fv(uniform(hullProgram_, "cameraPosition"), 1, glm::value_ptr(eye));
    const glm::vec3 glass = settings.blackBackground ? glm::vec3(0.70f, 0.82f, 0.95f) : glm::vec3(0.35f, 0.50f, 0.65f);
    glUniform3fv(uniform(hullProgram_, "glassColor"), 1, glm::value_ptr(glass));
    setLookUniforms(hullProgram_.get(), look_);
    if (hullVertices_ > 0) {
        glUniform1f(uniform(hullProgram_, "baseAlpha"), 0.025f);
        glUniform1f(uniform(hullProgram_, "rimAlpha"), 0.10f);
        glBindVertexArray(hullArray_.get());
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(hullVertices_));
    }
    if (lineVertices_ > 0) {
        glUniform1f(uniform(hullProgram_, "baseAlpha"), 0.45f);
        glUniform1f(uniform(hullProgram_, "rimAlpha"), 0.0f);
        glBindVertexArray(lineArray_.get());
        glDrawArrays(GL_LINES, 0, GLsizei(lineVertices_));
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

} // namespace sandglass
