#pragma once
/// \file scene_view.hpp
/// The 3D view: dense clouds and landmarks drawn into an offscreen
/// framebuffer that the UI shows as an image. Cloud data stays on the GPU between frames and is
/// uploaded again only when the data (or the colouring) changes. Lines, grid and legend are drawn
/// over it by scene_overlay.hpp.

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "render/gl.hpp"
#include "runners/worker.hpp"
#include "scene/cloud_colors.hpp"
#include "state/app_state.hpp"

namespace pagor::studio {

/// Colours of the overlay elements, shared by the renderer and the legend.
struct Palette {
  static constexpr Rgba source{60, 180, 255, 255};
  static constexpr Rgba target{255, 150, 40, 255};
  static constexpr Rgba clique{60, 230, 90, 255};
  static constexpr Rgba clique_outlier{255, 60, 60, 255};
  static constexpr Rgba other{200, 200, 200, 70};
  static constexpr Rgba background{22, 24, 28, 255};
  static constexpr Rgba plain{110, 110, 115, 255};  ///< the target under residual colouring
  /// The XYZ axes at the target sensor: light grey and lettered, unlike any line colour.
  static constexpr Rgba axis{225, 225, 235, 230};
};

/// What the source's verification points are coloured by: the view's diagnosis choice, or the
/// shown level's candidate when the clouds are coloured by residual.
Contribution shown_contribution(const ViewState& view);

/// Whether a correspondence agrees with the ground truth: its residual under T_gt is within
/// `bound` [m] (the studio uses the success criterion's translation tolerance, as KITTI's ground
/// truth itself is only good to about a metre).
bool true_inlier(const Correspondence& c, const Transform& T_gt, double bound);
/// |T_gt p - q| of a correspondence [m].
double ground_truth_residual(const Correspondence& c, const Transform& T_gt);
/// A source point moved by T, as the GPU buffers store it.
Eigen::Vector3f transform_point(const Transform& T, const Eigen::Vector3d& p);

class SceneView {
 public:
  bool init(const Gl& gl, std::string& error);
  void shutdown();

  /// Brings GPU buffers up to date with a snapshot and the view state; cheap when nothing changed.
  void update(const Snapshot& snapshot, const ViewState& view, const Transform& source_pose);
  /// Draws into the offscreen framebuffer of width x height pixels. Nothing is drawn when nothing
  /// it draws changed since the last call (the texture holds it); while the camera moves, the
  /// dense clouds are drawn thinned to about kMovingPointBudget points, and whole again at the
  /// first frame it stands still (a still picture is always the whole clouds).
  void render(int width, int height, const Camera& camera, const ViewState& view,
              const Transform& source_pose);
  /// The share of the texture's width and height the last render filled, from its bottom-left
  /// corner: 1, or about 0.5 while the camera moves (shown stretched over the view).
  Eigen::Vector2f texture_share() const { return share_xy_; }
  /// The colour texture of the last render (for ImGui::Image).
  GLuint texture() const { return color_texture_; }
  /// Cloud uploads so far (a test of "no re-upload per frame").
  int cloud_uploads() const { return cloud_uploads_; }
  /// A matcher's source points drawn faint at the last update: those outside the shown clique
  /// while its lines are shown (0 otherwise).
  std::size_t faint_keypoints() const { return faint_keypoints_; }
  /// Renders that drew (not served from the last picture), and those drawn thinned.
  int renders() const { return renders_; }
  int thinned_renders() const { return thinned_renders_; }
  /// Dense points drawn per frame while the camera moves (about; both clouds).
  static constexpr int kMovingPointBudget = 60000;
  const ClassColors& class_colors() const { return class_colors_; }
  /// The classes the class colouring draws (for the legend; from the clouds' labels).
  const std::vector<DrawnClass>& drawn_classes() const { return drawn_; }
  /// The scale of the height or intensity colouring drawn (for the legend).
  const ColorScale& color_scale() const { return scale_; }
  /// Height of the ground under the target: its 2 % height quantile [m] (cached per data).
  float ground_z(const Snapshot& snapshot);

 private:
  struct Buffer {
    GLuint vao = 0, vbo = 0;
    GLsizei count = 0;
    GLuint thin_vao = 0;  ///< the same points, every `stride`-th (the clouds only)
  };
  void upload(Buffer& b, const std::vector<float>& interleaved);
  void draw(const Buffer& b, GLenum mode, const Eigen::Matrix4f& mvp, float size, bool round,
            const Rgba* uniform_color, int stride = 1);
  /// Everything a render depends on; equal keys draw equal pictures.
  std::vector<double> render_key(int width, int height, const Eigen::Matrix4f& vp,
                                 const ViewState& view, const Transform& pose, bool thin) const;
  void draw_scene(const Eigen::Matrix4f& vp, const ViewState& view, const Transform& pose,
                  int stride);
  void resize(int width, int height);
  /// The verification points coloured by their contribution to D (ViewState::diagnosis).
  void update_contribution(const Snapshot& s, const ViewState& view);
  /// The dense clouds and their colours, when the data, the scheme, the mode or (height) the
  /// source's pose changed.
  void update_clouds(const Snapshot& s, const ViewState& view, const Transform& source_pose);

  const Gl* gl_ = nullptr;
  ClassColors class_colors_;
  GLuint program_ = 0, fbo_ = 0, color_texture_ = 0, depth_rb_ = 0;
  GLint u_mvp_ = -1, u_point_size_ = -1, u_use_uniform_ = -1, u_color_ = -1, u_round_ = -1;
  int fb_width_ = 0, fb_height_ = 0;
  float share_ = 1.0f;  ///< the resolution of the last render, of the view's
  Eigen::Vector2f share_xy_ = Eigen::Vector2f::Ones();  ///< the texture it filled (texture_share)
  Buffer source_, target_, landmarks_src_, landmarks_tgt_, keypoints_src_, keypoints_tgt_;
  Buffer contribution_;  ///< drawn instead of the source when not empty
  Transform contribution_pose_ = Transform::Identity();  ///< the pose the contribution is under
  std::string contribution_key_;
  std::uint64_t ground_generation_ = 0;
  float ground_z_ = 0.0f;
  std::string cloud_key_, source_key_;  // what the clouds' colours were made for
  std::vector<DrawnClass> drawn_;
  ColorScale scale_;
  std::uint64_t overlay_request_ = 0;
  std::string overlay_key_;
  int cloud_uploads_ = 0;
  std::size_t faint_keypoints_ = 0;
  std::uint64_t content_version_ = 0;  // counts uploads: a render key part
  std::vector<double> last_key_;
  Eigen::Matrix4f last_vp_ = Eigen::Matrix4f::Zero();
  int renders_ = 0, thinned_renders_ = 0;
};

}  // namespace pagor::studio
