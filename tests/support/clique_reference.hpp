#pragma once
// Straightforward references for the clique solvers' tests: random graphs, random association
// problems, subset enumeration, a plain branch and bound, and CLIPPER on dense matrices with
// rounding to the full support.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "pagor/graph/densest_clique.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "util/random_draw.hpp"

namespace pagor::test {

/// A one-level pyramid graph from adjacency lists (made symmetric and sorted).
inline PyramidGraph graph_from_lists(std::vector<std::vector<int>> adj) {
  PyramidGraph g;
  g.vertices = static_cast<int>(adj.size());
  g.thresholds = {1.0};
  g.offsets.assign(1, 0);
  std::size_t edges = 0;
  for (auto& row : adj) {
    std::sort(row.begin(), row.end());
    for (int v : row) {
      g.neighbors.push_back(v);
      g.level.push_back(0);
      g.trim.push_back(0.0f);
    }
    edges += row.size();
    g.offsets.push_back(static_cast<std::int64_t>(g.neighbors.size()));
  }
  g.edges_at_level = {edges / 2};
  return g;
}

/// A random graph (edge probability p) with a planted clique on k random vertices, as one level.
inline PyramidGraph random_graph(int n, double p, int k, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution edge(p);
  std::vector<int> ids(static_cast<std::size_t>(n));
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), rng);
  std::vector<char> planted(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < k && i < n; ++i)
    planted[static_cast<std::size_t>(ids[static_cast<std::size_t>(i)])] = 1;
  std::vector<std::vector<int>> adj(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((planted[static_cast<std::size_t>(i)] && planted[static_cast<std::size_t>(j)]) ||
          edge(rng)) {
        adj[static_cast<std::size_t>(i)].push_back(j);
        adj[static_cast<std::size_t>(j)].push_back(i);
      }
  return graph_from_lists(std::move(adj));
}

/// Issue 11's association problem, small: points in a 10 m cube, `inliers` of `m` moved by a
/// rigid motion with noise in a ball of 0.02 m, the others unrelated.
inline std::vector<Correspondence> association(int m, int inliers, std::uint64_t seed,
                                               std::vector<char>* flags = nullptr) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(0.0, 10.0), unit(-1.0, 1.0);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.2, 1).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(4, -2, 1);
  std::vector<Correspondence> c;
  for (int i = 0; i < m; ++i) {
    Correspondence x;
    x.source = x.target = i;
    x.p = draw3(coord, rng);
    Eigen::Vector3d n;
    do n = draw3(unit, rng);
    while (n.squaredNorm() > 1);
    x.q = i < inliers ? Eigen::Vector3d(R * x.p + t + 0.02 * n)
                      : draw3(coord, rng);
    c.push_back(x);
    if (flags) flags->push_back(i < inliers);
  }
  return c;
}

/// The graph parameters of issue 11's problems.
inline GraphParams association_params() {
  GraphParams gp;
  gp.trim = TrimKind::difference;
  gp.thresholds = {0.03, 0.06, 0.12, 0.24};
  gp.affinity = AffinityKind::gaussian;
  gp.sigma_ratio = 0.5;
  gp.min_length = 0.0;
  return gp;
}

/// Maximum clique size by enumerating every subset (n <= 20).
inline std::size_t brute_force_clique(const PyramidGraph& g, int level = 0) {
  std::size_t best = 0;
  for (std::uint32_t mask = 1; mask < (1u << g.vertices); ++mask) {
    const auto bits = static_cast<std::size_t>(__builtin_popcount(mask));
    if (bits <= best) continue;
    std::vector<int> s;
    for (int v = 0; v < g.vertices; ++v)
      if (mask & (1u << v)) s.push_back(v);
    if (is_clique(g, level, s)) best = bits;
  }
  return best;
}

/// Dense adjacency of a level.
inline std::vector<std::vector<char>> adjacency(const PyramidGraph& g, int level) {
  const auto n = static_cast<std::size_t>(g.vertices);
  std::vector<std::vector<char>> a(n, std::vector<char>(n, 0));
  for (std::size_t v = 0; v < n; ++v)
    for (auto e = g.offsets[v]; e < g.offsets[v + 1]; ++e)
      if (g.level[static_cast<std::size_t>(e)] <= level)
        a[v][static_cast<std::size_t>(g.neighbors[static_cast<std::size_t>(e)])] = 1;
  return a;
}

