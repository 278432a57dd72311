// SPDX-License-Identifier: MIT
// Why another process: assimp (Debian's 5.x) crashes with SIGSEGV, aborts in ai_assert and loops
// forever on truncated or byte-flipped PLY and OFF files. aiProcess_ValidateDataStructure turns
// some of these into errors, not all, and no check of ours can know every reader's bugs. So the
// import runs in a child process; the parent waits with a time limit and reads a plain triangle
// list from a pipe, checking every count and index.
//
// The child is the small executable sandglass-import (scene/src/import_helper_main.cpp), started with fork + exec.
// The GUI builds scenes on a worker thread, so the fork happens in a multi-threaded process:
// only the forking thread exists in the child, and a lock another thread held at the fork stays
// locked there (under ASan even malloc's). Between fork and exec the child therefore calls only
// async-signal-safe functions (dup2, open, setrlimit, execv, _exit) on strings prepared before
// the fork; exec then gives it a fresh process image with no inherited lock.
//
// Should the helper be missing (a library user who did not build it), the child runs the import
// itself after the fork: glibc's malloc is fork-safe and the child uses no stdio, GL or logging,
// and if it still blocks on a lock the time limit ends it with one line. The parent is never at
// risk. The child leaves with _exit, so no handler or static destructor of the parent runs twice.

#include "isolated_import.hpp"

#ifdef SANDGLASS_FIND_IMPORT_HELPER
#include "scene/data_paths.hpp"
#endif

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace sandglass {

namespace {

constexpr char kMagic[4] = {'S', 'G', 'T', 'L'};

using Matrix = std::array<double, 16>; // row-major 4x4, as aiMatrix4x4

Matrix toDouble(const aiMatrix4x4& m) {
    return {m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4};
}

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k) sum += a[std::size_t(4 * i + k)] * b[std::size_t(4 * k + j)];
            r[std::size_t(4 * i + j)] = sum;
        }
    return r;
}

// Node transforms are composed and applied in double: a model far from the origin keeps what
// precision the file gave it.
void appendNode(const aiScene& scene, const aiNode& node, const Matrix& parent, ImportedTriangles& out, int depth) {
    if (depth > 1000) throw std::runtime_error("the node hierarchy is deeper than 1000 levels");
    const Matrix transform = multiply(parent, toDouble(node.mTransformation));
    // S7: a node with meshes is one part, named after the node (or its first named mesh).
    ImportedPart part;
    part.name = node.mName.C_Str();
    const std::size_t firstTriangle = out.triangles.size();
    for (unsigned m = 0; m < node.mNumMeshes; ++m) {
        if (node.mMeshes == nullptr || node.mMeshes[m] >= scene.mNumMeshes || scene.mMeshes == nullptr ||
            scene.mMeshes[node.mMeshes[m]] == nullptr)
            throw std::runtime_error("a node refers to a missing mesh");
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
        if (part.name.empty()) part.name = mesh.mName.C_Str();
        aiColor4D diffuse;
        if (!part.hasColour && mesh.mMaterialIndex < scene.mNumMaterials && scene.mMaterials != nullptr &&
            scene.mMaterials[mesh.mMaterialIndex] != nullptr &&
            (scene.mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_BASE_COLOR, diffuse) == AI_SUCCESS ||
             scene.mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) &&
            std::isfinite(diffuse.r) && std::isfinite(diffuse.g) && std::isfinite(diffuse.b)) {
            part.hasColour = true;
            part.colour = {std::clamp(float(diffuse.r), 0.0f, 1.0f), std::clamp(float(diffuse.g), 0.0f, 1.0f),
                           std::clamp(float(diffuse.b), 0.0f, 1.0f)};
        }
        if (mesh.mNumVertices > 0 && mesh.mVertices == nullptr) throw std::runtime_error("a mesh has no positions");
        const std::size_t base = out.vertices.size();
        if (base + mesh.mNumVertices > 0xffffffffull) throw std::runtime_error("more than 2^32 vertices");
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const double p[3] = {mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z};
            std::array<double, 3> world{};
            for (std::size_t r = 0; r < 3; ++r)
                world[r] = transform[4 * r] * p[0] + transform[4 * r + 1] * p[1] + transform[4 * r + 2] * p[2] +
                           transform[4 * r + 3];
            out.vertices.push_back(world);
        }
        for (unsigned f = 0; f < mesh.mNumFaces && mesh.mFaces != nullptr; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3 || face.mIndices == nullptr) continue; // points and lines enclose nothing
            std::array<std::uint32_t, 3> t{};
            for (std::size_t i = 0; i < 3; ++i) {
                if (face.mIndices[i] >= mesh.mNumVertices) throw std::runtime_error("a face refers to a missing vertex");
                t[i] = std::uint32_t(base + face.mIndices[i]);
            }
            out.triangles.push_back(t);
        }
    }
    part.triangleCount = out.triangles.size() - firstTriangle;
    if (part.triangleCount > 0) out.parts.push_back(std::move(part));
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        if (node.mChildren != nullptr && node.mChildren[c] != nullptr)
            appendNode(scene, *node.mChildren[c], transform, out, depth + 1);
}

