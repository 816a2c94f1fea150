#include "scene/scene_view.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <tuple>
#include <unordered_map>

#include "render/resources.hpp"
#include "render/shader_program.hpp"
#include "scene/diagnosis_overlay.hpp"

namespace pagor::studio {
namespace {

constexpr int kFloatsPerVertex = 4;  // x, y, z, packed RGBA

float pack(const Rgba& c) {
  float f;
  std::uint32_t u = static_cast<std::uint32_t>(c[0]) | (static_cast<std::uint32_t>(c[1]) << 8) |
                    (static_cast<std::uint32_t>(c[2]) << 16) |
                    (static_cast<std::uint32_t>(c[3]) << 24);
  static_assert(sizeof(f) == sizeof(u));
  std::memcpy(&f, &u, sizeof(f));
  return f;
}

void push(std::vector<float>& v, const Eigen::Vector3f& p, const Rgba& c) {
  v.insert(v.end(), {p.x(), p.y(), p.z(), pack(c)});
}

}  // namespace

Contribution shown_contribution(const ViewState& view) {
  return view.color == ColorMode::residual ? Contribution::candidate : view.diagnosis.contribution;
}

Eigen::Vector3f transform_point(const Transform& T, const Eigen::Vector3d& p) {
  return (T.block<3, 3>(0, 0) * p + T.block<3, 1>(0, 3)).cast<float>();
}

double ground_truth_residual(const Correspondence& c, const Transform& T_gt) {
  return (T_gt.block<3, 3>(0, 0) * c.p + T_gt.block<3, 1>(0, 3) - c.q).norm();
}

bool true_inlier(const Correspondence& c, const Transform& T_gt, double bound) {
  return ground_truth_residual(c, T_gt) <= bound;
}

bool SceneView::init(const Gl& gl, std::string& error) {
  gl_ = &gl;
  program_ = build_program(gl, "points.vert", "points.frag", error);
  if (!program_) return false;
  u_mvp_ = gl.GetUniformLocation(program_, "u_mvp");
  u_point_size_ = gl.GetUniformLocation(program_, "u_point_size");
  u_use_uniform_ = gl.GetUniformLocation(program_, "u_use_uniform_color");
  u_color_ = gl.GetUniformLocation(program_, "u_color");
  u_round_ = gl.GetUniformLocation(program_, "u_round");
  for (Buffer* b : {&source_, &target_, &landmarks_src_, &landmarks_tgt_, &keypoints_src_,
                    &keypoints_tgt_, &contribution_}) {
    gl.GenVertexArrays(1, &b->vao);
    gl.GenBuffers(1, &b->vbo);
    gl.BindVertexArray(b->vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, b->vbo);
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, kFloatsPerVertex * sizeof(float), nullptr);
    gl.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, kFloatsPerVertex * sizeof(float),
                           reinterpret_cast<void*>(3 * sizeof(float)));
  }
  for (Buffer* b : {&source_, &target_, &contribution_}) {  // thinned: strides set at draw
    gl.GenVertexArrays(1, &b->thin_vao);
    gl.BindVertexArray(b->thin_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, b->vbo);
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
  }
  gl.BindVertexArray(0);
  return true;
}

void SceneView::shutdown() {
  if (!gl_) return;
  for (Buffer* b : {&source_, &target_, &landmarks_src_, &landmarks_tgt_, &keypoints_src_,
                    &keypoints_tgt_, &contribution_}) {
    gl_->DeleteBuffers(1, &b->vbo);
    gl_->DeleteVertexArrays(1, &b->vao);
    if (b->thin_vao) gl_->DeleteVertexArrays(1, &b->thin_vao);
  }
  gl_->DeleteFramebuffers(1, &fbo_);
  gl_->DeleteTextures(1, &color_texture_);
  gl_->DeleteRenderbuffers(1, &depth_rb_);
  gl_->DeleteProgram(program_);
  gl_ = nullptr;
}

