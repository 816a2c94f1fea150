#include "pagor/densest_clique.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>

namespace pagor {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// One level of the pyramid restricted to a vertex subset, with local ids and per-edge affinities:
// the relaxation's inner loop then touches neither absent levels nor pruned vertices.
struct LevelGraph {
  std::vector<int> ids;              // local -> global vertex id
  std::vector<std::size_t> offsets;  // CSR over local ids, neighbours sorted
  std::vector<int> neighbors;
  std::vector<double> weights;
  bool binary = true;  // all weights 1: M u = C u

  std::size_t size() const { return ids.size(); }
  bool adjacent(int a, int b) const {
    const auto first =
        neighbors.begin() + static_cast<std::ptrdiff_t>(offsets[static_cast<std::size_t>(a)]);
    const auto last =
        neighbors.begin() + static_cast<std::ptrdiff_t>(offsets[static_cast<std::size_t>(a) + 1]);
    return std::binary_search(first, last, b);
  }
};

std::vector<int> degrees(const PyramidGraph& g, int level) {
  std::vector<int> deg(static_cast<std::size_t>(g.vertices), 0);
  for (int v = 0; v < g.vertices; ++v)
    for (auto e = g.offsets[static_cast<std::size_t>(v)];
         e < g.offsets[static_cast<std::size_t>(v) + 1]; ++e)
      deg[static_cast<std::size_t>(v)] += g.level[static_cast<std::size_t>(e)] <= level;
  return deg;
}

// A clique grown greedily (by degree) from each of the highest-degree vertices: a lower bound.
std::vector<int> greedy_clique(const PyramidGraph& g, int level, const std::vector<int>& deg) {
  constexpr int kStarts = 32;  // highest-degree vertices to grow from
  std::vector<int> order(static_cast<std::size_t>(g.vertices));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return deg[static_cast<std::size_t>(a)] > deg[static_cast<std::size_t>(b)];
  });
  std::vector<int> best;
  for (int k = 0; k < std::min(kStarts, g.vertices); ++k) {
    const int v = order[static_cast<std::size_t>(k)];
    if (static_cast<std::size_t>(deg[static_cast<std::size_t>(v)]) + 1 <= best.size()) break;
    std::vector<int> cand;
    for (auto e = g.offsets[static_cast<std::size_t>(v)];
         e < g.offsets[static_cast<std::size_t>(v) + 1]; ++e)
      if (g.level[static_cast<std::size_t>(e)] <= level)
        cand.push_back(g.neighbors[static_cast<std::size_t>(e)]);
    std::stable_sort(cand.begin(), cand.end(), [&](int a, int b) {
      return deg[static_cast<std::size_t>(a)] > deg[static_cast<std::size_t>(b)];
    });
    std::vector<int> clique{v};
    for (int c : cand) {
      bool all = true;
      for (int w : clique) all = all && g.adjacent(c, w, level);
      if (all) clique.push_back(c);
    }
    if (clique.size() > best.size()) best = clique;
  }
  std::sort(best.begin(), best.end());
  return best;
}

// Vertices of the (min_degree)-core: what is left after repeatedly removing vertices with fewer
// than `min_degree` neighbours. A clique of size s lies in the (s-1)-core.
std::vector<int> core(const PyramidGraph& g, int level, std::vector<int> deg, int min_degree) {
  std::vector<char> removed(deg.size(), 0);
  std::vector<int> stack;
  for (int v = 0; v < g.vertices; ++v)
    if (deg[static_cast<std::size_t>(v)] < min_degree) {
      removed[static_cast<std::size_t>(v)] = 1;
      stack.push_back(v);
    }
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for (auto e = g.offsets[static_cast<std::size_t>(v)];
         e < g.offsets[static_cast<std::size_t>(v) + 1]; ++e) {
      if (g.level[static_cast<std::size_t>(e)] > level) continue;
      const auto w = static_cast<std::size_t>(g.neighbors[static_cast<std::size_t>(e)]);
      if (!removed[w] && --deg[w] < min_degree) {
        removed[w] = 1;
        stack.push_back(static_cast<int>(w));
      }
    }
  }
  std::vector<int> keep;
  for (int v = 0; v < g.vertices; ++v)
    if (!removed[static_cast<std::size_t>(v)]) keep.push_back(v);
  return keep;
}

