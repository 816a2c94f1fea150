#pragma once
/// \file refinement.hpp
/// Optional fine alignment of the selected pose on the metric clouds: point-to-plane ICP on the
/// verification's downsampled clouds, constrained to the pose model (SE(3), 4-DoF or SE(2)).
/// It is bounded (iterations, points, how far it may move the pose) and verified like every other
/// candidate: the refined pose is kept only when it lowers D; otherwise the selection stands and
/// the result says why.

#include <memory>
#include <string>
#include <vector>

#include "pagor/types.hpp"
#include "pagor/util/fields.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

/// Optional fine alignment of the selected pose on the metric clouds.
struct RefinementParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  bool enabled = true;
  int max_iterations = 20;
  int max_points = 1000;
  double max_distance = 1.0;
  double min_distance = 0.3;
  double robust_scale = 0.2;
  double normal_radius = 1.0;
  double max_translation = 2.0;
  double max_rotation = 5.0;
  bool free_roll_pitch = true;

  template <class V>
  static void fields(V&& v) {
    v(&RefinementParams::enabled,
      {"enabled", "Refine the selected pose by ICP (kept only when it lowers D)."});
    v(&RefinementParams::max_iterations,
      {"max_iterations", "ICP iterations, at most.", "", Range::closed(1, 1000)});
    v(&RefinementParams::max_points,
      {"max_points", "Source points used, spread evenly over the verification's cloud.", "",
       Range::closed(10, 1e6)});
    v(&RefinementParams::max_distance,
      {"max_distance",
       "Pairing distance of the first iteration; it shrinks to min_distance over the first half.",
       "m", Range::above(0, 1000)});
    v(&RefinementParams::min_distance,
      {"min_distance", "Pairing distance of the later iterations.", "m", Range::above(0, 1000)});
    v(&RefinementParams::robust_scale,
      {"robust_scale", "Cauchy scale of the point-to-plane residuals.", "m",
       Range::above(0, 1000)});
    v(&RefinementParams::normal_radius,
      {"normal_radius", "Neighbourhood of the target normals.", "m", Range::above(0, 100)});
    v(&RefinementParams::max_translation,
      {"max_translation", "A refinement that moves the pose farther is rejected.", "m",
       Range::above(0, 1e4)});
    v(&RefinementParams::max_rotation,
      {"max_rotation", "A refinement that turns the pose more is rejected.", "deg",
       Range::above(0, 180)});
    v(&RefinementParams::free_roll_pitch,
      {"free_roll_pitch",
       "Refine roll and pitch too when the pose model holds them level (4-DoF)."});
  }
  template <class C>
  static void check(const RefinementParams& p, C& c) {
    c.require(p.max_distance >= p.min_distance, "max_distance",
              "must be >= refinement.min_distance [m]");
  }
};

/// What the refinement did to the selected pose.
struct RefinementResult {
  bool ran = false;      ///< whether it ran (enabled and a pose was selected)
  bool applied = false;  ///< whether the refined pose replaced the selection (it lowered D)
  Transform T_before = Transform::Identity();  ///< the selected pose, T_target_source
  Transform T_after = Transform::Identity();   ///< the refined pose (T_before if not applied)
  double score_before = 0.0;                   ///< D of T_before [m]
  double score_after = 0.0;                    ///< D of the refined pose [m]
  double correction_translation = 0.0;         ///< how far refinement moved the pose [m]
  double correction_rotation = 0.0;            ///< how far it turned it [deg]
  int iterations = 0;                          ///< ICP iterations run
  int pairs = 0;                               ///< point-to-plane pairs in the last iteration
  /// When applied: per verification source point, its distance under the refined pose to the
  /// nearest target point [m], +infinity beyond mu (what score_after summed). Empty otherwise.
  std::vector<float> distances_after;
  std::string reason;  ///< why it was not applied; empty if applied
};

/// Refines poses against one verifier's clouds. The normal of a downsampled target point (from
/// its neighbours within `normal_radius`; none with fewer than 5 neighbours or no clear plane) is
/// estimated when ICP first pairs it and kept for later calls, so a refiner is not thread-safe.
class Refiner {
 public:
  /// `verifier` must outlive the refiner. Throws ConfigError naming refinement.normal_radius when
  /// the normals' radius searches would pass kMaxNeighbourVisits (work_budget.hpp).
  Refiner(const Verifier& verifier, double normal_radius);
  ~Refiner();
  Refiner(Refiner&&) noexcept;
  Refiner& operator=(Refiner&&) noexcept;

  /// Refines a candidate `T_target_source` whose D under `scoring` is `score` [m] (as verification
  /// found it), under `model`, and scores the refined pose the same way.
  RefinementResult refine(const Transform& T_target_source, double score, PoseModel model,
                          const RefinementParams& params, const VerificationParams& scoring,
                          int threads = 1);

  /// Target points whose normal has been estimated so far.
  std::size_t normals_estimated() const;
  /// The radius the normals were estimated with [m].
  double normal_radius() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pagor
