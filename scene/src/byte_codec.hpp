// SPDX-License-Identifier: MIT
#pragma once
// Little-endian binary writing and bounded reading for the state file (E1) and the undo
// history (E3). The reader checks every count against the bytes that are left before it
// allocates, so a damaged size can never make it reserve more memory than the input holds.

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sandglass {

static_assert(std::endian::native == std::endian::little, "the state file codec assumes a little-endian machine");

/// A damaged or inconsistent encoding; what() is the cause, without the file name.
class FormatError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Appends plain values and arrays of them to a byte buffer.
class ByteWriter {
public:
    template <class T> void put(T value) {
        static_assert(std::is_trivially_copyable_v<T>);
        append(&value, sizeof(T));
    }
    /// A count (u64) followed by the elements.
    template <class T> void putArray(std::span<const T> values) {
        static_assert(std::is_trivially_copyable_v<T>);
        put<std::uint64_t>(values.size());
        append(values.data(), values.size_bytes());
    }
    template <class T> void putArray(const std::vector<T>& values) { putArray(std::span<const T>(values)); }
    void putString(const std::string& text) {
        putArray(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
    }
    void reserve(std::size_t bytes) { bytes_.reserve(bytes); }
    std::vector<std::uint8_t>& bytes() { return bytes_; }

private:
    void append(const void* data, std::size_t size) {
        if (size == 0) return;
        const std::size_t at = bytes_.size();
        bytes_.resize(at + size);
        std::memcpy(bytes_.data() + at, data, size);
    }

    std::vector<std::uint8_t> bytes_;
};

/// Reads what ByteWriter wrote; throws FormatError on any overrun.
class ByteReader {
public:
    explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    template <class T> T get(const char* what) {
        static_assert(std::is_trivially_copyable_v<T>);
        require(sizeof(T), what);
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }
    /// An array written by putArray, of exactly `expected` elements unless expected is npos.
    template <class T> std::vector<T> getArray(const char* what, std::uint64_t expected = kAnyCount) {
        const auto count = get<std::uint64_t>(what);
        if (expected != kAnyCount && count != expected)
            throw FormatError(std::string(what) + ": " + std::to_string(count) + " entries where " +
                              std::to_string(expected) + " belong");
        if (count > remaining() / sizeof(T)) throw FormatError(std::string(what) + ": the data ends early");
        std::vector<T> values(static_cast<std::size_t>(count));
        if (count > 0) std::memcpy(values.data(), bytes_.data() + at_, std::size_t(count) * sizeof(T));
        at_ += std::size_t(count) * sizeof(T);
        return values;
    }
    /// An array written by putArray of exactly out.size() elements, read into out.
    template <class T> void getArrayInto(const char* what, std::span<T> out) {
        const auto count = get<std::uint64_t>(what);
        if (count != out.size())
            throw FormatError(std::string(what) + ": " + std::to_string(count) + " entries where " +
                              std::to_string(out.size()) + " belong");
        require(out.size_bytes(), what);
        if (!out.empty()) std::memcpy(out.data(), bytes_.data() + at_, out.size_bytes());
        at_ += out.size_bytes();
    }
    std::string getString(const char* what, std::size_t maxLength) {
        const auto length = get<std::uint64_t>(what);
        if (length > maxLength) throw FormatError(std::string(what) + ": a text longer than " + std::to_string(maxLength));
        require(std::size_t(length), what);
        std::string text(reinterpret_cast<const char*>(bytes_.data() + at_), std::size_t(length));
        at_ += std::size_t(length);
        return text;
    }
    std::size_t remaining() const { return bytes_.size() - at_; }
    static constexpr std::uint64_t kAnyCount = ~std::uint64_t{0};

private:
    void require(std::size_t bytes, const char* what) const {
        if (bytes > remaining()) throw FormatError(std::string(what) + ": the data ends early");
    }

    std::span<const std::uint8_t> bytes_;
    std::size_t at_ = 0;
};

} // namespace sandglass