std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

// assimp's PLY reader loops forever when a binary file ends inside its header; a PLY file
// whose header has no end_header line is refused before assimp sees it.
std::string plyHeaderProblem(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return {};
    std::string head(64 * 1024, '\0');
    std::size_t got = 0;
    while (got < head.size()) {
        const ssize_t n = ::read(fd, head.data() + got, head.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += std::size_t(n);
    }
    ::close(fd);
    head.resize(got);
    if (head.rfind("ply", 0) != 0) return {};
    if (head.find("end_header") == std::string::npos) return "the PLY header has no end_header line (truncated or corrupt)";
    return {};
}

void put(std::vector<std::uint8_t>& out, const void* data, std::size_t size) {
    if (size == 0) return;
    const std::size_t at = out.size();
    out.resize(at + size);
    std::memcpy(out.data() + at, data, size);
}

// Reads from a pipe until the writer closes it or the deadline passes; false on timeout.
bool readUntilClosed(int fd, std::chrono::steady_clock::time_point deadline, std::vector<std::uint8_t>& bytes) {
    std::uint8_t buffer[65536];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return false;
        pollfd watch{fd, POLLIN, 0};
        const int ready = ::poll(&watch, 1, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) return true; // treated as a closed pipe: the reply is decoded as it is
        if (ready == 0) continue;
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n <= 0) return true;
        bytes.insert(bytes.end(), buffer, buffer + n);
    }
}

[[noreturn]] void runChild(const std::string& path, int replyFd) {
    // Output of the importer (assert messages, sanitizer reports) must not reach the user's
    // terminal: the parent prints one line.
    const int devNull = ::open("/dev/null", O_WRONLY);
    if (devNull >= 0) {
        ::dup2(devNull, STDOUT_FILENO);
        ::dup2(devNull, STDERR_FILENO);
    }
    const rlimit noCore{0, 0}; // a crash of a corrupt file is expected: no core file
    ::setrlimit(RLIMIT_CORE, &noCore);
    std::vector<std::uint8_t> reply;
    try {
        reply = encodeImport(importInThisProcess(path));
    } catch (...) {
        ImportedTriangles failed;
        failed.error = "the importer ran out of memory or failed";
        reply = encodeImport(failed);
    }
    std::size_t done = 0;
    while (done < reply.size()) {
        const ssize_t n = ::write(replyFd, reply.data() + done, reply.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) ::_exit(3);
        done += std::size_t(n);
    }
    ::_exit(0);
}

} // namespace

