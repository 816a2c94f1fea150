#pragma once
/// \file camera.hpp
/// Orbit camera of the 3D view: orbit, pan, zoom, fit to data, and a top-down orthographic mode
/// (planar robots live there). Z is up.

#include <Eigen/Core>

namespace pagor::studio {

/// The yaw at which a top-down view shows x to the right and y up, as a floor plan is drawn [deg].
constexpr float kPlanYawDeg = -90.0f;

struct Camera {
  Eigen::Vector3f target = Eigen::Vector3f::Zero();  ///< orbit centre [m]
  float distance = 80.0f;                            ///< from the target [m]
  float yaw_deg = -60.0f;                            ///< around Z
  float pitch_deg = 45.0f;                           ///< above the horizon
  float fov_deg = 45.0f;                             ///< vertical field of view
  bool top_down = false;                             ///< orthographic, looking straight down

  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection(float aspect) const;
  Eigen::Vector3f eye() const;

  /// Mouse drag by (dx, dy) pixels: orbit (in top-down: yaw only).
  void orbit(float dx, float dy);
  /// Mouse drag by (dx, dy) pixels on a viewport `height` pixels high: move the target.
  void pan(float dx, float dy, float height);
  /// Wheel steps: positive zooms in.
  void zoom(float steps);
  /// Centres on the box [lo, hi] and sets the distance to see all of it in a viewport of this
  /// width / height: each of its corners within the frame at the camera's direction (perspective
  /// and top-down), with a margin (6 %, top-down 12 %), so that the whole box is framed however long, tall or
  /// turned.
  void fit(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi, float aspect = 1.0f);
};

/// Projects a world point with a view-projection matrix to pixel coordinates (origin top-left) in
/// a viewport of `width` x `height`; false when behind the camera.
bool project_to_screen(const Eigen::Matrix4f& view_projection, const Eigen::Vector3f& p,
                       float width, float height, Eigen::Vector2f& pixel);

}  // namespace pagor::studio
