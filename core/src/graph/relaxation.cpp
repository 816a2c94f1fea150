#include "graph/relaxation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace pagor::detail {
namespace {

constexpr std::size_t kLanes = 4;  // rows summed side by side in products()

// Products the relaxation needs: Mu = M u (affinities, unit diagonal), Cu = C u (adjacency, unit
// diagonal), both in one pass over the edges. When u has few non-zeros (late in the solve, and
// after a warm start), they are scattered from the support instead of gathered over every edge
// (the graph is symmetric).
void products(const LevelGraph& g, const std::vector<double>& u, std::vector<double>& Mu,
              std::vector<double>& Cu) {
  const std::size_t n = g.size();
  std::size_t support = 0;
  for (double x : u) support += x != 0.0;
  const int* nb = g.neighbors.data();
  const float* wt = g.weights.data();
  if (support * 4 < n) {
    std::fill(Cu.begin(), Cu.end(), 0.0);
    if (!g.binary) std::fill(Mu.begin(), Mu.end(), 0.0);
    for (std::size_t v = 0; v < n; ++v) {
      const double uv = u[v];
      if (uv == 0.0) continue;
      Cu[v] += uv;
      if (g.binary) {
        for (std::size_t e = g.offsets[v]; e < g.offsets[v + 1]; ++e)
          Cu[static_cast<std::size_t>(nb[e])] += uv;
      } else {
        Mu[v] += uv;
        for (std::size_t e = g.offsets[v]; e < g.offsets[v + 1]; ++e) {
          const auto w = static_cast<std::size_t>(nb[e]);
          Cu[w] += uv;
          Mu[w] += double(wt[e]) * uv;
        }
      }
    }
    if (g.binary) Mu = Cu;
    return;
  }
  // Each row's sum runs in edge order, so every product is the plain loop's to the last bit; four
  // rows are summed side by side over their common length, as one row's sum waits on its previous
  // addition at every edge.
  const auto x = [&](std::size_t e) { return u[static_cast<std::size_t>(nb[e])]; };
  std::size_t v = 0;
  for (; v + kLanes <= n; v += kLanes) {
    std::size_t e[kLanes], length = SIZE_MAX;
    double c[kLanes], m[kLanes];
    for (std::size_t k = 0; k < kLanes; ++k) {
      e[k] = g.offsets[v + k];
      length = std::min(length, g.offsets[v + k + 1] - e[k]);
      c[k] = m[k] = u[v + k];
    }
    if (g.binary) {
      for (std::size_t t = 0; t < length; ++t)
        for (std::size_t k = 0; k < kLanes; ++k) c[k] += x(e[k] + t);
    } else {
      for (std::size_t t = 0; t < length; ++t)
        for (std::size_t k = 0; k < kLanes; ++k) {
          const double xe = x(e[k] + t);
          c[k] += xe;
          m[k] += double(wt[e[k] + t]) * xe;
        }
    }
    for (std::size_t k = 0; k < kLanes; ++k) {
      for (std::size_t f = e[k] + length; f < g.offsets[v + k + 1]; ++f) {
        c[k] += x(f);
        if (!g.binary) m[k] += double(wt[f]) * x(f);
      }
      Cu[v + k] = c[k];
      Mu[v + k] = g.binary ? c[k] : m[k];
    }
  }
  for (; v < n; ++v) {
    double c = u[v], m = u[v];
    for (std::size_t e = g.offsets[v]; e < g.offsets[v + 1]; ++e) {
      c += x(e);
      if (!g.binary) m += double(wt[e]) * x(e);
    }
    Cu[v] = c;
    Mu[v] = g.binary ? c : m;
  }
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  return std::inner_product(a.begin(), a.end(), b.begin(), 0.0);
}

// The round(u^T C u) largest entries of u, then pruned greedily (most non-neighbours first) until
// they form a clique, which numerical ties can spoil. Local ids.
std::vector<int> round_to_clique(const LevelGraph& g, const std::vector<double>& u,
                                 const std::vector<double>& Cu) {
  const int omega = std::max(1, static_cast<int>(std::lround(dot(u, Cu))));
  std::vector<int> order(u.size());
  std::iota(order.begin(), order.end(), 0);
  const auto k = std::min<std::size_t>(static_cast<std::size_t>(omega), order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
                    [&](int a, int b) {
                      const double ua = u[static_cast<std::size_t>(a)],
                                   ub = u[static_cast<std::size_t>(b)];
                      return ua > ub || (ua == ub && a < b);
                    });
  std::vector<int> clique(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k));
  // in[v]: position in `clique` + 1, 0 outside. Members' non-neighbours among members, by
  // walking each member's neighbour list once.
  std::vector<int> in(u.size(), 0);
  while (clique.size() > 1) {
    for (std::size_t a = 0; a < clique.size(); ++a)
      in[static_cast<std::size_t>(clique[a])] = static_cast<int>(a) + 1;
    std::size_t worst = 0;
    int worst_missing = 0;
    for (std::size_t a = 0; a < clique.size(); ++a) {
      const auto v = static_cast<std::size_t>(clique[a]);
      int inside = 0;
      for (std::size_t e = g.offsets[v]; e < g.offsets[v + 1]; ++e)
        inside += in[static_cast<std::size_t>(g.neighbors[e])] != 0;
      const int missing = static_cast<int>(clique.size()) - 1 - inside;
      if (missing > worst_missing) {
        worst_missing = missing;
        worst = a;
      }
    }
    for (int v : clique) in[static_cast<std::size_t>(v)] = 0;
    if (worst_missing == 0) break;
    clique.erase(clique.begin() + static_cast<std::ptrdiff_t>(worst));
  }
  return clique;
}

}  // namespace

