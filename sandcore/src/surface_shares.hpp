// SPDX-License-Identifier: MIT
#pragma once
// What the two files of SurfaceUpkeep share (surface_upkeep.cpp: the flags, gradients and heights;
// surface_moves.cpp: the moved grains' cells into the bits). Private to sandcore.

#include "sandcore/surface_upkeep.hpp"
#include "worker_pool.hpp"

#include <cstddef>
#include <cstdint>

namespace sandcore {

namespace surface {

/// What a grain is listed for in a step's change lists (GrainSurface::listed).
inline constexpr std::uint8_t kPlaceListed = 1, kInnerListed = 2, kGradientListed = 4;

template <class T> void prefetch(const T* address) { __builtin_prefetch(address); }

} // namespace surface

// part(share) for each share in use: side by side on the pool's threads, or share 0 alone.
template <class Part> void SurfaceUpkeep::forEachShare(WorkerPool* pool, Part&& part) {
    if (pool != nullptr) pool->parallelFor(2, [&](int s) { part(shares_[std::size_t(s)]); });
    else part(shares_[0]);
}

} // namespace sandcore