LevelGraph induce(const PyramidGraph& g, int level, const std::vector<int>& keep) {
  LevelGraph s;
  s.ids = keep;
  s.binary = g.affinity == AffinityKind::binary;
  std::vector<int> local(static_cast<std::size_t>(g.vertices), -1);
  for (std::size_t i = 0; i < keep.size(); ++i)
    local[static_cast<std::size_t>(keep[i])] = static_cast<int>(i);
  s.offsets.assign(1, 0);
  for (int v : keep) {
    for (auto e = g.offsets[static_cast<std::size_t>(v)];
         e < g.offsets[static_cast<std::size_t>(v) + 1]; ++e) {
      const auto se = static_cast<std::size_t>(e);
      const int w = local[static_cast<std::size_t>(g.neighbors[se])];
      if (g.level[se] > level || w < 0) continue;
      s.neighbors.push_back(w);  // global ids are sorted, so local ids are too
      s.weights.push_back(g.weight(se, level));
    }
    s.offsets.push_back(s.neighbors.size());
  }
  return s;
}

// Products the relaxation needs: Mu = M u (affinities, unit diagonal), Cu = C u (adjacency, unit
// diagonal). When u has few non-zeros (late in the solve, and after a warm start), the products
// are scattered from the support instead of gathered over every edge (the graph is symmetric).
void products(const LevelGraph& g, const std::vector<double>& u, std::vector<double>& Mu,
              std::vector<double>& Cu) {
  std::size_t support = 0;
  for (double x : u) support += x != 0.0;
  const bool scatter = support * 4 < g.size();
  if (scatter) {
    std::fill(Cu.begin(), Cu.end(), 0.0);
    if (!g.binary) std::fill(Mu.begin(), Mu.end(), 0.0);
    for (std::size_t v = 0; v < g.size(); ++v) {
      const double uv = u[v];
      if (uv == 0.0) continue;
      Cu[v] += uv;
      if (!g.binary) Mu[v] += uv;
      for (std::size_t e = g.offsets[v]; e < g.offsets[v + 1]; ++e) {
        const auto w = static_cast<std::size_t>(g.neighbors[e]);
        Cu[w] += uv;
        if (!g.binary) Mu[w] += g.weights[e] * uv;
      }
    }
    if (g.binary) Mu = Cu;
    return;
  }
  for (std::size_t v = 0; v < g.size(); ++v) {
    double c = u[v];
    for (std::size_t e = g.offsets[v]; e < g.offsets[v + 1]; ++e)
      c += u[static_cast<std::size_t>(g.neighbors[e])];
    Cu[v] = c;
  }
  if (g.binary) {
    Mu = Cu;
    return;
  }
  for (std::size_t v = 0; v < g.size(); ++v) {
    double m = u[v];
    for (std::size_t e = g.offsets[v]; e < g.offsets[v + 1]; ++e)
      m += g.weights[e] * u[static_cast<std::size_t>(g.neighbors[e])];
    Mu[v] = m;
  }
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  return std::inner_product(a.begin(), a.end(), b.begin(), 0.0);
}

// Projection onto {u >= 0, |u| = 1}; false when nothing positive is left.
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
  while (clique.size() > 1) {
    std::size_t worst = 0;
    int worst_missing = 0;
    for (std::size_t a = 0; a < clique.size(); ++a) {
      int missing = 0;
      for (std::size_t b = 0; b < clique.size(); ++b)
        if (a != b && !g.adjacent(clique[a], clique[b])) ++missing;
      if (missing > worst_missing) {
        worst_missing = missing;
        worst = a;
      }
    }
    if (worst_missing == 0) break;
    clique.erase(clique.begin() + static_cast<std::ptrdiff_t>(worst));
  }
  return clique;
}

// Largest gradient step tried; beyond it a step only renormalises max(gradient, 0).
constexpr double kMaxStep = 1e6;

