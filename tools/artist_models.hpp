// SPDX-License-Identifier: MIT
#pragma once
// Hourglass models as 3D artists make them (SPEC S7-S9): glass with wall thickness, frames of
// plates and pillars as separate named objects with MTL colours, and a one-file binary STL with Z up.

#include <string>

/// Writes framed_hourglass.obj/.mtl (Y up, parts), framed_hourglass_z.stl (one binary STL, Z up)
/// and capped_glass.obj/.mtl (a glass with a closed inner cavity, caps and posts) into `dir`.
bool writeArtistModels(const std::string& dir);