ImportedTriangles importInThisProcess(const std::string& path) {
    ImportedTriangles out;
    if (std::string problem = plyHeaderProblem(path); !problem.empty()) {
        out.error = problem;
        return out;
    }
    try {
        Assimp::Importer importer;
        // No aiProcess_JoinIdenticalVertices: its epsilon merges distinct vertices of a model at
        // millimetre scale; loadMesh joins bit-identical positions only.
        const aiScene* scene = importer.ReadFile(
            path, aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_SortByPType);
        if (scene == nullptr) {
            std::string cause = oneLine(importer.GetErrorString());
            out.error = "cannot be read as a model: " + (cause.empty() ? std::string("unknown import error") : cause);
            return out;
        }
        if (scene->mRootNode != nullptr) appendNode(*scene, *scene->mRootNode, toDouble(aiMatrix4x4()), out, 0);
    } catch (const std::exception& e) {
        out = {};
        out.error = "cannot be read as a model: " + oneLine(e.what());
    }
    return out;
}

std::vector<std::uint8_t> encodeImport(const ImportedTriangles& imported) {
    std::vector<std::uint8_t> out;
    // Room for the whole reply first (also keeps GCC 12 from a false -Wstringop-overflow).
    std::size_t names = 0;
    for (const ImportedPart& part : imported.parts) names += part.name.size();
    out.reserve(5 + 8 + imported.error.size() + 24 + imported.vertices.size() * 24 + imported.triangles.size() * 12 +
                imported.parts.size() * 29 + names);
    put(out, kMagic, sizeof kMagic);
    const std::uint8_t failed = imported.error.empty() ? 0 : 1;
    put(out, &failed, 1);
    if (failed) {
        const auto length = std::uint64_t(imported.error.size());
        put(out, &length, sizeof length);
        put(out, imported.error.data(), imported.error.size());
        return out;
    }
    const auto vertexCount = std::uint64_t(imported.vertices.size());
    const auto triangleCount = std::uint64_t(imported.triangles.size());
    put(out, &vertexCount, sizeof vertexCount);
    put(out, imported.vertices.data(), imported.vertices.size() * sizeof(imported.vertices[0]));
    put(out, &triangleCount, sizeof triangleCount);
    put(out, imported.triangles.data(), imported.triangles.size() * sizeof(imported.triangles[0]));
    const auto partCount = std::uint64_t(imported.parts.size());
    put(out, &partCount, sizeof partCount);
    for (const ImportedPart& part : imported.parts) {
        const auto nameLength = std::uint64_t(part.name.size());
        put(out, &nameLength, sizeof nameLength);
        put(out, part.name.data(), part.name.size());
        put(out, &part.triangleCount, sizeof part.triangleCount);
        const std::uint8_t hasColour = part.hasColour ? 1 : 0;
        put(out, &hasColour, 1);
        put(out, part.colour.data(), sizeof part.colour);
    }
    return out;
}

ImportedTriangles decodeImport(const std::vector<std::uint8_t>& bytes) {
    ImportedTriangles out;
    std::size_t at = 0;
    auto take = [&](void* into, std::size_t size) {
        if (bytes.size() - at < size) return false;
        if (size == 0) return true; // an empty vector's data() may be null: memcpy must not see it
        std::memcpy(into, bytes.data() + at, size);
        at += size;
        return true;
    };
    char magic[4];
    std::uint8_t failed = 0;
    if (!take(magic, 4) || std::memcmp(magic, kMagic, 4) != 0 || !take(&failed, 1)) {
        out.error = "the model importer gave no answer";
        return out;
    }
    std::uint64_t count = 0;
    if (failed) {
        if (!take(&count, sizeof count) || count > bytes.size() - at) {
            out.error = "the model importer failed";
            return out;
        }
        out.error = oneLine(std::string(reinterpret_cast<const char*>(bytes.data() + at), std::size_t(count)));
        if (out.error.empty()) out.error = "the model importer failed";
        return out;
    }
    const char* const garbled = "the model importer's answer is incomplete";
    if (!take(&count, sizeof count) || count > (bytes.size() - at) / 24) {
        out.error = garbled;
        return out;
    }
    out.vertices.resize(std::size_t(count));
    take(out.vertices.data(), out.vertices.size() * 24);
    auto fail = [&] {
        out = {};
        out.error = garbled;
        return out;
    };
    if (!take(&count, sizeof count) || count > (bytes.size() - at) / 12) return fail();
    out.triangles.resize(std::size_t(count));
    take(out.triangles.data(), out.triangles.size() * 12);
    for (const auto& t : out.triangles)
        for (std::uint32_t i : t)
            if (i >= out.vertices.size()) return fail();
    // The parts: each at least 8 + 8 + 1 + 12 bytes, their triangles adding up to all of them.
    if (!take(&count, sizeof count) || count > (bytes.size() - at) / 29) return fail();
    out.parts.resize(std::size_t(count));
    std::uint64_t covered = 0;
    for (ImportedPart& part : out.parts) {
        std::uint64_t nameLength = 0;
        if (!take(&nameLength, sizeof nameLength) || nameLength > bytes.size() - at) return fail();
        part.name.assign(reinterpret_cast<const char*>(bytes.data() + at), std::size_t(nameLength));
        at += std::size_t(nameLength);
        std::uint8_t hasColour = 0;
        if (!take(&part.triangleCount, sizeof part.triangleCount) || !take(&hasColour, 1) ||
            !take(part.colour.data(), sizeof part.colour))
            return fail();
        part.hasColour = hasColour != 0;
        for (float& channel : part.colour)
            if (!(channel >= 0.0f && channel <= 1.0f)) return fail();
        if (part.triangleCount > out.triangles.size() - covered) return fail();
        covered += part.triangleCount;
    }
    if (covered != out.triangles.size() || at != bytes.size()) return fail();
    return out;
}

