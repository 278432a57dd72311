// SPDX-License-Identifier: MIT
#include "view/render/grain_gpu_store.hpp"

#include "view/render/grain_instances.hpp"

#include "sandcore/display_positions.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <cstddef>
#include <limits>

namespace sandglass {

namespace {

// Fewer changed cells than this are not worth waking another thread for.
constexpr std::size_t kSharedCellChanges = 1024;

constexpr std::uint32_t kNotListed = std::numeric_limits<std::uint32_t>::max();

// Sends the runs of `all` that `changed` marks (runs at most maxGap entries apart joined: the
// gaps go up too, unchanged), after prepare(first, end) brought each run of the mirror up to
// date. Several runs go through one mapping of the range they span, flushed run by run: one
// glBufferSubData per run costs more than the copy. Returns the bytes sent.
template <class T, class Prepare>
std::int64_t uploadRuns(GLenum target, GLuint buffer, std::span<const T> all, IndexRuns& changed, std::uint32_t maxGap,
                        std::vector<std::pair<std::uint32_t, std::uint32_t>>& runs, Prepare&& prepare) {
    runs.clear();
    changed.take(maxGap, [&](std::uint32_t first, std::uint32_t end) {
        end = std::min(end, std::uint32_t(all.size())); // entries past the end are not drawn
        if (first >= end) return;
        prepare(first, end);
        runs.emplace_back(first, end);
    });
    if (runs.empty()) return 0;
    glBindBuffer(target, buffer);
    std::int64_t bytes = 0;
    const std::uint32_t spanFirst = runs.front().first, spanEnd = runs.back().second;
    void* mapped = runs.size() > 1 ? glMapBufferRange(target, GLintptr(std::size_t(spanFirst) * sizeof(T)),
                                                      GLsizeiptr(std::size_t(spanEnd - spanFirst) * sizeof(T)),
                                                      GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT)
                                   : nullptr;
    if (mapped != nullptr) {
        auto* base = static_cast<unsigned char*>(mapped);
        for (const auto& [first, end] : runs) {
            const std::size_t offset = std::size_t(first - spanFirst) * sizeof(T), size = std::size_t(end - first) * sizeof(T);
            std::memcpy(base + offset, all.data() + first, size);
            glFlushMappedBufferRange(target, GLintptr(offset), GLsizeiptr(size));
            bytes += std::int64_t(size);
        }
        if (glUnmapBuffer(target) == GL_FALSE) { // the store was lost (GL's rule): send the span again
            glBufferSubData(target, GLintptr(std::size_t(spanFirst) * sizeof(T)),
                            GLsizeiptr(std::size_t(spanEnd - spanFirst) * sizeof(T)), all.data() + spanFirst);
            bytes += std::int64_t(std::size_t(spanEnd - spanFirst) * sizeof(T));
        }
    } else {
        for (const auto& [first, end] : runs) {
            const std::size_t size = std::size_t(end - first) * sizeof(T);
            glBufferSubData(target, GLintptr(std::size_t(first) * sizeof(T)), GLsizeiptr(size), all.data() + first);
            bytes += std::int64_t(size);
        }
    }
    glBindBuffer(target, 0);
    return bytes;
}

// The surface key carries the gradient normal and the occlusion level.
bool needsGradient(const RenderSettings& settings) {
    return (settings.lighting && settings.normals == sandcore::NormalMethod::OccupancyGradient) ||
           grainOcclusion(settings);
}

bool needsColumns(const RenderSettings& settings) {
    return settings.lighting && settings.normals == sandcore::NormalMethod::ColumnHeights;
}

// Words of a grid's bits, as sandcore::CellBitWords lays them out.
std::int64_t cellBitWordsOf(const sandcore::CellGrid& grid) {
    return std::int64_t(((std::size_t(grid.cellCount()) / 8 + 2 + 3) & ~std::size_t(3)) / 4);
}

constexpr sandcore::GridLevel kLevels[2] = {sandcore::GridLevel::Lower, sandcore::GridLevel::Upper};

GrainPlace placeOf(const sandcore::GrainStore& grains, std::uint32_t id) {
    return {grains.place[id].cell, grains.level[id] == sandcore::GridLevel::Upper ? 1u : 0u, grains.place[id].cameFrom,
            std::uint32_t(grains.place[id].movedAtStep)};
}

GrainPlace placeOf(const sandcore::MovedPlace& moved) { return {moved.cell, moved.level, moved.cameFrom, moved.movedStep}; }

} // namespace

GrainGpuStore::GrainGpuStore()
    : persistent_(persistentMappingAvailable()),
      places_gpu_{MappedBuffer(persistent_), GlTexture(newTexture()), GL_RGBA32UI},
      looks_gpu_{MappedBuffer(false), GlTexture(newTexture()), GL_RG32UI},
      jitters_gpu_{MappedBuffer(false), GlTexture(newTexture()), GL_RGBA32F},
      normals_gpu_{MappedBuffer(persistent_), GlTexture(newTexture()), GL_R32UI},
      cellBits_gpu_{MappedBuffer(persistent_), GlTexture(newTexture()), GL_R32UI},
      gradientTable_gpu_{MappedBuffer(false), GlTexture(newTexture()), GL_R32UI}, visibleBuffer_(persistent_),
      visibleArray_(newVertexArray()), everyGrainArray_(newVertexArray()), columnNormals_(newTexture()) {
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    maxTexels_ = maxTexels;
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    softwareRenderer_ = renderer != nullptr && isSoftwareRenderer(renderer);
    if (const char* setting = std::getenv("SANDGLASS_GPU_CELL_BITS")) { // either path, to compare
        if (std::strcmp(setting, "0") == 0) cellBitsChoice_ = CellBitsChoice::Never;
        if (std::strcmp(setting, "1") == 0) cellBitsChoice_ = CellBitsChoice::WhereTheyFit;
    }
    for (BufferTexture* texture : {&places_gpu_, &looks_gpu_, &jitters_gpu_, &normals_gpu_, &cellBits_gpu_})
        allocate(*texture, 16, nullptr); // never empty: a texture needs storage
    packedByKey_.resize(sandcore::SurfaceUpkeep::kSurfaceKeys);
    for (std::size_t key = 0; key < packedByKey_.size(); ++key)
        packedByKey_[key] = packNormal(sandcore::SurfaceUpkeep::normalOfGradientKey(std::uint16_t(key)));
    // The shader looks the normal of its gradient up here: the same packed word as the CPU's.
    allocate(gradientTable_gpu_, packedByKey_.size() * 4, packedByKey_.data());
    // The one per-instance attribute: the id of the grain to draw (when inner grains are hidden).
    visibleBuffer_.allocate(GL_ARRAY_BUFFER, 4, nullptr);
    glBindVertexArray(visibleArray_.get());
    glBindBuffer(GL_ARRAY_BUFFER, visibleBuffer_.get());
    glEnableVertexAttribArray(0);
    glVertexAttribIPointer(0, 1, GL_UNSIGNED_INT, 4, nullptr);
    glVertexAttribDivisor(0, 1);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, columnNormals_.get());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
}

