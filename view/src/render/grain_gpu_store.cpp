#include "view/render/grain_gpu_store.hpp"

#include "view/render/grain_instances.hpp"

#include "sandcore/display_positions.hpp"

#include <algorithm>
#include <cstring>
#include <cstddef>
#include <limits>

namespace sandglass {

namespace {

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

template <class T> std::int64_t uploadWhole(GLuint buffer, std::span<const T> all, GLenum usage) {
    glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    if (all.empty())
        glBufferData(GL_TEXTURE_BUFFER, 16, nullptr, usage); // a buffer texture needs some storage
    else
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(all.size_bytes()), all.data(), usage);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    return std::int64_t(all.size_bytes());
}

bool needsGradient(const RenderSettings& settings) {
    return settings.lighting && settings.normals == sandcore::NormalMethod::OccupancyGradient;
}

GrainPlace placeOf(const sandcore::GrainStore& grains, std::uint32_t id) {
    return {grains.cell[id], grains.level[id] == sandcore::GridLevel::Upper ? 1u : 0u, grains.cameFrom[id],
            std::uint32_t(grains.movedAtStep[id])};
}

} // namespace

GrainGpuStore::GrainGpuStore()
    : places_gpu_{GlBuffer(newBuffer()), GlTexture(newTexture())}, looks_gpu_{GlBuffer(newBuffer()), GlTexture(newTexture())},
      jitters_gpu_{GlBuffer(newBuffer()), GlTexture(newTexture())},
      normals_gpu_{GlBuffer(newBuffer()), GlTexture(newTexture())}, visibleBuffer_(newBuffer()),
      visibleArray_(newVertexArray()), columnNormals_(newTexture()) {
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    maxTexels_ = maxTexels;
    const std::pair<BufferTexture*, GLenum> textures[] = {
        {&places_gpu_, GL_RGBA32UI}, {&looks_gpu_, GL_RG32UI}, {&jitters_gpu_, GL_RGBA32F}, {&normals_gpu_, GL_R32UI}};
    for (const auto& [texture, format] : textures) {
        glBindBuffer(GL_TEXTURE_BUFFER, texture->buffer.get());
        glBufferData(GL_TEXTURE_BUFFER, 16, nullptr, GL_DYNAMIC_DRAW); // never empty: a texture needs storage
        glBindTexture(GL_TEXTURE_BUFFER, texture->texture.get());
        glTexBuffer(GL_TEXTURE_BUFFER, format, texture->buffer.get());
    }
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    // The one per-instance attribute: the id of the grain to draw (when inner grains are hidden).
    glBindVertexArray(visibleArray_.get());
    glBindBuffer(GL_ARRAY_BUFFER, visibleBuffer_.get());
    glBufferData(GL_ARRAY_BUFFER, 4, nullptr, GL_DYNAMIC_DRAW);
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

bool GrainGpuStore::canUpdate(const sandcore::Scene& scene, const RenderSettings& settings) const {
    const sandcore::Int3 size = scene.grid(sandcore::GridLevel::Lower).size();
    return places_.size() == scene.grains().size() && uploadedJitter_ == settings.jitter &&
           (gradientUploaded_ || !needsGradient(settings)) && columnsX_ == size.x && columnsZ_ == size.z;
}

void GrainGpuStore::bind(int firstUnit, int columnUnit) const {
    const BufferTexture* textures[] = {&places_gpu_, &looks_gpu_, &jitters_gpu_, &normals_gpu_};
    for (int i = 0; i < 4; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit + i));
        glBindTexture(GL_TEXTURE_BUFFER, textures[i]->texture.get());
    }
    glActiveTexture(GLenum(GL_TEXTURE0 + columnUnit));
    glBindTexture(GL_TEXTURE_2D, columnNormals_.get());
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(visibleArray_.get());
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
    if (visible) {
        slot = std::uint32_t(visible_.size());
        visible_.push_back(grain);
        changedSlots_.mark(slot);
        return;
    }
    const std::uint32_t last = visible_.back();
    visible_[slot] = last;
    slotOf_[last] = slot;
    if (last != grain) changedSlots_.mark(slot);
    visible_.pop_back();
    slot = kNotListed;
}