LevelGraph induce(const PyramidGraph& g, int level, const std::vector<int>& keep) {
  LevelGraph s;
  s.ids = keep;
  s.binary = g.affinity == AffinityKind::binary;
  std::vector<int> local(static_cast<std::size_t>(g.vertices), -1);
  for (std::size_t i = 0; i < keep.size(); ++i)
    local[static_cast<std::size_t>(keep[i])] = static_cast<int>(i);
  s.offsets.assign(1, 0);
  std::size_t rows = 0;  // an upper bound of the edges kept
  for (int v : keep)
    rows += static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v) + 1] -
                                     g.offsets[static_cast<std::size_t>(v)]);
  s.neighbors.reserve(rows);
  if (!s.binary) s.weights.reserve(rows);
  for (int v : keep) {
    const auto last = static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v) + 1]);
    for (auto e = static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v)]); e < last; ++e) {
      const int w = local[static_cast<std::size_t>(g.neighbors[e])];
      if (g.level[e] > level || w < 0) continue;
      s.neighbors.push_back(w);  // global ids are sorted, so local ids are too
      if (!s.binary) s.weights.push_back(g.trim[e]);
    }
    s.offsets.push_back(s.neighbors.size());
  }
  return s;
}

void set_weights(LevelGraph& s, const PyramidGraph& g, int level) {
  if (s.binary) return;
  const double sigma = g.sigma_ratio * g.thresholds[static_cast<std::size_t>(level)];
  const double scale = -1.0 / (2 * sigma * sigma);
  for (float& w : s.weights) w = static_cast<float>(std::exp(scale * double(w) * w));
}

bool project(std::vector<double>& u) {
  double n2 = 0;
  for (double& x : u) {
    x = std::max(x, 0.0);
    n2 += x * x;
  }
  if (n2 <= 0) return false;
  const double inv = 1.0 / std::sqrt(n2);
  for (double& x : u) x *= inv;
  return true;
}