// New storage, and the texture pointed at it (a persistent buffer's name changes).
void GrainGpuStore::allocate(BufferTexture& texture, std::size_t bytes, const void* data) {
    texture.buffer.allocate(GL_TEXTURE_BUFFER, bytes, data);
    glBindTexture(GL_TEXTURE_BUFFER, texture.texture.get());
    glTexBuffer(GL_TEXTURE_BUFFER, texture.format, texture.buffer.get());
    glBindTexture(GL_TEXTURE_BUFFER, 0);
}

bool isSoftwareRenderer(std::string_view glRenderer) {
    for (std::string_view name : {"llvmpipe", "softpipe", "swrast", "SwiftShader", "Software Rasterizer", "GDI Generic"})
        if (glRenderer.find(name) != std::string_view::npos) return true;
    return false;
}

int verticesPerGrain(const RenderSettings& settings) {
    const int perCell = drawnGrainsPerCell(settings);
    const bool quads = drawsQuads(settings.mode);
    return quads ? 4 * perCell : perCell;
}

bool hiddenInnerGrainsFromList(bool softwareRenderer, const RenderSettings& settings) {
    return !settings.innerGrains && (softwareRenderer || verticesPerGrain(settings) >= kVisibleListVertices);
}

bool GrainGpuStore::usesCellBits(const sandcore::Scene& scene, const RenderSettings& settings) const {
    if (cellBitsChoice_ == CellBitsChoice::Never) return false;
    if (cellBitsChoice_ == CellBitsChoice::ByRenderer && hiddenInnerGrainsFromList(softwareRenderer_, settings))
        return false;
    std::int64_t words = 0;
    for (sandcore::GridLevel level : kLevels) words += 2 * cellBitWordsOf(scene.grid(level));
    return holds(scene) && words <= maxTexels_;
}

