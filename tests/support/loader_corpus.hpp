// SPDX-License-Identifier: MIT
#pragma once
// A fixed corpus of small valid files for every loader (models: OBJ, ASCII and binary PLY, OFF,
// ASCII and binary STL, glTF; drafts: PNG and JPEG) and a seeded mutator that truncates them and
// flips bits and bytes. The same seed gives the same files on every machine, so a failing case
// can be replayed by its name.

#include <stb_image_write.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace corpus {

/// One file of the corpus: a name with the format's extension and its bytes.
struct CorpusFile {
    std::string name;
    std::string bytes;
};

// An octahedron: 6 vertices, 8 faces, closed and counter-clockwise seen from outside.
inline const float kVertices[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
inline const int kFaces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

template <typename T> void putBinary(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

inline std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) n |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) n |= std::uint32_t(std::uint8_t(bytes[i + 2]));
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

/// The model files: the same octahedron in every format assimp is asked to read.
inline std::vector<CorpusFile> modelFiles() {
    std::vector<CorpusFile> files;
    std::string obj = "# octahedron\no shape\n";
    for (const auto& v : kVertices) obj += "v " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
    for (const auto& f : kFaces) obj += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
    files.push_back({"octahedron.obj", obj});

    const std::string plyHeader = "element vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                                  "element face 8\nproperty list uchar int vertex_indices\nend_header\n";
    std::string ascii = "ply\nformat ascii 1.0\n" + plyHeader;
    for (const auto& v : kVertices) ascii += std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
    for (const auto& f : kFaces) ascii += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    files.push_back({"octahedron_ascii.ply", ascii});

    std::string binary = "ply\nformat binary_little_endian 1.0\n" + plyHeader;
    for (const auto& v : kVertices)
        for (float c : v) putBinary(binary, c);
    for (const auto& f : kFaces) {
        putBinary(binary, std::uint8_t(3));
        for (int i : f) putBinary(binary, std::int32_t(i));
    }
    files.push_back({"octahedron_binary.ply", binary});

    std::string off = "OFF\n6 8 12\n";
    for (const auto& v : kVertices) off += std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
    for (const auto& f : kFaces) off += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    files.push_back({"octahedron.off", off});

    std::string stl = "solid octahedron\n";
    for (const auto& f : kFaces) {
        stl += "facet normal 0 0 0\nouter loop\n";
        for (int i : f)
            stl += "vertex " + std::to_string(kVertices[i][0]) + " " + std::to_string(kVertices[i][1]) + " " +
                   std::to_string(kVertices[i][2]) + "\n";
        stl += "endloop\nendfacet\n";
    }
    stl += "endsolid octahedron\n";
    files.push_back({"octahedron_ascii.stl", stl});

    std::string binaryStl(80, ' ');
    putBinary(binaryStl, std::uint32_t(8));
    for (const auto& f : kFaces) {
        for (int k = 0; k < 3; ++k) putBinary(binaryStl, 0.0f);
        for (int i : f)
            for (float c : kVertices[i]) putBinary(binaryStl, c);
        putBinary(binaryStl, std::uint16_t(0));
    }
    files.push_back({"octahedron_binary.stl", binaryStl});

    std::string buffer;
    for (const auto& v : kVertices)
        for (float c : v) putBinary(buffer, c);
    for (const auto& f : kFaces)
        for (int i : f) putBinary(buffer, std::uint16_t(i));
    const std::string gltf =
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
        "\"buffers\":[{\"byteLength\":" + std::to_string(buffer.size()) +
        ",\"uri\":\"data:application/octet-stream;base64," + base64(buffer) + "\"}],"
        "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":72},"
        "{\"buffer\":0,\"byteOffset\":72,\"byteLength\":48}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":6,\"type\":\"VEC3\","
        "\"min\":[-1,-1,-1],\"max\":[1,1,1]},{\"bufferView\":1,\"componentType\":5123,\"count\":24,\"type\":\"SCALAR\"}]}";
    files.push_back({"octahedron.gltf", gltf});
    return files;
}

inline void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

/// The draft images: a small gradient as PNG and as JPEG.
inline std::vector<CorpusFile> draftFiles() {
    const int width = 24, height = 16;
    std::vector<std::uint8_t> rgb(std::size_t(width * height * 3));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = rgb.data() + 3 * (y * width + x);
            p[0] = std::uint8_t(x * 10), p[1] = std::uint8_t(y * 15), p[2] = std::uint8_t((x ^ y) * 8);
        }
    std::vector<CorpusFile> files(2);
    files[0].name = "draft.png";
    stbi_write_png_to_func(appendBytes, &files[0].bytes, width, height, 3, rgb.data(), width * 3);
    files[1].name = "draft.jpg";
    stbi_write_jpg_to_func(appendBytes, &files[1].bytes, width, height, 3, rgb.data(), 90);
    return files;
}

/// `count` corrupted copies of `original`: truncations (inside the header as well as the body),
/// single and multiple bit flips, and bytes overwritten with digits, signs and extremes.
inline std::vector<CorpusFile> mutations(const CorpusFile& original, int count, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::vector<CorpusFile> out;
    const std::string& bytes = original.bytes;
    const std::size_t size = bytes.size();
    const auto dot = original.name.find_last_of('.');
    const std::string stem = original.name.substr(0, dot), extension = original.name.substr(dot);
    for (int n = 0; n < count; ++n) {
        std::string mutated = bytes;
        const int kind = n % 4;
        if (kind == 0) {
            // Truncations: short ones land in the header.
            const std::size_t keep = n < 8 ? std::size_t(random() % std::min<std::size_t>(size, 96)) : std::size_t(random() % size);
            mutated.resize(keep);
        } else if (kind == 1) {
            mutated[random() % size] ^= char(1u << (random() % 8));
        } else if (kind == 2) {
            const int flips = 2 + int(random() % 15);
            for (int f = 0; f < flips; ++f) mutated[random() % size] ^= char(1u << (random() % 8));
        } else {
            static const char replacements[] = {'0', '9', '-', '.', 'e', ' ', '\n', '\0', '\xff', '\x7f'};
            const int bytesChanged = 1 + int(random() % 4);
            for (int f = 0; f < bytesChanged; ++f)
                mutated[random() % size] = replacements[random() % sizeof replacements];
        }
        out.push_back({stem + "_" + std::to_string(n) + extension, mutated});
    }
    return out;
}

} // namespace corpus
