// SPDX-License-Identifier: MIT
#pragma once
// Models "from the wild": hourglasses, funnels, characters and keyboards made the way users
// download them (several objects, open rims with gaps, thick or single walls, damaged faces,
// any up axis, any unit), generated from a seed with their ground truth, so tests can check
// what the loader and voxelizer make of them against what the model really holds.
//
// Every model is built in a canonical frame (y up, the glass's axis on x = z = 0, total height
// about 1) and then turned so that canonical +y points along its up axis, scaled by unitScale
// and moved by offset: model = rotation * canonical * unitScale + offset.

#include "sandcore/triangle_mesh.hpp"
#include "sandcore/vec3.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sandglass::wild {

/// The kinds of model in the corpus.
enum class ModelClass { ThickFramed, SingleWall, OpenBulbsPlates, OneObjectAsset, ConesRingsPost, Funnel, Character, Keyboard };

/// Every class, in the order of the enum.
inline constexpr std::array<ModelClass, 8> kAllClasses{ModelClass::ThickFramed,     ModelClass::SingleWall, ModelClass::OpenBulbsPlates,
                                                       ModelClass::OneObjectAsset,  ModelClass::ConesRingsPost, ModelClass::Funnel,
                                                       ModelClass::Character,       ModelClass::Keyboard};

/// "thick-framed", "single-wall", "open-bulbs-plates", "one-object-asset", "cones-rings-post",
/// "funnel", "character" or "keyboard".
const char* className(ModelClass modelClass);

/// A point or direction in double precision (canonical or model units).
using Point = std::array<double, 3>;

/// One point of the inner space's radius profile, canonical units.
struct ProfileSample {
    double height = 0; ///< along the axis from the bottom of the inner space
    double radius = 0; ///< inner radius there; two samples at one height make a step
};

/// A solid ellipsoid, canonical units.
struct Ellipsoid {
    Point centre{}; ///< canonical units
    Point radii{};  ///< half-axes along x, y, z, canonical units
};

/// A solid capsule (a cylinder with optional hemispherical ends), canonical units.
struct Capsule {
    Point a{};          ///< one end of the axis segment
    Point b{};          ///< the other end
    double radius = 0;  ///< canonical units
    bool roundA = true; ///< a hemisphere closes the end at a; otherwise the end is flat (and open in the mesh)
    bool roundB = true; ///< as roundA, for b
};

/// A solid axis-aligned box, canonical units.
struct Box {
    Point min{}; ///< canonical units
    Point max{}; ///< canonical units
};

/// What the model really holds, canonical units: a radius profile about the y axis (glasses,
/// funnels) or a union of solids (characters, keyboards).
struct GroundTruth {
    double bottom = 0;                  ///< canonical y of profile height 0
    std::vector<ProfileSample> profile; ///< bottom to top, heights non-decreasing; empty without one
    double neckHeight = -1;             ///< profile height of the neck; negative: no neck between two bulbs
    /// A glass open at its bottom (top) end over a plate with a gap: the gap, canonical units. The
    /// column under (over) the opening down (up) to the plate is enclosed by glass and plate, so
    /// sand there is inside; sand beside it, under the glass's rim, is not.
    double openBelow = 0, openAbove = 0;
    std::vector<Ellipsoid> ellipsoids;  ///< solids whose union is the inside (characters)
    std::vector<Capsule> capsules;      ///< as ellipsoids
    std::vector<Box> boxes;             ///< as ellipsoids (keyboard keys)
    double sandFraction = 0;            ///< modelled sand's share of the upper bulb's volume; 0: none
};

/// Damage done to the meshes, as a downloaded file has it.
struct Damage {
    std::int64_t flippedFaces = 0;    ///< faces whose index order was reversed
    std::int64_t duplicatedFaces = 0; ///< faces written twice (half with the same winding, half reversed)
    std::int64_t removedFaces = 0;    ///< faces cut away to leave holes
    bool unwelded = false;            ///< some object gives every triangle its own three vertices
};