void SceneView::upload(Buffer& b, const std::vector<float>& v) {
  gl_->BindBuffer(GL_ARRAY_BUFFER, b.vbo);
  gl_->BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(),
                  GL_STATIC_DRAW);
  b.count = static_cast<GLsizei>(v.size() / kFloatsPerVertex);
  ++content_version_;
}

void SceneView::update_clouds(const Snapshot& s, const ViewState& view, const Transform& pose) {
  // by_cloud and residual draw uniform colours over the class colours (SceneView::render).
  const ColorMode mode = view.color == ColorMode::height || view.color == ColorMode::intensity
                             ? view.color
                             : ColorMode::by_class;
  // Each cloud in the scheme its labels were read with (`auto`: the one detected for it).
  const LabelScheme& source_scheme = cloud_scheme(s, true);
  const LabelScheme& target_scheme = cloud_scheme(s, false);
  const std::string key = std::to_string(s.data_generation) + "/" + source_scheme.name + "/" +
                          source_scheme.class_list() + "|" + target_scheme.name + "/" +
                          target_scheme.class_list() + "/" +
                          std::to_string(static_cast<int>(mode));
  std::string source_key = key;
  if (mode == ColorMode::height)  // the source's height in the target frame follows its pose
    for (int i = 0; i < 16; ++i) source_key += "," + std::to_string(pose(i / 4, i % 4));
  if (key == cloud_key_ && source_key == source_key_) return;
  const bool both = key != cloud_key_;
  if (both) {
    drawn_ = studio::drawn_classes(s, class_colors_);
    scale_ = mode == ColorMode::height      ? height_scale(s)
             : mode == ColorMode::intensity ? intensity_scale(s)
                                            : ColorScale{};
  }
  for (const auto& [cloud, buffer, T, read_as] :
       {std::tuple{s.source.get(), &source_, pose, &source_scheme},
        std::tuple{s.target.get(), &target_, Transform(Transform::Identity()), &target_scheme}}) {
    if (buffer == &target_ && !both) continue;
    std::vector<float> v;
    if (cloud) {
      const std::vector<Rgba> colors =
          cloud_colors(*cloud, mode, class_colors_, *read_as, T, scale_);
      v.reserve(cloud->size() * kFloatsPerVertex);
      for (std::size_t i = 0; i < cloud->size(); ++i) push(v, cloud->points[i], colors[i]);
    }
    upload(*buffer, v);
  }
  cloud_key_ = key;
  source_key_ = source_key;
  ++cloud_uploads_;
}

