#include "pagor/eval/association_problem.hpp"

#include "util/random_draw.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace pagor {

AssociationProblem association_problem(const AssociationParams& a) {
  std::mt19937_64 rng(a.seed);
  std::uniform_real_distribution<double> coord(0.0, a.extent), unit(-1.0, 1.0), angle(-M_PI, M_PI);
  AssociationProblem out;
  const Eigen::Vector3d axis = draw3(unit, rng).normalized();
  out.T_target_source.block<3, 3>(0, 0) = Eigen::AngleAxisd(angle(rng), axis).toRotationMatrix();
  out.T_target_source.block<3, 1>(0, 3) = draw3(unit, rng) * a.extent;
  const auto R = out.T_target_source.block<3, 3>(0, 0);
  const auto t = out.T_target_source.block<3, 1>(0, 3);
  const int inliers = static_cast<int>(std::lround(a.inlier_ratio * a.m));
  std::vector<char> flags(static_cast<std::size_t>(a.m), 0);
  std::fill(flags.begin(), flags.begin() + inliers, 1);
  std::shuffle(flags.begin(), flags.end(), rng);
  for (int i = 0; i < a.m; ++i) {
    Correspondence c;
    c.class_index = -1;
    c.origin = CorrespondenceOrigin::matcher;
    c.source = c.target = i;
    c.p = draw3(coord, rng);
    if (flags[static_cast<std::size_t>(i)]) {
      Eigen::Vector3d n;
      do n = draw3(unit, rng);
      while (n.squaredNorm() > 1.0);  // uniform in the unit ball
      c.q = R * c.p + t + a.noise * n;
    } else {
      c.q = R * draw3(coord, rng) + t;
    }
    c.score = 1.0;
    out.correspondences.push_back(c);
  }
  out.inlier = std::move(flags);
  return out;
}

GraphParams association_graph_params() {
  GraphParams g;
  g.trim = TrimKind::difference;
  g.thresholds = {0.03, 0.06, 0.12, 0.24};
  g.affinity = AffinityKind::gaussian;
  g.sigma_ratio = 0.5;
  g.min_length = 0.0;
  return g;
}

bool write_association_problem(const std::string& path, const AssociationProblem& p,
                               const std::string& comment) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return false;
  std::fprintf(f, "# %s\n# ground truth T_target_source, rows 1-3 of 4:", comment.c_str());
  for (int r = 0; r < 3; ++r)
    std::fprintf(f, "  %.9g %.9g %.9g %.9g", p.T_target_source(r, 0), p.T_target_source(r, 1),
                 p.T_target_source(r, 2), p.T_target_source(r, 3));
  std::fprintf(f, "\n# px py pz qx qy qz weight inlier\n");
  for (std::size_t i = 0; i < p.correspondences.size(); ++i) {
    const auto& c = p.correspondences[i];
    std::fprintf(f, "%.9g %.9g %.9g %.9g %.9g %.9g 1 %d\n", c.p.x(), c.p.y(), c.p.z(), c.q.x(),
                 c.q.y(), c.q.z(), p.inlier[i] ? 1 : 0);
  }
  return std::fclose(f) == 0;
}

}  // namespace pagor
