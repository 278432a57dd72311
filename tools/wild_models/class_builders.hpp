// SPDX-License-Identifier: MIT
#pragma once
// One builder per model class, each making its canonical model from the random stream, and the
// pieces several classes share (frames of plates and posts, names as exporters write them).

#include "canonical_parts.hpp"
#include "seeded_random.hpp"

#include <initializer_list>
#include <string>
#include <vector>

namespace sandglass::wild {

CanonicalModel buildThickFramed(Rng& rng);     ///< glass with a wall thickness in a frame
CanonicalModel buildSingleWall(Rng& rng);      ///< a one-surface glass, closed or covered by plates
CanonicalModel buildOpenBulbsPlates(Rng& rng); ///< two open bulbs closed by stacked plates and caps
CanonicalModel buildOneObjectAsset(Rng& rng);  ///< glass, modelled sand, posts and plates in one object
CanonicalModel buildConesRingsPost(Rng& rng);  ///< one closed surface of discs and cones with a hair-thin neck
CanonicalModel buildFunnel(Rng& rng);          ///< an open hopper
CanonicalModel buildCharacter(Rng& rng);       ///< an open humanoid of overlapping shells
CanonicalModel buildKeyboard(Rng& rng);        ///< 89 keys, each thinner than a cell at resolution 64

/// Segments around a surface of revolution, as modellers choose them.
inline int randomSegments(Rng& rng) { return uniformInt(rng, 24, 64); }
/// One of the names.
std::string pick(Rng& rng, std::initializer_list<const char*> names);
/// The profile moved up so that height 0 lies at canonical y = bottom.
std::vector<ProfileSample> raised(std::vector<ProfileSample> profile, double bottom);
/// The largest radius of a profile.
double widest(const std::vector<ProfileSample>& profile);

/// Two plates, at y in [0, plate] and [height - plate, height], and optional posts between them.
struct FrameRequest {
    double plate = 0.05;       ///< plate thickness, canonical units
    double height = 1.0;       ///< from the bottom of the lower plate to the top of the upper one
    double clearRadius = 0.3;  ///< the glass's outer radius: posts stand outside it
    bool posts = true;         ///< posts between the plates
    bool postsInside = false;  ///< posts reach a little into the plates, as modellers often leave them
};

/// A random frame, its parts named either one by one or as one "Frame" object.
std::vector<Part> randomFrame(Rng& rng, const FrameRequest& request);
/// All parts joined into one, named `name`.
Part merged(const std::vector<Part>& parts, std::string name);

} // namespace sandglass::wild
