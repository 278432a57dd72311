#include "view/render/grain_gpu_store.hpp"

#include "view/render/grain_instances.hpp"

#include "sandcore/display_positions.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace sandglass {

namespace {

constexpr std::uint32_t kNotListed = std::numeric_limits<std::uint32_t>::max();

// Sends the elements named by `indices` (sorted here) from `all`, one glBufferSubData per run of
// indices at most maxGap apart (the gaps go up too, unchanged: fewer calls for a few bytes more).
// Returns the bytes sent.
template <class T>
std::int64_t uploadRuns(GLenum target, GLuint buffer, std::span<const T> all, std::vector<std::uint32_t>& indices,
                        std::uint32_t maxGap) {
    if (indices.empty()) return 0;
    std::sort(indices.begin(), indices.end());
    glBindBuffer(target, buffer);
    std::int64_t bytes = 0;
    for (std::size_t first = 0; first < indices.size();) {
        std::size_t last = first;
        while (last + 1 < indices.size() && indices[last + 1] <= indices[last] + 1 + maxGap) ++last;
        const auto count = std::size_t(indices[last] - indices[first] + 1);
        glBufferSubData(target, GLintptr(std::size_t(indices[first]) * sizeof(T)), GLsizeiptr(count * sizeof(T)),
                        all.data() + indices[first]);
        bytes += std::int64_t(count * sizeof(T));
        first = last + 1;
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
        changedSlots_.push_back(slot);
        return;
    }
    const std::uint32_t last = visible_.back();
    visible_[slot] = last;
    slotOf_[last] = slot;
    if (last != grain) changedSlots_.push_back(slot);
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
    sortedIds_.clear();
    for (const sandcore::ColumnRef& ref : surface.changedColumns()) {
        const std::size_t texel = (ref.level == sandcore::GridLevel::Upper ? layer : 0) + ref.column;
        packedColumns_[texel] = packNormal(surface.columnNormals(ref.level)[ref.column]);
        sortedIds_.push_back(std::uint32_t(texel));
    }
    if (sortedIds_.empty()) return 0;
    std::sort(sortedIds_.begin(), sortedIds_.end());
    glBindTexture(GL_TEXTURE_2D, columnNormals_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    std::int64_t bytes = 0;
    const auto width = std::uint32_t(columnsX_);
    for (std::size_t first = 0; first < sortedIds_.size();) {
        // A run of texels in one row of the texture goes up as one rectangle.
        std::size_t last = first;
        while (last + 1 < sortedIds_.size() && sortedIds_[last + 1] == sortedIds_[last] + 1 &&
               sortedIds_[last + 1] / width == sortedIds_[first] / width)
            ++last;
        const std::uint32_t texel = sortedIds_[first];
        const auto runLength = GLsizei(sortedIds_[last] - texel + 1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, GLint(texel % width), GLint(texel / width), runLength, 1, GL_RED_INTEGER,
                        GL_UNSIGNED_INT, packedColumns_.data() + texel);
        bytes += std::int64_t(runLength) * 4;
        first = last + 1;
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    return bytes;
}

std::int64_t GrainGpuStore::uploadChanges(const sandcore::Scene& scene, const sandcore::SurfaceUpkeep& surface) {
    const sandcore::GrainStore& grains = scene.grains();
    std::int64_t bytes = 0;
    sortedIds_.assign(surface.movedGrains().begin(), surface.movedGrains().end());
    for (std::uint32_t id : sortedIds_) places_[id] = placeOf(grains, id);
    bytes += uploadRuns(GL_TEXTURE_BUFFER, places_gpu_.buffer.get(), std::span<const GrainPlace>(places_), sortedIds_, 0);
    changedSlots_.clear();
    for (std::uint32_t id : surface.changedInnerFlags()) setVisible(id, !surface.isInner(id));
    // Slots past the end were vacated: nothing draws them.
    std::erase_if(changedSlots_, [&](std::uint32_t slot) { return slot >= visible_.size(); });
    bytes += uploadRuns(GL_ARRAY_BUFFER, visibleBuffer_.get(), std::span<const std::uint32_t>(visible_), changedSlots_, 2);
    if (gradientUploaded_) {
        sortedIds_.assign(surface.changedGradientNormals().begin(), surface.changedGradientNormals().end());
        for (std::uint32_t id : sortedIds_) packedNormals_[id] = packNormal(surface.gradientNormal(id));
        bytes += uploadRuns(GL_TEXTURE_BUFFER, normals_gpu_.buffer.get(), std::span<const std::uint32_t>(packedNormals_),
                            sortedIds_, 4);
    }
    bytes += uploadColumns(surface);
    return bytes;
}

} // namespace sandglass
