// SPDX-License-Identifier: MIT
#pragma once
// Random numbers from std::mt19937_64, whose output the standard fixes, turned into values by
// hand: the standard library's distributions differ between implementations, and the corpus
// must be the same everywhere.

#include <cmath>
#include <cstdint>
#include <random>

namespace sandglass::wild {

using Rng = std::mt19937_64;

/// A double in [0, 1) from the top 53 bits of one draw.
inline double unitDraw(Rng& rng) { return double(rng() >> 11) * 0x1.0p-53; }
/// A double in [a, b).
inline double uniform(Rng& rng, double a, double b) { return a + (b - a) * unitDraw(rng); }
/// An integer in [low, high]; the modulo bias is far below anything a test could see.
inline int uniformInt(Rng& rng, int low, int high) { return low + int(rng() % std::uint64_t(high - low + 1)); }
/// True with probability p.
inline bool chance(Rng& rng, double p) { return unitDraw(rng) < p; }
/// A double whose logarithm is uniform in [log a, log b).
inline double logUniform(Rng& rng, double a, double b) { return std::exp(uniform(rng, std::log(a), std::log(b))); }

} // namespace sandglass::wild