std::int64_t GrainGpuStore::uploadAll(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface,
                                      const RenderSettings& settings) {
    const sandcore::GrainStore& grains = scene.grains();
    const std::uint32_t count = grains.size();
    places_.resize(count);
    std::vector<std::uint32_t> looks(std::size_t(count) * 2);
    std::vector<float> jitters(std::size_t(count) * 4, 0.0f);
    for (std::uint32_t id = 0; id < count; ++id) {
        places_[id] = placeOf(grains, id);
        looks[2 * std::size_t(id)] = grains.identity[id];
        looks[2 * std::size_t(id) + 1] = grains.color[id];
        const sandcore::Vec3 jitter = sandcore::jitterOffset(grains.identity[id], settings.jitter);
        jitters[4 * std::size_t(id)] = jitter.x;
        jitters[4 * std::size_t(id) + 1] = jitter.y;
        jitters[4 * std::size_t(id) + 2] = jitter.z;
    }
    std::int64_t bytes = uploadWhole(places_gpu_.buffer.get(), std::span<const GrainPlace>(places_), GL_DYNAMIC_DRAW);
    bytes += uploadWhole(looks_gpu_.buffer.get(), std::span<const std::uint32_t>(looks), GL_STATIC_DRAW);
    bytes += uploadWhole(jitters_gpu_.buffer.get(), std::span<const float>(jitters), GL_STATIC_DRAW);
    gradientUploaded_ = needsGradient(settings) && surface.tracksGradientNormals();
    packedNormals_.assign(gradientUploaded_ ? count : 0, 0u);
    for (std::uint32_t id = 0; id < packedNormals_.size(); ++id) packedNormals_[id] = packNormal(surface.gradientNormal(id));
    bytes += uploadWhole(normals_gpu_.buffer.get(), std::span<const std::uint32_t>(packedNormals_), GL_DYNAMIC_DRAW);

    for (IndexRuns* runs : {&changedIds_, &changedSlots_, &changedNormals_}) runs->resize(count);
    // The visible list's buffer holds every grain, so the list can grow without reallocating.
    makeVisibleList(surface);
    glBindBuffer(GL_ARRAY_BUFFER, visibleBuffer_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(std::max<std::size_t>(count, 1) * 4), nullptr, GL_DYNAMIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(visible_.size() * 4), visible_.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    bytes += std::int64_t(visible_.size()) * 4;

    const sandcore::Int3 size = scene.grid(sandcore::GridLevel::Lower).size();
    columnsX_ = size.x;
    columnsZ_ = size.z;
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
    uploadedJitter_ = settings.jitter;
    return bytes;
}

std::int64_t GrainGpuStore::uploadColumns(const sandcore::SurfaceUpkeep& surface) {
    const std::size_t layer = std::size_t(columnsX_) * std::size_t(columnsZ_);
    if (surface.changedColumns().empty()) return 0;
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

// The moved grains' places and the changed normals go up in id order, each mirror entry
// refreshed as its run goes up (in memory order, not the step's).
std::int64_t GrainGpuStore::uploadChanges(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface) {
    const sandcore::GrainStore& grains = scene.grains();
    std::int64_t bytes = 0;
    for (std::uint32_t id : surface.movedGrains()) changedIds_.mark(id);
    bytes += uploadRuns(GL_TEXTURE_BUFFER, places_gpu_.buffer.get(), std::span<const GrainPlace>(places_), changedIds_, 0,
                        runs_, [&](std::uint32_t first, std::uint32_t end) {
                            for (std::uint32_t id = first; id < end; ++id) places_[id] = placeOf(grains, id);
                        });
    for (std::uint32_t id : surface.changedInnerFlags()) setVisible(id, !surface.isInner(id));
    bytes += uploadRuns(GL_ARRAY_BUFFER, visibleBuffer_.get(), std::span<const std::uint32_t>(visible_), changedSlots_, 2,
                        runs_, [](std::uint32_t, std::uint32_t) {});
    if (gradientUploaded_) {
        for (std::uint32_t id : surface.changedGradientNormals()) changedNormals_.mark(id);
        bytes += uploadRuns(GL_TEXTURE_BUFFER, normals_gpu_.buffer.get(), std::span<const std::uint32_t>(packedNormals_),
                            changedNormals_, 4, runs_, [&](std::uint32_t first, std::uint32_t end) {
                                for (std::uint32_t id = first; id < end; ++id)
                                    packedNormals_[id] = packNormal(surface.gradientNormal(id));
                            });
    }
    bytes += uploadColumns(surface);
    return bytes;
}

} // namespace sandglass