/// One object ("o NAME") of the file.
struct Object {
    std::string name;           ///< as written after "o"
    sandcore::TriangleMesh mesh; ///< model coordinates
};

/// Where a model point lies relative to the canonical axis, model units.
struct AxisPosition {
    double height = 0;   ///< along the up direction from axisBottom()
    double distance = 0; ///< from the axis
};

/// A generated model with its ground truth.
struct WildModel {
    ModelClass modelClass = ModelClass::ThickFramed; ///< what kind of model
    std::uint64_t seed = 0;                          ///< the seed it was generated from
    std::vector<Object> objects;                     ///< model coordinates; no vertex shared between objects
    int upAxis = 2;          ///< model direction of the true up: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z (sandcore::UpAxis order)
    double unitScale = 1;    ///< model units per canonical unit
    double height = 1;       ///< canonical height of the whole model, canonical units
    std::array<std::array<int, 3>, 3> rotation{}; ///< canonical to model turn, rows of -1/0/1, determinant +1
    Point offset{};          ///< added after turning and scaling, model units
    GroundTruth truth;       ///< canonical units
    Damage damage;           ///< what was done to the meshes

    /// p lies in the inner space (sand space; the body for characters, a key for keyboards) or
    /// within `tolerance` model units of it. For ellipsoids the tolerance band may reach up to
    /// (largest / smallest radius) times further out.
    bool insideGlass(sandcore::Vec3 p, double tolerance) const;
    /// Inside the glass and above the neck; for a model without a neck, inside at all.
    bool inUpperBulb(sandcore::Vec3 p) const;
    /// Inside the glass and below the neck; false for a model without a neck.
    bool inLowerBulb(sandcore::Vec3 p) const;
    /// Volume of revolution of the profile above the neck (the whole profile without a neck),
    /// model units cubed; 0 without a profile.
    double upperBulbVolume() const;
    /// Inner radius at the neck (the outlet of a funnel), model units; 0 without a profile.
    double neckRadius() const;
    /// The model holds closed shells of sand inside its glass.
    bool hasModelledSand() const { return truth.sandFraction > 0; }

    /// The model point on the axis at the bottom of the inner space (profile height 0).
    Point axisBottom() const;
    /// Unit vector of the true up, model coordinates.
    Point upDirection() const;
    /// Height along the axis and distance from it of a model point, model units.
    AxisPosition axisPositionOf(Point p) const;
    /// The model point at `height` along the axis and `distance` from it, at `angle` radians about it.
    Point modelPointAt(double height, double distance, double angle) const;
    /// Length of the inner space along the axis, model units; 0 without a profile.
    double innerHeight() const;
    /// Profile height of the neck, model units; negative without a neck.
    double neckHeight() const;
    /// Inner radius at `height` along the axis, model units; negative outside the profile.
    double innerRadiusAt(double height) const;
    /// Canonical coordinates of a model point.
    Point canonicalOf(Point p) const;
    /// Model coordinates of a canonical point.
    Point modelOf(Point canonical) const;
    /// Smallest extent of any object's bounds along any axis, model units.
    double smallestPartExtent() const;
    /// Largest extent of the whole model's bounds, model units (the voxelizer's resolution runs along it).
    double largestExtent() const;
    /// Triangles over all objects.
    std::size_t triangleCount() const;
};

/// The model of `modelClass` for `seed`: the same seed gives the same model, bit for bit, on
/// any standard library (cos and sin aside).
WildModel generate(ModelClass modelClass, std::uint64_t seed);

/// The same surface with every triangle split into four, `times` times over (edge midpoints
/// shared between neighbours, so a closed mesh stays closed).
sandcore::TriangleMesh subdivided(const sandcore::TriangleMesh& mesh, int times);

/// Writes an OBJ file: one "o NAME" per object, then its v and f lines. Throws std::runtime_error
/// when the file cannot be written.
void writeObj(const WildModel& model, const std::filesystem::path& path);
/// Writes a binary STL of all objects merged (STL has no objects). Throws std::runtime_error
/// when the file cannot be written.
void writeStl(const WildModel& model, const std::filesystem::path& path);

} // namespace sandglass::wild