sandcore::SurfaceTracking GrainGpuStore::trackingFor(const sandcore::Scene& scene, const RenderSettings& settings) const {
    if (usesCellBits(scene, settings)) return {false, false, needsColumns(settings)};
    return {true, needsGradient(settings), true};
}

bool GrainGpuStore::drawsFrom(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface,
                              const RenderSettings& settings) const {
    const sandcore::SurfaceTracking kept = surface.kept();
    if (needsColumns(settings) && !kept.columnNormals) return false;
    if (!kept.grainFlags) return usesCellBits(scene, settings);
    return !needsGradient(settings) || surface.tracksGradientNormals();
}

bool GrainGpuStore::canUpdate(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface,
                              const RenderSettings& settings) const {
    const sandcore::Int3 size = scene.grid(sandcore::GridLevel::Lower).size();
    const bool bits = !surface.kept().grainFlags;
    return grainCount_ == std::int64_t(scene.grains().size()) && uploadedJitter_ == settings.jitter &&
           uploadedPalette_ == settings.palette && bitsMode_ == bits &&
           (bits || gradientUploaded_ || !needsGradient(settings)) && (columnsUploaded_ || !needsColumns(settings)) &&
           columnsX_ == size.x && columnsZ_ == size.z;
}

void GrainGpuStore::bind(int firstUnit, int columnUnit) const {
    const BufferTexture* textures[] = {&places_gpu_, &looks_gpu_, &jitters_gpu_, &normals_gpu_, &cellBits_gpu_, &gradientTable_gpu_};
    for (int i = 0; i < 6; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit + i));
        glBindTexture(GL_TEXTURE_BUFFER, textures[i]->texture.get());
    }
    glActiveTexture(GLenum(GL_TEXTURE0 + columnUnit));
    glBindTexture(GL_TEXTURE_2D, columnNormals_.get());
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(bitsMode_ ? everyGrainArray_.get() : visibleArray_.get());
}

// All four bit sets in one buffer: lower grains, upper grains, lower hides, upper hides.
std::int64_t GrainGpuStore::uploadCellBits(const sandcore::SurfaceUpkeep& surface) {
    const sandcore::CellBitWords sets[4] = {surface.grainBits(kLevels[0]), surface.grainBits(kLevels[1]),
                                            surface.hideBits(kLevels[0]), surface.hideBits(kLevels[1])};
    std::vector<std::uint32_t> words;
    for (int i = 0; i < 4; ++i) {
        bitsOffsets_[std::size_t(i)] = std::int32_t(words.size());
        for (std::uint32_t w = 0; w < sets[i].wordCount(); ++w) words.push_back(sets[i].word(w));
    }
    allocate(cellBits_gpu_, words.size() * 4, words.data());
    const auto bytes = std::int64_t(words.size()) * 4;
    cellBitWords_ = std::move(words);
    return bytes;
}

std::vector<std::uint32_t> GrainGpuStore::readCellBits() const {
    std::vector<std::uint32_t> words(cellBits_gpu_.buffer.size() / 4);
    glBindBuffer(GL_TEXTURE_BUFFER, cellBits_gpu_.buffer.get());
    glGetBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(words.size() * 4), words.data());
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    return words;
}

