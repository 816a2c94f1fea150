#include "state/camera.hpp"

#include <algorithm>
#include <cmath>

namespace pagor::studio {
namespace {
constexpr float kDegToRad = 3.14159265358979f / 180.0f;
}

Eigen::Vector3f Camera::eye() const {
  const float pitch = (top_down ? 89.9f : pitch_deg) * kDegToRad, yaw = yaw_deg * kDegToRad;
  return target + distance * Eigen::Vector3f(std::cos(pitch) * std::cos(yaw),
                                             std::cos(pitch) * std::sin(yaw), std::sin(pitch));
}

Eigen::Matrix4f Camera::view() const {
  const Eigen::Vector3f e = eye();
  const Eigen::Vector3f f = (target - e).normalized();
  // Up: +Z, except straight down where the yaw direction points up on screen.
  const float yaw = yaw_deg * kDegToRad;
  const Eigen::Vector3f up_hint =
      top_down ? Eigen::Vector3f(-std::cos(yaw), -std::sin(yaw), 0.0f) : Eigen::Vector3f::UnitZ();
  const Eigen::Vector3f s = f.cross(up_hint).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f V = Eigen::Matrix4f::Identity();
  V.block<1, 3>(0, 0) = s.transpose();
  V.block<1, 3>(1, 0) = u.transpose();
  V.block<1, 3>(2, 0) = -f.transpose();
  V(0, 3) = -s.dot(e);
  V(1, 3) = -u.dot(e);
  V(2, 3) = f.dot(e);
  return V;
}

Eigen::Matrix4f Camera::projection(float aspect) const {
  const float near_plane = std::max(0.05f, distance * 0.002f),
              far_plane = distance * 20.0f + 500.0f;
  Eigen::Matrix4f P = Eigen::Matrix4f::Zero();
  if (top_down) {
    const float h = distance * std::tan(fov_deg * 0.5f * kDegToRad), w = h * aspect;
    P(0, 0) = 1.0f / w;
    P(1, 1) = 1.0f / h;
    P(2, 2) = -2.0f / (far_plane - near_plane);
    P(2, 3) = -(far_plane + near_plane) / (far_plane - near_plane);
    P(3, 3) = 1.0f;
  } else {
    const float t = 1.0f / std::tan(fov_deg * 0.5f * kDegToRad);
    P(0, 0) = t / aspect;
    P(1, 1) = t;
    P(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
    P(2, 3) = 2.0f * far_plane * near_plane / (near_plane - far_plane);
    P(3, 2) = -1.0f;
  }
  return P;
}

void Camera::orbit(float dx, float dy) {
  yaw_deg -= dx * 0.3f;
  if (!top_down) pitch_deg = std::clamp(pitch_deg + dy * 0.3f, -89.0f, 89.0f);
}

void Camera::pan(float dx, float dy, float height) {
  const Eigen::Matrix4f V = view();
  const Eigen::Vector3f right = V.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3f up = V.block<1, 3>(1, 0).transpose();
  const float metres_per_pixel =
      2.0f * distance * std::tan(fov_deg * 0.5f * kDegToRad) / std::max(height, 1.0f);
  target += (-dx * right + dy * up) * metres_per_pixel;
}

void Camera::zoom(float steps) {
  distance = std::clamp(distance * std::pow(0.88f, steps), 0.5f, 5000.0f);
}

void Camera::fit(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi, float aspect) {
  target = 0.5f * (lo + hi);
  aspect = std::isfinite(aspect) && aspect > 0 ? aspect : 1.0f;
  const float tan_half = std::tan(fov_deg * 0.5f * kDegToRad);
  // The box's corners on the screen's axes (right, up) and towards the camera (back); the view's
  // directions do not depend on the distance. Straight down (orthographic) the half height shown
  // is distance * tan_half; in perspective a corner at `back` towards the camera is seen within
  // the frame from distance back + |right| / (tan_half * aspect) and back + |up| / tan_half.
  const Eigen::Matrix4f V = view();
  const Eigen::Vector3f right = V.block<1, 3>(0, 0).transpose(),
                        up = V.block<1, 3>(1, 0).transpose(),
                        back = V.block<1, 3>(2, 0).transpose();
  float needed = 0.5f / tan_half;  // at least a metre across
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3f c = Eigen::Vector3f((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                              (k & 4) ? hi.z() : lo.z()) -
                              target;
    const float x = std::abs(c.dot(right)) / (tan_half * aspect), y = std::abs(c.dot(up)) / tan_half;
    needed = std::max(needed, (top_down ? 0.0f : c.dot(back)) + std::max(x, y));
    // Top-down, the eye is above the highest corner too (the near plane is in front of it).
    if (top_down) needed = std::max(needed, c.dot(back) + 1.0f);
  }
  // A margin of 6 %, 12 % top-down (a plan's outline would otherwise touch the view's edges).
  distance = std::clamp(needed * (top_down ? 1.12f : 1.06f), 0.5f, 5000.0f);
}

bool project_to_screen(const Eigen::Matrix4f& vp, const Eigen::Vector3f& p, float width,
                       float height, Eigen::Vector2f& pixel) {
  const Eigen::Vector4f c = vp * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
  if (c.w() <= 1e-6f) return false;
  pixel = Eigen::Vector2f((c.x() / c.w() * 0.5f + 0.5f) * width,
                          (0.5f - c.y() / c.w() * 0.5f) * height);
  return true;
}

}  // namespace pagor::studio