void SceneView::update(const Snapshot& s, const ViewState& view, const Transform& pose) {
  update_clouds(s, view, pose);
  update_contribution(s, view);
  // Landmarks: small; again when the snapshot, the level, the pose or the colouring change.
  const int level = shown_level(view, s.selected, static_cast<int>(s.levels.size()));
  std::string key = std::to_string(level) + (view.layers.all_correspondences ? "a" : "c") +
                    (view.layers.correspondences ? "l" : "n") +
                    (view.color == ColorMode::by_class ? "k" : "s") + "/" +
                    view.diagnosis.class_name + "/" +
                    std::to_string(static_cast<int>(view.diagnosis.truth)) + "/";
  for (int i = 0; i < 16; ++i) key += std::to_string(pose(i / 4, i % 4)) + ",";
  if (s.request == overlay_request_ && key == overlay_key_) return;
  overlay_request_ = s.request;
  overlay_key_ = key;

  std::vector<char> used_src(s.source_landmarks.landmarks.size(), 0),
      used_tgt(s.target_landmarks.landmarks.size(), 0);
  // A matcher's correspondences name keypoints of their own, not landmarks: their points p and q
  // are drawn as keypoints (source under the pose), whether or not clouds came with them. With the
  // clique's lines shown, its members stand out and the rest (often a thousand and more) are
  // faint (so are the members whose lines the diagnosis filters hide).
  std::vector<char> in_clique(s.correspondences.size(), 0);
  const bool dim_others = view.layers.correspondences && level >= 0;
  if (dim_others)
    for (int v : s.levels[static_cast<std::size_t>(level)].clique)
      if (v >= 0 && static_cast<std::size_t>(v) < in_clique.size() &&
          diagnosis_keeps(s, view.diagnosis, static_cast<std::size_t>(v)))
        in_clique[static_cast<std::size_t>(v)] = 1;
  const auto faint = [](Rgba c) { return Rgba{c[0], c[1], c[2], 60}; };
  std::vector<float> faint_src, faint_tgt, strong_src, strong_tgt;  // strong: drawn last
  for (std::size_t i = 0; i < s.correspondences.size(); ++i) {
    const Correspondence& c = s.correspondences[i];
    if (c.origin == CorrespondenceOrigin::matcher) {
      const bool strong = !dim_others || in_clique[i];
      push(strong ? strong_src : faint_src, transform_point(pose, c.p),
           strong ? Palette::source : faint(Palette::source));
      push(strong ? strong_tgt : faint_tgt, c.q.cast<float>(),
           strong ? Palette::target : faint(Palette::target));
      continue;
    }
    if (c.source >= 0 && static_cast<std::size_t>(c.source) < used_src.size())
      used_src[static_cast<std::size_t>(c.source)] = 1;
    if (c.target >= 0 && static_cast<std::size_t>(c.target) < used_tgt.size())
      used_tgt[static_cast<std::size_t>(c.target)] = 1;
  }
  const auto landmark_vertices = [&](const LandmarkSet& set, const std::vector<char>& used,
                                     bool source, LandmarkKind kind) {
    std::vector<float> v;
    for (std::size_t i = 0; i < set.landmarks.size(); ++i) {
      const Landmark& lm = set.landmarks[i];
      if (lm.kind != kind || (kind == LandmarkKind::keypoint && !used[i])) continue;
      const Rgba color =
          view.color == ColorMode::by_class
              ? class_colors_.of(set.classes[static_cast<std::size_t>(lm.class_index)].name)
              : (source ? Palette::source : Palette::target);
      push(v, source ? transform_point(pose, lm.centroid) : lm.centroid.cast<float>(), color);
    }
    return v;
  };
  upload(landmarks_src_,
         landmark_vertices(s.source_landmarks, used_src, true, LandmarkKind::cluster));
  upload(landmarks_tgt_,
         landmark_vertices(s.target_landmarks, used_tgt, false, LandmarkKind::cluster));
  std::vector<float> key_src = landmark_vertices(s.source_landmarks, used_src, true,
                                                 LandmarkKind::keypoint);
  std::vector<float> key_tgt = landmark_vertices(s.target_landmarks, used_tgt, false,
                                                 LandmarkKind::keypoint);
  faint_keypoints_ = faint_src.size() / kFloatsPerVertex;
  for (const std::vector<float>* m : {&faint_src, &strong_src})
    key_src.insert(key_src.end(), m->begin(), m->end());
  for (const std::vector<float>* m : {&faint_tgt, &strong_tgt})
    key_tgt.insert(key_tgt.end(), m->begin(), m->end());
  upload(keypoints_src_, key_src);
  upload(keypoints_tgt_, key_tgt);
}

void SceneView::update_contribution(const Snapshot& s, const ViewState& view) {
  const Contribution mode = shown_contribution(view);
  const int level = shown_level(view, s.selected, static_cast<int>(s.levels.size()));
  const std::string key = std::to_string(s.request) + "/" + std::to_string(static_cast<int>(mode)) +
                          "/" + std::to_string(level);
  if (key == contribution_key_) return;
  contribution_key_ = key;
  const std::vector<float>* part = nullptr;
  if (mode == Contribution::ground_truth && s.ground_truth) {
    part = &s.gt_contribution;
    contribution_pose_ = *s.ground_truth;
  } else if (mode == Contribution::candidate && level >= 0 &&
             static_cast<std::size_t>(level) < s.contributions.size()) {
    part = &s.contributions[static_cast<std::size_t>(level)];
    contribution_pose_ = s.levels[static_cast<std::size_t>(level)].pose.T_target_source;
  }
  std::vector<float> v;
  if (part && s.verification_source && part->size() == s.verification_source->size()) {
    const float mu = static_cast<float>(s.config.verification.mu);
    v.reserve(part->size() * kFloatsPerVertex);
    for (std::size_t i = 0; i < part->size(); ++i)
      push(v, (*s.verification_source)[i], diagnosis_colormap((*part)[i] / mu));
  }
  upload(contribution_, v);
}

