#pragma once
/// \file association_problem.hpp
/// Generated association problems, as CLIPPER's benchmarks pose them: random 3-D points, a
/// fraction of the correspondences inliers (the source point moved by a known transform with a
/// random rotation about any axis, plus bounded noise), the rest pairing two unrelated random
/// points. Every correspondence has its own source and target point, so no pair is excluded for
/// sharing a landmark. They stand for a matcher's correspondences (origin `matcher`): the
/// benchmark's dense problems and the tests of the correspondence input.

#include <cstdint>
#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// Parameters of one problem.
struct AssociationParams {
  int m = 1000;               ///< correspondences
  double inlier_ratio = 0.1;  ///< fraction of inliers, in [0, 1]
  double noise = 0.02;        ///< inlier noise: uniform in a ball of this radius [m]
  double extent = 10.0;       ///< points are uniform in a cube of this side [m]
  std::uint64_t seed = 1;     ///< random seed
};

/// A problem with its ground truth.
struct AssociationProblem {
  std::vector<Correspondence> correspondences;  ///< origin matcher, class_index -1, weight 1
  std::vector<char> inlier;                     ///< ground-truth flag per correspondence
  Transform T_target_source = Transform::Identity();
};

/// The problem `params` describe; the same parameters give the same problem.
AssociationProblem association_problem(const AssociationParams& params);

/// The graph parameters of the problem set: difference TRIM ("point distance"), epsilon =
/// 0.03/0.06/0.12/0.24 m, Gaussian affinity with sigma = epsilon / 2, no minimum length.
GraphParams association_graph_params();

/// Writes a problem as a correspondences file (`px py pz qx qy qz weight inlier` per line, as
/// `pagor register --correspondences` reads). Returns false when the file cannot be written.
bool write_association_problem(const std::string& path, const AssociationProblem& problem,
                               const std::string& comment);

}  // namespace pagor