// The words holding the cells the upkeep lists as changed, from its bits: into the mapped buffer
// (with the scene's idle threads, one grid each: their words are apart), or into the copy here and
// marked for the runs.
std::int64_t GrainGpuStore::writeCellBitChanges(const sandcore::SurfaceUpkeep& surface, sandcore::WorkerPool* workers) {
    if (!bitsMode_) return 0;
    auto* mapped = persistent_ ? static_cast<std::uint32_t*>(cellBits_gpu_.buffer.mapped()) : nullptr;
    std::uint32_t* words = mapped != nullptr ? mapped : cellBitWords_.data();
    const std::span<const sandcore::CellRef> changed = surface.changedCells();
    const sandcore::CellBitWords grainWords[2] = {surface.grainBits(kLevels[0]), surface.grainBits(kLevels[1])};
    const sandcore::CellBitWords hideWords[2] = {surface.hideBits(kLevels[0]), surface.hideBits(kLevels[1])};
    auto writeGrids = [&](int only) { // only: 0 or 1 for that grid, -1 for both
        for (const sandcore::CellRef& ref : changed) {
            const int grid = ref.level == sandcore::GridLevel::Upper ? 1 : 0;
            if (only >= 0 && grid != only) continue;
            const std::uint32_t word = ref.cell >> 5;
            const auto grains = std::uint32_t(bitsOffsets_[std::size_t(grid)]) + word;
            const auto hides = std::uint32_t(bitsOffsets_[std::size_t(2 + grid)]) + word;
            words[grains] = grainWords[grid].word(word);
            words[hides] = hideWords[grid].word(word);
            if (mapped != nullptr) continue;
            changedWords_.mark(grains);
            changedWords_.mark(hides);
        }
    };
    if (mapped != nullptr && workers != nullptr && changed.size() >= kSharedCellChanges) sandcore::parallelFor(workers, 2, writeGrids);
    else writeGrids(-1);
    if (mapped != nullptr) return std::int64_t(changed.size()) * 8;
    return uploadRuns(GL_TEXTURE_BUFFER, cellBits_gpu_.buffer.get(), std::span<const std::uint32_t>(cellBitWords_),
                      changedWords_, 4, runs_, [](std::uint32_t, std::uint32_t) {});
}

// The visible list in id order (the order the earlier path drew in).
void GrainGpuStore::makeVisibleList(const sandcore::SurfaceUpkeep& surface) {
    visible_.clear();
    slotOf_.assign(surface.grainCount(), kNotListed);
    for (std::uint32_t id = 0; id < surface.grainCount(); ++id) {
        if (surface.isInner(id)) continue;
        slotOf_[id] = std::uint32_t(visible_.size());
        visible_.push_back(id);
    }
}

// A grain that turns visible joins the end of the list; one that turns inner leaves it, the last
// entry taking its slot. Either way one or two entries change.
void GrainGpuStore::setVisible(std::uint32_t grain, bool visible) {
    std::uint32_t& slot = slotOf_[grain];
    if (visible == (slot != kNotListed)) return;
    auto* mapped = static_cast<std::uint32_t*>(visibleBuffer_.mapped());
    auto changedSlot = [&](std::uint32_t changed) {
        if (mapped == nullptr) {
            changedSlots_.mark(changed);
            return;
        }
        mapped[changed] = visible_[changed];
        visibleBytes_ += 4;
    };
    if (visible) {
        slot = std::uint32_t(visible_.size());
        visible_.push_back(grain);
        changedSlot(slot);
        return;
    }
    const std::uint32_t last = visible_.back();
    visible_[slot] = last;
    slotOf_[last] = slot;
    if (last != grain) changedSlot(slot);
    visible_.pop_back();
    slot = kNotListed;
}

