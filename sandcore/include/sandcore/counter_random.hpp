// SPDX-License-Identifier: MIT
#pragma once
// Counter-based randomness (R3): a random number is a pure function of its inputs, never the
// state of a shared generator, so results do not depend on threads or visiting order.

#include <cstdint>

namespace sandcore {

/// SplitMix64's finaliser: a bijective 64-bit mix with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ull;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebull;
    v ^= v >> 31;
    return v;
}

/// The part of counterRandom that depends on (seed, step) only: a sweep computes it once.
constexpr std::uint64_t counterRandomStepKey(std::uint64_t seed, std::uint64_t step) {
    return mix64(mix64(seed ^ 0x5851f42d4c957f2dull) ^ step);
}

/// counterRandom(seed, step, stream, index) from stepKey = counterRandomStepKey(seed, step).
constexpr std::uint64_t counterRandomFromKey(std::uint64_t stepKey, std::uint64_t stream, std::uint64_t index) {
    return mix64(stepKey ^ (index + (stream << 40)));
}

/// A random 64-bit value for (seed, step, stream, index): the same inputs always give the same value.
constexpr std::uint64_t counterRandom(std::uint64_t seed, std::uint64_t step, std::uint64_t stream,
                                      std::uint64_t index) {
    return counterRandomFromKey(counterRandomStepKey(seed, step), stream, index);
}

/// Maps a random value to [0, count) without division (Lemire's multiply-shift).
constexpr std::uint32_t pickBelow(std::uint64_t random, std::uint32_t count) {
    return std::uint32_t(((random >> 32) * std::uint64_t(count)) >> 32);
}

/// Maps a random value to [0, 1).
constexpr float unitFloat(std::uint64_t random) {
    return float(random >> 40) * (1.0f / float(1u << 24));
}

} // namespace sandcore