float SceneView::ground_z(const Snapshot& s) {
  if (s.data_generation == ground_generation_ || !s.target || s.target->points.empty())
    return ground_z_;
  std::vector<float> z;
  const std::size_t stride = std::max<std::size_t>(1, s.target->points.size() / 20000);
  for (std::size_t i = 0; i < s.target->points.size(); i += stride)
    z.push_back(s.target->points[i].z());
  const auto k = static_cast<std::ptrdiff_t>(0.02 * static_cast<double>(z.size() - 1));
  std::nth_element(z.begin(), z.begin() + k, z.end());
  ground_z_ = z[static_cast<std::size_t>(k)];
  ground_generation_ = s.data_generation;
  return ground_z_;
}

void SceneView::resize(int width, int height) {
  if (width == fb_width_ && height == fb_height_ && fbo_) return;
  const Gl& gl = *gl_;
  if (!fbo_) {
    gl.GenFramebuffers(1, &fbo_);
    gl.GenTextures(1, &color_texture_);
    gl.GenRenderbuffers(1, &depth_rb_);
  }
  gl.BindTexture(GL_TEXTURE_2D, color_texture_);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_texture_, 0);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  fb_width_ = width;
  fb_height_ = height;
}

void SceneView::draw(const Buffer& b, GLenum mode, const Eigen::Matrix4f& mvp, float size,
                     bool round, const Rgba* uniform_color, int stride) {
  if (b.count == 0) return;
  const Gl& gl = *gl_;
  gl.UniformMatrix4fv(u_mvp_, 1, GL_FALSE, mvp.data());
  gl.Uniform1f(u_point_size_, size);
  gl.Uniform1i(u_round_, round ? 1 : 0);
  gl.Uniform1i(u_use_uniform_, uniform_color ? 1 : 0);
  if (uniform_color)
    gl.Uniform4f(u_color_, (*uniform_color)[0] / 255.0f, (*uniform_color)[1] / 255.0f,
                 (*uniform_color)[2] / 255.0f, (*uniform_color)[3] / 255.0f);
  if (stride <= 1 || !b.thin_vao) {
    gl.BindVertexArray(b.vao);
    gl.DrawArrays(mode, 0, b.count);
    return;
  }
  // Every stride-th vertex: the same buffer read with a longer step.
  const GLsizei step = static_cast<GLsizei>(stride * kFloatsPerVertex * sizeof(float));
  gl.BindVertexArray(b.thin_vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, b.vbo);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, step, nullptr);
  gl.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, step,
                         reinterpret_cast<void*>(3 * sizeof(float)));
  gl.DrawArrays(mode, 0, (b.count + stride - 1) / stride);
}

std::vector<double> SceneView::render_key(int width, int height, const Eigen::Matrix4f& vp,
                                          const ViewState& view, const Transform& pose,
                                          bool thin) const {
  std::vector<double> k = {double(width), double(height), double(view.color),
                           double(view.layers.target), double(view.layers.source),
                           double(view.layers.landmarks), view.point_size, view.landmark_size,
                           double(shown_contribution(view)), double(content_version_),
                           double(thin)};
  k.insert(k.end(), vp.data(), vp.data() + 16);
  k.insert(k.end(), pose.data(), pose.data() + 16);
  k.insert(k.end(), contribution_pose_.data(), contribution_pose_.data() + 16);
  return k;
}

