#pragma once
/// \file verification.hpp
/// "Distrust and verify": every candidate pose is scored on the dense metric clouds by
///   D = sum_p min(|T p - q_nn|, mu)   (truncated, default),
/// or the ablation variants `trimmed` (sum of d over d < mu) and `nearest` (sum of d). The source
/// and target are voxel-downsampled first; the target's nearest neighbours come from a kd-tree.
/// The lowest D wins.

#include <limits>
#include <memory>
#include <vector>

#include "pagor/params.hpp"
#include "pagor/pose/gnc.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// The downsampled clouds, built once; scores any number of poses. Searches bounded by mu run on
/// a hashed grid of the target (cells of the bound), unbounded ones on a kd-tree; each is built
/// on first use. Safe to use from several threads at once.
class Verifier {
 public:
  /// Downsamples both clouds on a `voxel_size` grid [m] (0 keeps every point); `threads` > 1
  /// downsamples the two at once.
  Verifier(const PointCloud& source, const PointCloud& target, double voxel_size, int threads = 1);
  ~Verifier();
  Verifier(Verifier&&) noexcept;
  Verifier& operator=(Verifier&&) noexcept;

  /// Score D of a pose, in metres summed over the downsampled source points; `threads` > 1 splits
  /// the points over threads (same result). When `distances` is given it receives what the score
  /// summed: per source point the distance to its nearest target point [m], +infinity where none
  /// is closer than mu (any distance for ScoreKind::nearest).
  double score(const Transform& T_target_source, double mu, ScoreKind kind, int threads = 1,
               std::vector<float>* distances = nullptr) const;

  /// Distance from each downsampled source point, moved by T, to its nearest target point [m];
  /// +infinity where none is closer than `bound` [m] (a smaller bound searches faster).
  std::vector<float> distances(const Transform& T_target_source,
                               float bound = std::numeric_limits<float>::infinity()) const;
  /// The same for the points i with only[i] != 0 (one flag per downsampled source point); the
  /// others are not searched and stay +infinity. What a caller that ignores some points (the
  /// ground, in acceptance) asks for.
  std::vector<float> distances(const Transform& T_target_source, float bound,
                               const std::vector<char>& only) const;

  /// How many of the points i with only[i] != 0, moved by T, have a target point strictly closer
  /// than `radius` [m]: what a count of aligned points needs, without the nearest one (a search
  /// stops at the first point it finds). `threads` > 1 splits the points (same count).
  std::size_t count_within(const Transform& T_target_source, float radius,
                           const std::vector<char>& only, int threads = 1) const;

  /// Nearest downsampled target point to `q` strictly closer than sqrt(`max_distance_sq`) [m^2]:
  /// its index in target_points() and squared distance; index -1 when there is none.
  std::pair<int, float> nearest_target(const Eigen::Vector3f& q, float max_distance_sq) const;

  const std::vector<Eigen::Vector3f>& source_points() const;
  const std::vector<Eigen::Vector3f>& target_points() const;
  double build_time_ms() const;
  /// Per source point (of source_points()): the semantic id (semantic_id) all the cloud's points
  /// in its voxel share, 0 where they differ; empty when the source cloud has no labels.
  const std::vector<std::uint32_t>& source_labels() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Scores of all candidates and the winner.
struct VerificationResult {
  std::vector<double> scores;  ///< D per candidate [m]; +infinity for an invalid candidate
  int selected = -1;           ///< index of the lowest D; -1 when no candidate is valid
  bool tie = false;            ///< whether another candidate had the same D (broken by inliers)
  double time_ms = 0.0;        ///< wall time of the scoring [ms]
  /// Per source point of the verifier, its distance under the selected pose to the nearest target
  /// point [m], +infinity beyond `distance_bound` (what the selection's D summed; acceptance
  /// reuses it instead of searching again). Empty when nothing was selected.
  std::vector<float> selected_distances;
  float distance_bound = 0.0f;  ///< [m]: mu, or +infinity for ScoreKind::nearest
  /// Selection without clouds (level_selection.hpp), per candidate: the correspondences its pose
  /// explains within the bound, and its score S on them [m] (+infinity when invalid). Empty when
  /// the candidates were verified on clouds.
  std::vector<int> support;
  std::vector<double> support_scores;
};

/// Scores every valid candidate and selects the lowest D. Ties (equal D to 1e-9 relative) go to
/// the candidate with more inliers, then to the lower index.
VerificationResult verify_candidates(const Verifier& verifier,
                                     const std::vector<PoseEstimate>& candidates,
                                     const VerificationParams& params, int threads = 1);

}  // namespace pagor