// The relaxation proper on a level graph, from a non-negative unit vector u.
std::vector<int> relax(const LevelGraph& g, std::vector<double>& u, double d, const CliqueParams& p,
                       CliqueResult& r, Deadline deadline) {
  const std::size_t n = g.size();
  std::vector<double> Mu(n), Cu(n), grad(n), cand(n), Mu_c(n), Cu_c(n);
  std::vector<std::size_t> support(n);  // of the candidate
  double alpha = 1.0;
  products(g, u, Mu, Cu);
  double sum = std::accumulate(u.begin(), u.end(), 0.0);
  // F(u) = u^T M_d u with M_d u = M u - d (sum(u) 1 - C u).
  const auto penalised = [&](const std::vector<double>& M, const std::vector<double>& C, double s,
                             std::vector<double>& out) {
    for (std::size_t i = 0; i < n; ++i) out[i] = M[i] - d * (s - C[i]);
  };
  for (int outer = 0; outer < p.max_outer_iterations; ++outer) {
    // Inner loop: projected gradient ascent with backtracking; the step grows after a success.
    penalised(Mu, Cu, sum, grad);
    double F = dot(u, grad);
    alpha = 1.0 / (1.0 + d);  // the gradient grows with d
    for (int inner = 0; inner < p.max_inner_iterations; ++inner) {
      if (deadline != kNoDeadline && std::chrono::steady_clock::now() > deadline) {
        r.budget = CliqueBudget::time;
        break;
      }
      bool accepted = false;
      double F_new = F, sum_c = 0;
      for (int ls = 0; ls < p.max_line_search; ++ls) {
        ++r.gradient_steps;
        // The candidate projected onto {u >= 0, |u| = 1} (project()), with its sum, F and the
        // step: as the plain loops compute them to the last bit, but each sum runs over the
        // support only, as adding a zero changes no sum, and most entries are zero.
        std::size_t* const in = support.data();
        std::size_t k = 0;
        double n2 = 0;
        for (std::size_t i = 0; i < n; ++i) {
          const double c = std::max(u[i] + alpha * grad[i], 0.0);
          cand[i] = c;
          if (c > 0) {
            in[k++] = i;
            n2 += c * c;
          }
        }
        if (n2 > 0) {
          const double inv = 1.0 / std::sqrt(n2);
          sum_c = 0;
          for (std::size_t i = 0; i < n; ++i) cand[i] *= inv;
          for (std::size_t j = 0; j < k; ++j) sum_c += cand[in[j]];
          products(g, cand, Mu_c, Cu_c);
          double Fc = 0;
          for (std::size_t j = 0; j < k; ++j) {
            const std::size_t i = in[j];
            Fc += cand[i] * (Mu_c[i] - d * (sum_c - Cu_c[i]));
          }
          if (Fc > F) {
            F_new = Fc;
            accepted = true;
            break;
          }
        }
        alpha *= p.beta;
      }
      if (!accepted) break;
      double step = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (cand[i] != u[i]) step += (cand[i] - u[i]) * (cand[i] - u[i]);
      u.swap(cand);
      Mu.swap(Mu_c);
      Cu.swap(Cu_c);
      sum = sum_c;
      penalised(Mu, Cu, sum, grad);
      const double dF = F_new - F;
      F = F_new;
      alpha = std::min(alpha / p.beta, p.max_step);
      if (std::sqrt(step) < p.tol_u || std::abs(dF) < p.tol_F) break;
    }

    // Entries that have all but vanished are set to zero, so that the support test below sees
    // the support the rounding will see.
    const double floor = p.support_tol * *std::max_element(u.begin(), u.end());
    bool zeroed = false;
    for (double& x : u)
      if (x > 0 && x < floor) {
        x = 0;
        zeroed = true;
      }
    if (zeroed) {
      project(u);
      products(g, u, Mu, Cu);
      sum = std::accumulate(u.begin(), u.end(), 0.0);
    }

    // Outer loop: is the support of u a clique? If not, raise d. For a support entry i with
    // non-neighbours in the support, d_i = (M u)_i / (sum(u) - (C u)_i) is the penalty at which
    // its gradient vanishes; d grows by the mean d_i, so that many offenders leave at once.
    double increment = 0.0;
    int offenders = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (u[i] <= p.eps) continue;
      const double outside = sum - Cu[i];  // mass on i's non-neighbours
      if (outside <= p.eps) continue;
      increment += Mu[i] / outside;
      ++offenders;
    }
    ++r.penalty_updates;
    if (offenders == 0) break;  // the support is a clique
    if (r.budget == CliqueBudget::time) break;  // rounded from where it stands
    d += std::max(increment / offenders, p.eps);
  }
  r.penalty = d;
  return round_to_clique(g, u, Cu);
}

}  // namespace pagor::detail
