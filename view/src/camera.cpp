// SPDX-License-Identifier: MIT
#include "view/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sandglass {

namespace {
constexpr float kMaxPitch = 1.5621f; // 89.5 degrees: never straight down, so "up" stays defined
}

void OrbitCamera::frame(sandcore::Vec3 minCorner, sandcore::Vec3 maxCorner) {
    const glm::vec3 lo{minCorner.x, minCorner.y, minCorner.z}, hi{maxCorner.x, maxCorner.y, maxCorner.z};
    home_ = 0.5f * (lo + hi);
    radius_ = std::max(0.5f * glm::length(hi - lo), 1e-3f);
    // The whole bounding sphere fits the vertical field of view, so no corner of a box is cut off.
    homeDistance_ = radius_ / std::sin(0.5f * fovY_);
    setView(CameraView::Perspective);
}

void OrbitCamera::setView(CameraView view) {
    target_ = home_;
    distance_ = homeDistance_;
    switch (view) {
    case CameraView::Perspective: yaw_ = 0.6f; pitch_ = 0.35f; break;
    case CameraView::Front: yaw_ = 0.0f; pitch_ = 0.0f; break;
    case CameraView::Top: yaw_ = 0.0f; pitch_ = kMaxPitch; break;
    }
}

void OrbitCamera::rotate(float yawRadians, float pitchRadians) {
    yaw_ = std::remainder(yaw_ + yawRadians, 2.0f * 3.14159265f);
    pitch_ = std::clamp(pitch_ + pitchRadians, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float rightFraction, float upFraction) {
    const float viewHeight = 2.0f * distance_ * std::tan(0.5f * fovY_);
    target_ += (rightFraction * right() + upFraction * up()) * viewHeight;
}

void OrbitCamera::zoom(float factor) {
    if (!(factor > 0.0f)) return;
    distance_ = std::clamp(distance_ * factor, 0.05f * radius_, 20.0f * radius_);
}

glm::vec3 OrbitCamera::position() const {
    const glm::vec3 back{std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), std::cos(yaw_) * std::cos(pitch_)};
    return target_ + distance_ * back;
}

glm::vec3 OrbitCamera::right() const { return {std::cos(yaw_), 0.0f, -std::sin(yaw_)}; }

glm::vec3 OrbitCamera::up() const { return glm::normalize(glm::cross(right(), target_ - position())); }

glm::mat4 OrbitCamera::view() const {
    const glm::mat4 look = glm::lookAt(position(), target_, up());
    if (turn_ == 0.0f) return look;
    // The scene turns about the screen-right axis through its centre, as a hand turns an hourglass.
    return look * glm::translate(glm::mat4(1.0f), home_) * glm::rotate(glm::mat4(1.0f), turn_, right()) *
           glm::translate(glm::mat4(1.0f), -home_);
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    const float nearPlane = std::max(distance_ - 2.0f * radius_, 0.01f * radius_);
    const float farPlane = distance_ + 2.0f * radius_;
    glm::mat4 projection = glm::perspective(fovY_, std::max(aspect, 1e-3f), nearPlane, farPlane);
    // A shift of the whole image in normalised device coordinates (2 = the target's width):
    // x_ndc += share, the same for every depth, so nothing turns or scales.
    projection[2][0] -= lensShift_; // clip x += share * w, and w = -z_eye for a perspective projection
    return projection;
}

} // namespace sandglass