void SceneView::render(int width, int height, const Camera& camera, const ViewState& view,
                       const Transform& pose) {
  if (width <= 0 || height <= 0) return;
  const Eigen::Matrix4f vp = camera.projection(static_cast<float>(width) / height) * camera.view();
  // The camera moved since the last picture: thinned clouds, whole again when it stops.
  const long long points = static_cast<long long>(source_.count) + target_.count;
  const bool moving = !last_key_.empty() && vp != last_vp_;
  const int stride =
      moving && points > kMovingPointBudget
          ? static_cast<int>((points + kMovingPointBudget - 1) / kMovingPointBudget)
          : 1;
  std::vector<double> key = render_key(width, height, vp, view, pose, stride > 1);
  last_vp_ = vp;
  if (key == last_key_ && fbo_) return;  // the texture holds this picture
  last_key_ = std::move(key);
  ++renders_;
  if (stride > 1) ++thinned_renders_;
  resize(width, height);
  // Moving: also half the resolution (a quarter of the pixels to clear and fill), in the
  // texture's bottom-left quarter, shown stretched (texture_share).
  share_ = stride > 1 ? 0.5f : 1.0f;
  draw_scene(vp, view, pose, stride);
}

void SceneView::draw_scene(const Eigen::Matrix4f& vp, const ViewState& view, const Transform& pose,
                           int stride) {
  const Gl& gl = *gl_;
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  const int w = std::max(1, static_cast<int>(std::lround(fb_width_ * share_))),
            h = std::max(1, static_cast<int>(std::lround(fb_height_ * share_)));
  share_xy_ = Eigen::Vector2f(float(w) / float(fb_width_), float(h) / float(fb_height_));
  gl.Viewport(0, 0, w, h);
  gl.Enable(GL_SCISSOR_TEST);  // the clear too: only the share drawn
  gl.Scissor(0, 0, w, h);
  const auto& bg = Palette::background;
  gl.ClearColor(bg[0] / 255.0f, bg[1] / 255.0f, bg[2] / 255.0f, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.Disable(GL_SCISSOR_TEST);
  // Point sizes in the texture's pixels: at half the resolution, half the size (shown the same).
  const auto px = [&](float size) { return std::max(1.0f, size * share_); };
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LEQUAL);
  gl.Enable(GL_PROGRAM_POINT_SIZE);
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.UseProgram(program_);

  const Eigen::Matrix4f source_mvp = vp * pose.cast<float>();
  const bool by_cloud = view.color == ColorMode::by_cloud;
  const bool residual = view.color == ColorMode::residual;
  if (view.layers.target)
    draw(target_, GL_POINTS, vp, px(view.point_size), false,
         by_cloud   ? &Palette::target
         : residual ? &Palette::plain
                    : nullptr,
         stride);
  if (view.layers.source && shown_contribution(view) != Contribution::off)
    draw(contribution_, GL_POINTS, vp * contribution_pose_.cast<float>(), px(view.point_size + 1.0f),
         false, nullptr, stride);
  else if (view.layers.source)
    draw(source_, GL_POINTS, source_mvp, px(view.point_size), false,
         by_cloud ? &Palette::source : nullptr, stride);
  // Landmarks on top of the clouds (lines are drawn over everything by the overlay).
  gl.DepthMask(GL_FALSE);
  gl.Disable(GL_DEPTH_TEST);
  if (view.layers.landmarks) {
    draw(keypoints_tgt_, GL_POINTS, vp, px(view.landmark_size * 0.5f), true, nullptr);
    draw(keypoints_src_, GL_POINTS, vp, px(view.landmark_size * 0.5f), true, nullptr);
    draw(landmarks_tgt_, GL_POINTS, vp, px(view.landmark_size), true, nullptr);
    draw(landmarks_src_, GL_POINTS, vp, px(view.landmark_size), true, nullptr);
  }
  gl.DepthMask(GL_TRUE);
  gl.BindVertexArray(0);
  gl.UseProgram(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace pagor::studio