// The relaxation proper on a level graph, from a non-negative unit vector u.
std::vector<int> relax(const LevelGraph& g, std::vector<double>& u, double d, const CliqueParams& p,
                       CliqueResult& r) {
  const std::size_t n = g.size();
  std::vector<double> Mu(n), Cu(n), grad(n), cand(n), Mu_c(n), Cu_c(n);
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
      bool accepted = false;
      double F_new = F;
      for (int ls = 0; ls < p.max_line_search; ++ls) {
        ++r.gradient_steps;
        for (std::size_t i = 0; i < n; ++i) cand[i] = u[i] + alpha * grad[i];
        if (project(cand)) {
          products(g, cand, Mu_c, Cu_c);
          const double sum_c = std::accumulate(cand.begin(), cand.end(), 0.0);
          double Fc = 0;
          for (std::size_t i = 0; i < n; ++i) Fc += cand[i] * (Mu_c[i] - d * (sum_c - Cu_c[i]));
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
      for (std::size_t i = 0; i < n; ++i) step += (cand[i] - u[i]) * (cand[i] - u[i]);
      u.swap(cand);
      Mu.swap(Mu_c);
      Cu.swap(Cu_c);
      sum = std::accumulate(u.begin(), u.end(), 0.0);
      penalised(Mu, Cu, sum, grad);
      const double dF = F_new - F;
      F = F_new;
      alpha = std::min(alpha / p.beta, kMaxStep);
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
    d += std::max(increment / offenders, p.eps);
  }
  r.penalty = d;
  return round_to_clique(g, u, Cu);
}

}  // namespace

std::vector<double> random_start(int size, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(1e-3, 1.0);
  std::vector<double> u(static_cast<std::size_t>(size));
  for (double& x : u) x = dist(rng);
  project(u);
  return u;
}

bool is_clique(const PyramidGraph& g, int level, const std::vector<int>& vertices) {
  for (std::size_t a = 0; a < vertices.size(); ++a)
    for (std::size_t b = a + 1; b < vertices.size(); ++b)
      if (!g.adjacent(vertices[a], vertices[b], level)) return false;
  return true;
}

CliqueResult solve_clipper(const PyramidGraph& g, int level, const std::vector<double>& u0,
                           const CliqueParams& p, const std::vector<int>& known_clique, double d0) {
  const auto t0 = Clock::now();
  CliqueResult r;
  r.level = level;
  if (g.vertices == 0) return r;
  const std::size_t n = static_cast<std::size_t>(g.vertices);

  // Which vertices the relaxation works on: all, or the core that can hold a clique at least as
  // large as a greedy one.
  const std::vector<int> deg = degrees(g, level);
  std::vector<int> greedy, keep;
  if (p.prune) {
    greedy = greedy_clique(g, level, deg);
    if (known_clique.size() > greedy.size() && is_clique(g, level, known_clique))
      greedy = known_clique;
    keep = core(g, level, deg, static_cast<int>(greedy.size()) - 1);
  } else {
    keep.resize(n);
    std::iota(keep.begin(), keep.end(), 0);
  }
  const LevelGraph sub = induce(g, level, keep);

  // Start vector restricted to the kept vertices; the seeded random start if nothing is left.
  std::vector<double> u(sub.size());
  // A warm start gets a little of the random start mixed in, so that vertices it left at zero
  // start above zero.
  const std::vector<double> start = random_start(g.vertices, p.seed);
  const bool warm = u0.size() == n;
  for (std::size_t i = 0; i < sub.size(); ++i) {
    const auto v = static_cast<std::size_t>(sub.ids[i]);
    u[i] = warm ? u0[v] + p.warm_start_mix * start[v] : 0.0;
  }
  if (!project(u)) {
    for (std::size_t i = 0; i < sub.size(); ++i) u[i] = start[static_cast<std::size_t>(sub.ids[i])];
    project(u);
  }

  const std::vector<int> local = sub.size() > 0 ? relax(sub, u, d0, p, r) : std::vector<int>{};
  for (int v : local) r.vertices.push_back(sub.ids[static_cast<std::size_t>(v)]);
  std::sort(r.vertices.begin(), r.vertices.end());
  if (greedy.size() > r.vertices.size()) r.vertices = greedy;  // never worse than the lower bound
  r.u.assign(n, 0.0);
  for (std::size_t i = 0; i < sub.size(); ++i) r.u[static_cast<std::size_t>(sub.ids[i])] = u[i];
  r.time_ms = ms_since(t0);
  return r;
}