ImportedTriangles importInChildProcess(const std::string& path, double timeLimitSeconds) {
    ImportedTriangles failed;
    // Everything the child needs before exec is prepared here: it may not allocate.
    const char* helper = nullptr;
#ifdef SANDGLASS_FIND_IMPORT_HELPER
    // Beside an installed executable or in the build tree (data_paths.hpp).
    const std::string helperPath = importHelperPath().string();
    if (!helperPath.empty()) helper = helperPath.c_str();
#endif
    std::string helperName = "sandglass-import", pathArgument = path;
    std::vector<char*> arguments = {helperName.data(), pathArgument.data(), nullptr};
    int reply[2];
    if (::pipe2(reply, O_CLOEXEC) != 0) {
        failed.error = std::string("cannot start the model importer (") + std::strerror(errno) + ")";
        return failed;
    }
    const pid_t child = ::fork();
    if (child < 0) {
        failed.error = std::string("cannot start the model importer (") + std::strerror(errno) + ")";
        ::close(reply[0]);
        ::close(reply[1]);
        return failed;
    }
    if (child == 0) {
        ::close(reply[0]);
        if (helper != nullptr) {
            // Async-signal-safe calls only, until exec.
            const int devNull = ::open("/dev/null", O_RDWR);
            if (devNull >= 0) {
                ::dup2(devNull, STDIN_FILENO);
                ::dup2(devNull, STDERR_FILENO);
            }
            ::dup2(reply[1], STDOUT_FILENO);
            const rlimit noCore{0, 0};
            ::setrlimit(RLIMIT_CORE, &noCore);
            ::execv(helper, arguments.data());
            ::_exit(127);
        }
        runChild(path, reply[1]);
    }
    ::close(reply[1]);
    const auto limit = std::chrono::duration<double>(timeLimitSeconds);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(limit);
    std::vector<std::uint8_t> bytes;
    const bool finished = readUntilClosed(reply[0], deadline, bytes);
    ::close(reply[0]);
    if (!finished) ::kill(child, SIGKILL);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (!finished) {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", timeLimitSeconds);
        failed.error = std::string("the model importer did not finish within ") + seconds +
                       " s (the file is probably corrupt)";
        return failed;
    }
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        const char* name = sigabbrev_np(signal);
        failed.error = "the model importer crashed on this file (signal " + std::to_string(signal) +
                       (name ? std::string(", SIG") + name : std::string()) + "); the file is probably corrupt";
        return failed;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127 && bytes.empty()) {
        failed.error = "cannot start the model importer " + std::string(helper ? helper : "");
        return failed;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        failed.error = "the model importer failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
        return failed;
    }
    return decodeImport(bytes);
}

} // namespace sandglass
