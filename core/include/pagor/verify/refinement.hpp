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

#include "pagor/params.hpp"
#include "pagor/types.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

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
