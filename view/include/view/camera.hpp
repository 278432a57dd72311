// SPDX-License-Identifier: MIT
#pragma once
// The orbit camera of SPEC G3: it circles the scene centre (thesis §3.6: Alt + mouse, arrows,
// +/-; 1 perspective, 2 front, 3 top). Angles in radians, distances in world units.

#include "sandcore/vec3.hpp"

#include <glm/glm.hpp>

namespace sandglass {

/// The three fixed views of thesis §3.6.
enum class CameraView { Perspective, Front, Top };

class OrbitCamera {
public:
    /// Centres the camera on a box (world units) and backs off until all of it is in view.
    void frame(sandcore::Vec3 minCorner, sandcore::Vec3 maxCorner);
    /// Jumps to one of the three fixed views, keeping the framing distance.
    void setView(CameraView view);

    void rotate(float yawRadians, float pitchRadians); ///< orbit; pitch stays within +-89.5 degrees
    void pan(float rightFraction, float upFraction);    ///< move the centre by fractions of the view height
    void zoom(float factor);                           ///< distance *= factor (> 1 moves away)

    float yaw() const { return yaw_; }           ///< radians about +y; 0 looks along -z
    float pitch() const { return pitch_; }       ///< radians above the horizon
    float distance() const { return distance_; } ///< from the centre, world units
    glm::vec3 target() const { return target_; } ///< the point the camera looks at

    glm::vec3 position() const;                    ///< eye point in world units
    glm::vec3 right() const;                       ///< unit screen-right in world space
    glm::vec3 up() const;                          ///< unit screen-up in world space
    glm::mat4 view() const;                        ///< world to eye
    glm::mat4 projection(float aspect) const;      ///< eye to clip for width/height = aspect, lens shift included
    /// Moves the image right by `share` of the target's width (0..1) without turning the camera,
    /// so the scene centres in the part a panel on the left leaves free.
    void setLensShift(float share) { lensShift_ = share; }
    float lensShift() const { return lensShift_; } ///< share of the target's width
    float verticalFieldOfView() const { return fovY_; } ///< radians
    /// Turns the scene about the screen's horizontal axis through its centre by `radians` in
    /// the view (pi = upside down): the turning hourglass animation.
    void setTurn(float radians) { turn_ = radians; }
    float turn() const { return turn_; } ///< radians

private:
    glm::vec3 target_{0.0f};
    glm::vec3 home_{0.0f};
    float yaw_ = 0.6f, pitch_ = 0.35f, distance_ = 10.0f, homeDistance_ = 10.0f;
    float radius_ = 1.0f;
    float fovY_ = 0.6981f; // 40 degrees
    float lensShift_ = 0.0f;
    float turn_ = 0.0f;
};

} // namespace sandglass