std::int64_t GrainGpuStore::uploadAll(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface,
                                      const RenderSettings& settings) {
    if (persistent_) fence_.waitForDraws();
    const sandcore::GrainStore& grains = scene.grains();
    const std::uint32_t count = grains.size();
    grainCount_ = count;
    places_.resize(count);
    std::vector<std::uint32_t> looks(std::size_t(count) * 2);
    std::vector<float> jitters(std::size_t(count) * 4, 0.0f);
    for (std::uint32_t id = 0; id < count; ++id) {
        places_[id] = placeOf(grains, id);
        looks[2 * std::size_t(id)] = grains.identity[id];
        looks[2 * std::size_t(id) + 1] = drawnGrainColor(grains, id, settings.palette);
        const sandcore::Vec3 jitter = sandcore::jitterOffset(grains.identity[id], settings.jitter);
        jitters[4 * std::size_t(id)] = jitter.x;
        jitters[4 * std::size_t(id) + 1] = jitter.y;
        jitters[4 * std::size_t(id) + 2] = jitter.z;
    }
    allocate(places_gpu_, places_.size() * sizeof(GrainPlace), places_.data());
    allocate(looks_gpu_, looks.size() * 4, looks.data());
    allocate(jitters_gpu_, jitters.size() * 4, jitters.data());
    std::int64_t bytes = std::int64_t(places_.size() * sizeof(GrainPlace) + looks.size() * 4 + jitters.size() * 4);
    bitsMode_ = !surface.kept().grainFlags;
    gradientUploaded_ = !bitsMode_ && needsGradient(settings) && surface.tracksGradientNormals();
    packedNormals_.assign(gradientUploaded_ ? count : 0, 0u);
    for (std::uint32_t id = 0; id < packedNormals_.size(); ++id) packedNormals_[id] = surface.gradientKeyOf(id);
    allocate(normals_gpu_, packedNormals_.size() * 4, packedNormals_.data());
    bytes += std::int64_t(packedNormals_.size()) * 4;
    if (bitsMode_) {
        bytes += uploadCellBits(surface);
    } else {
        cellBitWords_.clear();
        allocate(cellBits_gpu_, 16, nullptr);
    }
    // A driver that would not map a buffer gets the runs for all of them (MappedBuffer fell back).
    persistent_ = persistent_ && places_gpu_.buffer.persistent() && normals_gpu_.buffer.persistent() &&
                  cellBits_gpu_.buffer.persistent();
    if (persistent_) { // the mapped buffers are the copies now
        places_ = {};
        packedNormals_ = {};
        cellBitWords_ = {};
    }

    for (IndexRuns* runs : {&changedIds_, &changedSlots_, &changedNormals_}) runs->resize(persistent_ ? 0 : count);
    changedWords_.resize(persistent_ ? 0 : std::uint32_t(cellBitWords_.size()));
    // The visible list's buffer holds every grain, so the list can grow without reallocating.
    // From the bits the shader drops inner grains itself: no list.
    if (bitsMode_) {
        visible_.clear();
        slotOf_ = {};
    } else {
        makeVisibleList(surface);
    }
    std::vector<std::uint32_t> visibleStore(bitsMode_ ? 1 : std::max<std::size_t>(count, 1), 0u);
    std::copy(visible_.begin(), visible_.end(), visibleStore.begin());
    visibleBuffer_.allocate(GL_ARRAY_BUFFER, visibleStore.size() * 4, visibleStore.data());
    persistent_ = persistent_ && visibleBuffer_.persistent();
    glBindVertexArray(visibleArray_.get());
    glBindBuffer(GL_ARRAY_BUFFER, visibleBuffer_.get());
    glVertexAttribIPointer(0, 1, GL_UNSIGNED_INT, 4, nullptr); // the buffer's name may be new
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    bytes += std::int64_t(visibleStore.size()) * 4;
    visibleBytes_ = 0;

    const sandcore::Int3 size = scene.grid(sandcore::GridLevel::Lower).size();
    columnsX_ = size.x;
    columnsZ_ = size.z;
    uploadedJitter_ = settings.jitter;
    uploadedPalette_ = settings.palette;
    columnsUploaded_ = surface.kept().columnNormals;
    if (!columnsUploaded_) { // lighting without column normals: the texture is not read
        packedColumns_.clear();
        return bytes;
    }
    const std::size_t layer = std::size_t(size.x) * std::size_t(size.z);
    packedColumns_.resize(2 * layer);
    for (sandcore::GridLevel level : {sandcore::GridLevel::Lower, sandcore::GridLevel::Upper}) {
        const std::size_t base = level == sandcore::GridLevel::Upper ? layer : 0;
        const std::span<const sandcore::Vec3> normals = surface.columnNormals(level);
        for (std::size_t column = 0; column < layer; ++column) packedColumns_[base + column] = packNormal(normals[column]);
    }
    glBindTexture(GL_TEXTURE_2D, columnNormals_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, size.x, 2 * size.z, 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                 packedColumns_.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    bytes += std::int64_t(packedColumns_.size()) * 4;
    return bytes;
}

std::int64_t GrainGpuStore::uploadColumns(const sandcore::SurfaceUpkeep& surface) {
    const std::size_t layer = std::size_t(columnsX_) * std::size_t(columnsZ_);
    if (!columnsUploaded_ || surface.changedColumns().empty()) return 0;
    if (changedTexels_.capacity() < 2 * layer) changedTexels_.resize(std::uint32_t(2 * layer));
    for (const sandcore::ColumnRef& ref : surface.changedColumns()) {
        const std::size_t texel = (ref.level == sandcore::GridLevel::Upper ? layer : 0) + ref.column;
        packedColumns_[texel] = packNormal(surface.columnNormals(ref.level)[ref.column]);
        changedTexels_.mark(std::uint32_t(texel));
    }
    glBindTexture(GL_TEXTURE_2D, columnNormals_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    std::int64_t bytes = 0;
    const auto width = std::uint32_t(columnsX_);
    changedTexels_.take(2, [&](std::uint32_t first, std::uint32_t end) {
        // A texture takes rectangles: a run that crosses a row goes up row by row.
        for (std::uint32_t texel = first; texel < end;) {
            const std::uint32_t rowEnd = std::min(end, (texel / width + 1) * width);
            glTexSubImage2D(GL_TEXTURE_2D, 0, GLint(texel % width), GLint(texel / width), GLsizei(rowEnd - texel), 1,
                            GL_RED_INTEGER, GL_UNSIGNED_INT, packedColumns_.data() + texel);
            bytes += std::int64_t(rowEnd - texel) * 4;
            texel = rowEnd;
        }
    });
    glBindTexture(GL_TEXTURE_2D, 0);
    return bytes;
}

std::int64_t GrainGpuStore::uploadChanges(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface) {
    const std::int64_t bytes = persistent_ ? writeChanges(surface, scene.workers()) : sendChangesInRuns(surface);
    return bytes + uploadColumns(surface);
}

// Persistent mapping: each change is one store into the buffer the GPU reads, in the upkeep's
// order (a grain moved twice since the last frame ends with its last place). The places, a cache
// miss each, are shared with the scene's threads, idle between steps.
std::int64_t GrainGpuStore::writeChanges(const sandcore::SurfaceUpkeep& surface, sandcore::WorkerPool* workers) {
    const std::size_t moved = surface.movedPlaceCount();
    const std::span<const std::uint32_t> flags = surface.changedInnerFlags();
    const std::span<const std::uint32_t> normals = gradientUploaded_ ? surface.changedGradientNormals()
                                                                     : std::span<const std::uint32_t>();
    if (moved == 0 && flags.empty() && normals.empty() && surface.changedCells().empty()) return 0;
    fence_.waitForDraws();
    auto* places = static_cast<GrainPlace*>(places_gpu_.buffer.mapped());
    surface.forEachMovedPlace(workers, [places](const sandcore::MovedPlace& grain) { places[grain.grain] = placeOf(grain); });
    visibleBytes_ = 0;
    for (std::uint32_t id : flags) setVisible(id, !surface.isInner(id));
    auto* packed = static_cast<std::uint32_t*>(normals_gpu_.buffer.mapped());
    for (std::uint32_t id : normals) packed[id] = surface.gradientKeyOf(id);
    return std::int64_t(moved * sizeof(GrainPlace)) + visibleBytes_ + std::int64_t(normals.size()) * 4 +
           writeCellBitChanges(surface, workers);
}

// Without it: the copies here are brought up to date and the changed entries go up in id order,
// in runs.
std::int64_t GrainGpuStore::sendChangesInRuns(const sandcore::SurfaceUpkeep& surface) {
    std::int64_t bytes = 0;
    surface.forEachMovedPlace([&](const sandcore::MovedPlace& grain) {
        places_[grain.grain] = placeOf(grain);
        changedIds_.mark(grain.grain);
    });
    bytes += uploadRuns(GL_TEXTURE_BUFFER, places_gpu_.buffer.get(), std::span<const GrainPlace>(places_), changedIds_, 0,
                        runs_, [](std::uint32_t, std::uint32_t) {});
    for (std::uint32_t id : surface.changedInnerFlags()) setVisible(id, !surface.isInner(id));
    bytes += uploadRuns(GL_ARRAY_BUFFER, visibleBuffer_.get(), std::span<const std::uint32_t>(visible_), changedSlots_, 2,
                        runs_, [](std::uint32_t, std::uint32_t) {});
    if (gradientUploaded_) {
        for (std::uint32_t id : surface.changedGradientNormals()) {
            packedNormals_[id] = surface.gradientKeyOf(id);
            changedNormals_.mark(id);
        }
        bytes += uploadRuns(GL_TEXTURE_BUFFER, normals_gpu_.buffer.get(), std::span<const std::uint32_t>(packedNormals_),
                            changedNormals_, 4, runs_, [](std::uint32_t, std::uint32_t) {});
    }
    return bytes + writeCellBitChanges(surface, nullptr);
}

} // namespace sandglass
