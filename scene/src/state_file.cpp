// SPDX-License-Identifier: MIT
#include "scene/state_file.hpp"

#include "byte_codec.hpp"
#include "compression.hpp"
#include "snapshot_codec.hpp"

#include "scene/file_io.hpp"
#include "scene/model_voxelizer.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

namespace sandglass {

using sandcore::CellGrid;
using sandcore::GridLevel;

namespace {

constexpr std::array<std::uint8_t, 8> kSignature{0x89, 'S', 'A', 'N', 'D', '\r', '\n', 0x1a};
constexpr std::uint64_t kMaxRequestFields = 64;
constexpr std::size_t kMaxFieldText = 4096;

// ---- the scene request as named text fields: a field this version does not know is skipped,
// so later versions can add options without breaking older readers of the same format version.

using Fields = std::vector<std::pair<std::string, std::string>>;

std::string numberText(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// The model as the file stores it: relative to the .sand file's folder when the file is known
// and both lie on one tree, else as given; and its absolute path, the fallback when the
// relative one does not lead to it (the .sand file moved without its model).
std::pair<std::string, std::string> storedModelPaths(const std::string& model, const std::filesystem::path& savedAt) {
    if (model.empty() || savedAt.empty()) return {model, {}};
    std::error_code error;
    const std::filesystem::path absoluteModel = std::filesystem::absolute(model, error).lexically_normal();
    if (error) return {model, {}};
    const std::filesystem::path folder = std::filesystem::absolute(savedAt, error).parent_path().lexically_normal();
    if (error) return {model, absoluteModel.string()};
    const std::filesystem::path relative = absoluteModel.lexically_relative(folder);
    return {relative.empty() ? absoluteModel.string() : relative.generic_string(), absoluteModel.string()};
}

bool isFile(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
}

// The stored model path as a file this program can open: version 2 resolves a relative path
// against the .sand file's folder and falls back to the absolute path stored beside it.
std::string resolvedModelPath(const std::string& stored, const std::string& absolute, const std::filesystem::path& file) {
    const std::filesystem::path path(stored);
    if (stored.empty() || path.is_absolute()) return stored;
    std::error_code error;
    const std::filesystem::path beside = std::filesystem::absolute(file.parent_path() / path, error).lexically_normal();
    if (!error && isFile(beside)) return beside.string();
    if (!absolute.empty() && isFile(absolute)) return absolute;
    return error ? stored : beside.string();
}

Fields requestFields(const SceneRequest& r, const std::filesystem::path& savedAt) {
    const auto [model, modelAbsolute] = storedModelPaths(r.modelPath, savedAt);
    Fields fields{{"kind", sceneKindName(r.kind)},
                  {"shape", r.shape},
                  {"resolution", std::to_string(r.resolution)},
                  {"neck_radius", numberText(r.neckRadius)},
                  {"fill_fraction", numberText(r.fillFraction)},
                  {"model", model},
                  {"stretch", r.stretch ? "1" : "0"},
                  {"robust", r.robust ? "1" : "0"},
                  {"noise_threshold", std::to_string(r.noiseThreshold)},
                  {"drain_completely", r.drainCompletely ? "1" : "0"}};
    if (!modelAbsolute.empty()) fields.emplace_back("model_absolute", modelAbsolute);
    return fields;
}

template <class Number> Number parseNumber(const std::string& key, const std::string& text) {
    Number value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw FormatError("scene option '" + key + "' has the value '" + text + "', not a number");
    return value;
}

SceneRequest requestFrom(const Fields& fields, const std::filesystem::path& file, std::uint32_t version) {
    SceneRequest r;
    std::string modelAbsolute;
    for (const auto& [key, value] : fields) {
        if (key == "kind") {
            try {
                r.kind = parseSceneKind(value);
            } catch (const std::invalid_argument& e) {
                throw FormatError(std::string("scene option 'kind': ") + e.what());
            }
        } else if (key == "shape") r.shape = value;
        else if (key == "resolution") r.resolution = parseNumber<int>(key, value);
        else if (key == "neck_radius") r.neckRadius = parseNumber<float>(key, value);
        else if (key == "fill_fraction") r.fillFraction = parseNumber<float>(key, value);
        else if (key == "model") r.modelPath = value;
        else if (key == "stretch") r.stretch = parseNumber<int>(key, value) != 0;
        else if (key == "robust") r.robust = parseNumber<int>(key, value) != 0;
        else if (key == "noise_threshold") r.noiseThreshold = parseNumber<int>(key, value);
        else if (key == "drain_completely") r.drainCompletely = parseNumber<int>(key, value) != 0;
        else if (key == "model_absolute") modelAbsolute = value;
    }
    // Version 1 stored the path as it was typed, relative to wherever the program ran: kept as is.
    if (version >= 2) r.modelPath = resolvedModelPath(r.modelPath, modelAbsolute, file);
    return r;
}

// ---- layouts: EMPTY or INVALID per cell, one byte each.

void writeLayout(ByteWriter& out, const CellGrid& layout) {
    const sandcore::Int3 s = layout.size();
    for (int v : {s.x, s.y, s.z}) out.put<std::int32_t>(v);
    std::vector<std::uint8_t> invalid(layout.cellCount());
    for (std::uint32_t n = 0; n < layout.cellCount(); ++n) invalid[n] = layout[n] == sandcore::kInvalid ? 1 : 0;
    out.putArray(invalid);
}

CellGrid readLayout(ByteReader& in, const char* what) {
    sandcore::Int3 size;
    size.x = in.get<std::int32_t>(what);
    size.y = in.get<std::int32_t>(what);
    size.z = in.get<std::int32_t>(what);
    try {
        sandcore::validateGridSize(size);
    } catch (const std::invalid_argument& e) {
        throw FormatError(std::string(what) + ": " + e.what());
    }
    const std::uint64_t cells = std::uint64_t(size.x) * std::uint64_t(size.y) * std::uint64_t(size.z);
    if (cells > in.remaining()) throw FormatError(std::string(what) + ": the data ends early");
    const std::vector<std::uint8_t> invalid = in.getArray<std::uint8_t>(what, cells);
    CellGrid layout(size);
    for (std::uint32_t n = 0; n < layout.cellCount(); ++n) {
        if (invalid[n] > 1) throw FormatError(std::string(what) + ": a cell that is neither EMPTY nor INVALID");
        layout[n] = invalid[n] ? sandcore::kInvalid : sandcore::kEmpty;
    }
    return layout;
}

// ---- the header.

void putU32(std::uint8_t* at, std::uint32_t v) { std::memcpy(at, &v, 4); }
void putU64(std::uint8_t* at, std::uint64_t v) { std::memcpy(at, &v, 8); }
std::uint32_t getU32(const std::uint8_t* at) {
    std::uint32_t v;
    std::memcpy(&v, at, 4);
    return v;
}
std::uint64_t getU64(const std::uint8_t* at) {
    std::uint64_t v;
    std::memcpy(&v, at, 8);
    return v;
}

std::uint64_t fileChecksum(std::span<const std::uint8_t> header, std::span<const std::uint8_t> compressed) {
    return stateChecksum(compressed, stateChecksum(header.first(32)));
}

std::string gibibytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GiB", double(bytes) / double(1ull << 30));
    return text;
}

} // namespace

std::uint64_t stateChecksum(std::span<const std::uint8_t> bytes, std::uint64_t seed) {
    constexpr std::uint64_t kPrime1 = 0x9e3779b185ebca87ull, kPrime2 = 0xc2b2ae3d27d4eb4full;
    // Each step is a bijection of the running value for a fixed word and of the word for a fixed
    // running value, so changing any one word always changes the result.
    std::uint64_t h = seed ^ (std::uint64_t(bytes.size()) * kPrime2);
    const auto absorb = [&](std::uint64_t word) { h = std::rotl(h ^ (word * kPrime1), 31) * kPrime2; };
    std::size_t at = 0;
    for (; at + 8 <= bytes.size(); at += 8) {
        std::uint64_t word;
        std::memcpy(&word, bytes.data() + at, 8);
        absorb(word);
    }
    if (at < bytes.size()) {
        std::uint64_t word = 0;
        std::memcpy(&word, bytes.data() + at, bytes.size() - at);
        absorb(word);
    }
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    return h;
}

std::vector<std::uint8_t> encodeStatePayload(const sandcore::Scene& scene, const SceneRequest& request,
                                             const std::filesystem::path& savedAt) {
    ByteWriter out;
    out.reserve(encodedSnapshotBytes(scene) + 2 * std::size_t(scene.grid(GridLevel::Upper).cellCount()) +
                2 * std::size_t(scene.grid(GridLevel::Lower).cellCount()) + 4 * scene.fillCells().size() + 4096);
    // The file names the scene by its kind and builds it again from sceneShapeOf(kind).
    if (sandcore::sceneShapeOf(request.kind) != scene.shape())
        throw std::invalid_argument(std::string("the scene is not of the kind its request names (") +
                                    sceneKindName(request.kind) + ")");
    out.put<std::uint8_t>(std::uint8_t(request.kind));
    out.put<std::uint64_t>(scene.settings().seed);
    out.put<std::int32_t>(scene.settings().threads);
    out.put<std::uint8_t>(scene.settings().sleeping ? 1 : 0);
    out.put<std::uint8_t>(scene.flipped() ? 1 : 0);
    out.put<std::uint8_t>(std::uint8_t(scene.settings().physics.level));
    out.put<float>(scene.settings().physics.reposeDegrees);
    out.put<float>(scene.settings().physics.gravity);
    const Fields fields = requestFields(request, savedAt);
    out.put<std::uint64_t>(fields.size());
    for (const auto& [key, value] : fields) {
        out.putString(key);
        out.putString(value.size() <= kMaxFieldText ? value : value.substr(0, kMaxFieldText));
    }
    writeLayout(out, scene.layout(GridLevel::Upper));
    writeLayout(out, scene.layout(GridLevel::Lower));
    out.putArray(scene.fillCells());
    writeSnapshot(out, scene);
    return std::move(out.bytes());
}

std::vector<std::uint8_t> sealStateFile(std::span<const std::uint8_t> payload) {
    const std::vector<std::uint8_t> compressed = compressBytes(payload);
    std::vector<std::uint8_t> file(kStateHeaderBytes + compressed.size(), 0);
    std::copy(kSignature.begin(), kSignature.end(), file.begin());
    putU32(file.data() + 8, kStateFileVersion);
    putU32(file.data() + 12, 0);
    putU64(file.data() + 16, payload.size());
    putU64(file.data() + 24, compressed.size());
    std::copy(compressed.begin(), compressed.end(), file.begin() + std::ptrdiff_t(kStateHeaderBytes));
    putU64(file.data() + 32, fileChecksum(std::span(file).first(kStateHeaderBytes), compressed));
    return file;
}

std::vector<std::uint8_t> encodeStateFile(const sandcore::Scene& scene, const SceneRequest& request,
                                          const std::filesystem::path& savedAt) {
    return sealStateFile(encodeStatePayload(scene, request, savedAt));
}

std::uint32_t stateFileVersion(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 12 ? getU32(bytes.data() + 8) : 0;
}

std::vector<std::uint8_t> openStateFile(std::span<const std::uint8_t> bytes, const std::filesystem::path& file,
                                        const StateLoadLimits& limits) {
    if (bytes.empty()) throw FileError(file, "is empty, not a sandglass state file");
    const std::size_t signatureBytes = std::min(bytes.size(), kSignature.size());
    if (!std::equal(kSignature.begin(), kSignature.begin() + std::ptrdiff_t(signatureBytes), bytes.begin()))
        throw FileError(file, "is not a sandglass state file (no .sand signature)");
    if (bytes.size() < kStateHeaderBytes)
        throw FileError(file, "is truncated: " + std::to_string(bytes.size()) + " bytes, shorter than the " +
                                  std::to_string(kStateHeaderBytes) + "-byte header");
    const std::uint32_t version = getU32(bytes.data() + 8);
    if (version < kOldestStateFileVersion || version > kStateFileVersion)
        throw FileError(file, "is a state file of format version " + std::to_string(version) +
                                  "; this program reads versions " + std::to_string(kOldestStateFileVersion) + " to " +
                                  std::to_string(kStateFileVersion));
    if (getU32(bytes.data() + 12) != 0 || getU64(bytes.data() + 40) != 0)
        throw FileError(file, "is corrupted (unknown header flags)");
    const std::uint64_t payloadBytes = getU64(bytes.data() + 16);
    const std::uint64_t compressedBytes = getU64(bytes.data() + 24);
    const std::uint64_t present = bytes.size() - kStateHeaderBytes;
    if (compressedBytes > present)
        throw FileError(file, "is truncated: " + std::to_string(present) + " of " + std::to_string(compressedBytes) +
                                  " bytes of data are there");
    if (compressedBytes < present)
        throw FileError(file, "is corrupted: " + std::to_string(present - compressedBytes) +
                                  " bytes follow the end of the data");
    const std::span<const std::uint8_t> compressed = bytes.subspan(kStateHeaderBytes);
    if (fileChecksum(bytes.first(kStateHeaderBytes), compressed) != getU64(bytes.data() + 32))
        throw FileError(file, "is corrupted (checksum mismatch)");
    // The state, decompressed, and the scene built from it each take about payloadBytes.
    const std::uint64_t limit = limits.memoryLimit != 0 ? limits.memoryLimit : availableMemoryBytes();
    if (payloadBytes > limit / 3)
        throw FileError(file, "holds a state of " + gibibytes(payloadBytes) + ", too large for the " +
                                  gibibytes(limit) + " of memory available");
    try {
        return decompressBytes(compressed, payloadBytes);
    } catch (const FormatError& e) {
        throw FileError(file, std::string("is corrupted: ") + e.what());
    }
}

LoadedState decodeStatePayload(std::span<const std::uint8_t> payload, const std::filesystem::path& file,
                               std::uint32_t version) {
    try {
        ByteReader in(payload);
        const auto kind = in.get<std::uint8_t>("scene kind");
        if (kind > std::uint8_t(sandcore::SceneKind::Canvas)) throw FormatError("unknown scene kind " + std::to_string(kind));
        sandcore::StepSettings settings;
        settings.seed = in.get<std::uint64_t>("seed");
        settings.threads = in.get<std::int32_t>("threads");
        if (!kThreadsRange.contains(settings.threads))
            throw FormatError("thread count " + std::to_string(settings.threads) + " out of range");
        const auto sleeping = in.get<std::uint8_t>("sleeping");
        if (sleeping > 1) throw FormatError("the sleeping flag is neither on nor off");
        settings.sleeping = sleeping == 1;
        const auto flipped = in.get<std::uint8_t>("turned over");
        if (flipped > 1) throw FormatError("the turned-over flag is neither on nor off");
        const auto level = in.get<std::uint8_t>("physics level");
        if (level > std::uint8_t(sandcore::PhysicsLevel::Granular)) throw FormatError("unknown physics level");
        settings.physics.level = sandcore::PhysicsLevel(level);
        settings.physics.reposeDegrees = in.get<float>("repose angle");
        settings.physics.gravity = in.get<float>("gravity");
        try {
            sandcore::validatePhysics(settings.physics);
        } catch (const std::invalid_argument& e) {
            throw FormatError(e.what());
        }
        const auto fieldCount = in.get<std::uint64_t>("scene options");
        if (fieldCount > kMaxRequestFields) throw FormatError(std::to_string(fieldCount) + " scene options cannot be right");
        Fields fields;
        for (std::uint64_t i = 0; i < fieldCount; ++i) {
            std::string key = in.getString("scene option name", 64);
            std::string value = in.getString("scene option value", kMaxFieldText);
            fields.emplace_back(std::move(key), std::move(value));
        }
        SceneRequest request = requestFrom(fields, file, version);
        CellGrid upperLayout = readLayout(in, "upper layout");
        CellGrid lowerLayout = readLayout(in, "lower layout");
        std::vector<std::uint32_t> fill = in.getArray<std::uint32_t>("fill cells");
        sandcore::SceneSnapshot snapshot = readSnapshot(in);
        if (in.remaining() != 0) throw FormatError(std::to_string(in.remaining()) + " bytes follow the state");
        requireConsistentSnapshot(snapshot, upperLayout, lowerLayout);
        if (flipped == 1) {
            // A turned hourglass is built upright, as its fill expects, and restored turned.
            if (!sandcore::sceneShapeOf(sandcore::SceneKind(kind)).turnsOver) throw FormatError("only an hourglass turns over");
            CellGrid upright = sandcore::mirroredInY(lowerLayout);
            lowerLayout = sandcore::mirroredInY(upperLayout);
            upperLayout = std::move(upright);
            snapshot.flipped = true;
        }
        request.kind = sandcore::SceneKind(kind);
        try {
            sandcore::Scene scene(sandcore::sceneShapeOf(sandcore::SceneKind(kind)), std::move(upperLayout), std::move(lowerLayout),
                                  std::move(fill), settings);
            scene.restore(snapshot);
            return {std::move(scene), SceneSettings{std::move(request), settings}};
        } catch (const std::invalid_argument& e) {
            throw FormatError(e.what());
        }
    } catch (const FormatError& e) {
        throw FileError(file, std::string("is corrupted: ") + e.what());
    } catch (const std::bad_alloc&) {
        throw FileError(file, "holds a state too large for the memory available");
    }
}

void saveState(const std::filesystem::path& file, const sandcore::Scene& scene, const SceneRequest& request) {
    requireWritableFileTarget(file);
    writeFileAtomically(file, std::span<const std::uint8_t>(encodeStateFile(scene, request, file)));
}

LoadedState loadState(const std::filesystem::path& file, const StateLoadLimits& limits) {
    const std::vector<std::uint8_t> bytes = readFileBytes(file, limits.maxFileBytes);
    const std::vector<std::uint8_t> payload = openStateFile(bytes, file, limits);
    return decodeStatePayload(payload, file, stateFileVersion(bytes));
}

} // namespace sandglass