/// Maximum clique size by plain branch and bound (Carraghan and Pardalos: |current| +
/// |candidates| as the only bound) on a dense adjacency matrix.
inline std::size_t plain_max_clique(const PyramidGraph& g, int level) {
  const auto a = adjacency(g, level);
  std::size_t best = 0;
  std::function<void(std::size_t, const std::vector<int>&)> expand =
      [&](std::size_t size, const std::vector<int>& cand) {
        if (cand.empty()) {
          best = std::max(best, size);
          return;
        }
        for (std::size_t i = 0; i < cand.size(); ++i) {
          if (size + cand.size() - i <= best) return;
          std::vector<int> next;
          for (std::size_t j = i + 1; j < cand.size(); ++j)
            if (a[static_cast<std::size_t>(cand[i])][static_cast<std::size_t>(cand[j])])
              next.push_back(cand[j]);
          expand(size + 1, next);
        }
      };
  std::vector<int> all(static_cast<std::size_t>(g.vertices));
  std::iota(all.begin(), all.end(), 0);
  expand(0, all);
  return best;
}

/// CLIPPER as published, on dense matrices: maximise u^T M_d u over the non-negative unit sphere
/// by projected gradient ascent with backtracking, M_d = M - d (1 1^T - C), raising d by the mean
/// of (M u)_i / (sum(u) - (C u)_i) over the support entries with non-neighbours in the support
/// until the support is a clique; the answer is the full support of u.
inline std::vector<int> clipper_full_support(const PyramidGraph& g, int level, std::uint64_t seed) {
  const int n = g.vertices;
  if (n == 0) return {};
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(n, n), C = Eigen::MatrixXd::Identity(n, n);
  for (int v = 0; v < n; ++v)
    for (auto e = g.offsets[static_cast<std::size_t>(v)];
         e < g.offsets[static_cast<std::size_t>(v) + 1]; ++e) {
      const double w = g.weight(static_cast<std::size_t>(e), level);
      if (w == 0.0) continue;
      M(v, g.neighbors[static_cast<std::size_t>(e)]) = w;
      C(v, g.neighbors[static_cast<std::size_t>(e)]) = 1.0;
    }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(1e-3, 1.0);
  Eigen::VectorXd u(n);
  for (int i = 0; i < n; ++i) u[i] = dist(rng);
  u.normalize();
  const double eps = 1e-9;
  double d = 0;
  const auto F = [&](const Eigen::VectorXd& x) {
    return x.dot(M * x - d * (Eigen::VectorXd::Constant(n, x.sum()) - C * x));
  };
  for (int outer = 0; outer < 1000; ++outer) {
    double Fu = F(u);
    for (int inner = 0; inner < 200; ++inner) {
      const Eigen::VectorXd grad = M * u - d * (Eigen::VectorXd::Constant(n, u.sum()) - C * u);
      double alpha = 1.0 / (1.0 + d);
      bool accepted = false;
      Eigen::VectorXd un;
      double Fn = Fu;
      for (int ls = 0; ls < 99; ++ls) {
        un = (u + alpha * grad).cwiseMax(0.0);
        if (un.norm() > 0) {
          un.normalize();
          Fn = F(un);
          if (Fn > Fu) {
            accepted = true;
            break;
          }
        }
        alpha *= 0.25;
      }
      if (!accepted) break;
      const double step = (un - u).norm(), dF = Fn - Fu;
      u = un;
      Fu = Fn;
      if (step < 1e-8 || std::abs(dF) < 1e-9) break;
    }
    const double floor = 1e-6 * u.maxCoeff();
    for (int i = 0; i < n; ++i)
      if (u[i] < floor) u[i] = 0;
    u.normalize();
    const Eigen::VectorXd Mu = M * u, Cu = C * u;
    const double sum = u.sum();
    double increment = 0;
    int offenders = 0;
    for (int i = 0; i < n; ++i)
      if (u[i] > eps && sum - Cu[i] > eps) {
        increment += Mu[i] / (sum - Cu[i]);
        ++offenders;
      }
    if (offenders == 0) break;
    d += std::max(increment / offenders, eps);
  }
  std::vector<int> support;
  for (int i = 0; i < n; ++i)
    if (u[i] > eps) support.push_back(i);
  return support;
}

}  // namespace pagor::test