namespace {

// Branch and bound for the maximum clique with a greedy colouring bound (Tomita-style).
struct ExactSearch {
  const PyramidGraph& g;
  int level;
  long budget;
  long nodes = 0;
  std::vector<int> best, current;

  void expand(std::vector<int> candidates) {
    if (++nodes > budget) return;
    // Greedy colouring of the candidates: colour classes of mutually non-adjacent vertices.
    std::vector<int> order, colour;
    std::vector<std::vector<int>> classes;
    for (int v : candidates) {
      std::size_t k = 0;
      for (; k < classes.size(); ++k) {
        bool fits = true;
        for (int w : classes[k]) fits = fits && !g.adjacent(v, w, level);
        if (fits) break;
      }
      if (k == classes.size()) classes.emplace_back();
      classes[k].push_back(v);
    }
    for (std::size_t k = 0; k < classes.size(); ++k)
      for (int v : classes[k]) {
        order.push_back(v);
        colour.push_back(static_cast<int>(k) + 1);
      }
    // Take vertices from the highest colour down; colour + |current| bounds any clique found.
    for (int idx = static_cast<int>(order.size()) - 1; idx >= 0; --idx) {
      if (current.size() + static_cast<std::size_t>(colour[static_cast<std::size_t>(idx)]) <=
          best.size())
        return;
      const int v = order[static_cast<std::size_t>(idx)];
      current.push_back(v);
      std::vector<int> next;
      for (int j = 0; j < idx; ++j)
        if (g.adjacent(v, order[static_cast<std::size_t>(j)], level))
          next.push_back(order[static_cast<std::size_t>(j)]);
      if (next.empty()) {
        if (current.size() > best.size()) best = current;
      } else {
        expand(std::move(next));
      }
      current.pop_back();
      if (nodes > budget) return;
    }
  }
};

}  // namespace

CliqueResult exact_max_clique(const PyramidGraph& g, int level, const CliqueParams& p) {
  const auto t0 = Clock::now();
  ExactSearch s{g, level, p.exact_max_nodes, 0, {}, {}};
  std::vector<int> all(static_cast<std::size_t>(g.vertices));
  std::iota(all.begin(), all.end(), 0);
  // Higher degree first tends to find large cliques early.
  const std::vector<int> degree = degrees(g, level);
  std::stable_sort(all.begin(), all.end(), [&](int a, int b) {
    return degree[static_cast<std::size_t>(a)] < degree[static_cast<std::size_t>(b)];
  });
  if (!all.empty()) s.expand(all);
  CliqueResult r;
  r.level = level;
  r.vertices = s.best;
  std::sort(r.vertices.begin(), r.vertices.end());
  r.optimal = s.nodes <= s.budget;
  r.time_ms = ms_since(t0);
  return r;
}

std::vector<CliqueResult> solve_pyramid(const PyramidGraph& g, const CliqueParams& p) {
  std::vector<CliqueResult> out;
  const std::vector<double> start = random_start(g.vertices, p.seed);
  for (int l = 0; l < g.levels(); ++l) {
    switch (p.solver) {
      case CliqueSolver::exact:
        out.push_back(exact_max_clique(g, l, p));
        break;
      case CliqueSolver::independent:
        out.push_back(solve_clipper(g, l, start, p));
        break;
      case CliqueSolver::cascaded:
        // Alg. 1: level l starts where level l-1 ended. Its edges are a subset of level l's, so its
        // clique is also a clique here: a lower bound for pruning.
        if (l == 0)
          out.push_back(solve_clipper(g, l, start, p));
        else
          out.push_back(solve_clipper(g, l, out.back().u, p, out.back().vertices,
                                      p.warm_start_penalty * out.back().penalty));
        break;
    }
  }
  return out;
}

}  // namespace pagor
