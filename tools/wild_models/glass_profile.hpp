// SPDX-License-Identifier: MIT
#pragma once
// The inner space of a glass as a radius profile r(h) about the y axis, canonical units: made at
// random as bulbs of varied shape around a neck, and queried as ground truth.

#include "seeded_random.hpp"
#include "wild_models/wild_models.hpp"

#include <vector>

namespace sandglass::wild {

/// One bulb: a superellipse of revolution, cut where it meets a plate or closed at a pole.
struct BulbShape {
    double radius = 0.3;   ///< largest radius, canonical units
    double exponent = 2;   ///< 2: sphere or ellipsoid; near 1: cone-like; 3..6: rounded cylinder
    double skew = 1;       ///< moves the widest part towards the neck (< 1) or the far end (> 1)
    double cut = 1;        ///< share of the shape kept from the neck; 1 closes the bulb at a pole
};

/// What an hourglass profile is made from.
struct HourglassRequest {
    double innerHeight = 0.8; ///< canonical units
    double neckRadius = 0.02; ///< canonical units
    bool closedEnds = false;  ///< the bulbs end in poles (or are open, to be covered)
    double neckTube = 0.01;   ///< length of the straight neck, canonical units
};

/// A random bulb shape whose length from the neck is `length`.
BulbShape randomBulb(Rng& rng, double length, bool closed);
/// The same shape changed a little, as the two bulbs of one glass differ.
BulbShape nearlyTheSame(Rng& rng, BulbShape shape);

/// The profile of an hourglass with random bulbs; sets the neck height.
std::vector<ProfileSample> hourglassProfile(Rng& rng, const HourglassRequest& request, double& neckHeight);

/// The largest radius of the profile at height h; negative outside [first, last] height.
double radiusAt(const std::vector<ProfileSample>& profile, double h);
/// Volume of revolution between heights h0 and h1.
double volumeBetween(const std::vector<ProfileSample>& profile, double h0, double h1);
/// The height above h0 below which the volume of revolution is `volume`.
double heightForVolume(const std::vector<ProfileSample>& profile, double h0, double volume);
/// Distance in the meridian plane from (h, d) to the solid of revolution; 0 inside.
double distanceToProfile(const std::vector<ProfileSample>& profile, double h, double d);
/// The samples between heights h0 and h1, with samples added at both.
std::vector<ProfileSample> profileBetween(const std::vector<ProfileSample>& profile, double h0, double h1);

} // namespace sandglass::wild
