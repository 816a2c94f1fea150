#include "pagor/graph/pyramid_graph.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "pagor/graph/trim.hpp"
#include "util/big_buffers.hpp"

// The pair loops are compiled for AVX2 too, chosen once at load time where the CPU has it (GCC's
// function clones; other compilers get the portable build only).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PAGOR_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PAGOR_AVX2_CLONES
#endif

namespace pagor {
namespace {

// Edge (i, j), i < j, kept in row i's run of its pass (row i is known from where the run starts):
// j in the low 24 bits, the edge's lowest level in the high 8. Four bytes an edge, and its TRIM
// value beside it only where the affinity needs it: a dense build's scratch is megabytes, and on
// its first build in a process each page of it is a fault (dear in a virtual machine).
using Edge = std::uint32_t;
constexpr int kEdgeLevelShift = 24;
constexpr Edge kEdgeVertexMask = (Edge(1) << kEdgeLevelShift) - 1;
inline Edge edge(int j, int level) {
  return static_cast<Edge>(j) | static_cast<Edge>(level) << kEdgeLevelShift;
}
inline int edge_vertex(Edge e) {
  return static_cast<int>(e & kEdgeVertexMask);
}
inline std::uint8_t edge_level(Edge e) {
  return static_cast<std::uint8_t>(e >> kEdgeLevelShift);
}

// One thread's share of the edge pass: the edges (i, j), i < j, of rows [first, first + rows), in
// (i, j) order, where each row's run starts, and how many edges each vertex gets as the higher end.
struct EdgeRows {
  detail::UninitVector<Edge> edges;
  detail::UninitVector<float> trims;  // each edge's TRIM value; empty unless `with_trims`
  bool with_trims = false;
  std::vector<std::size_t> starts;  // row first + r's edges are [starts[r], starts[r + 1])
  std::vector<int> lower;           // per vertex v: edges (i, v), i < v, in these rows
  int first = 0;

  /// Empty, for rows from `first_row` on of a graph of m vertices (storage kept).
  void reset(int m, int first_row, bool trims_too) {
    edges.clear();
    trims.clear();
    with_trims = trims_too;
    starts.clear();
    lower.assign(static_cast<std::size_t>(m), 0);
    first = first_row;
  }
};

// Coordinates and ids in flat arrays, read in the hot loop: exact (double) and, for a first
// vectorised pass, centred single-precision copies.
struct Packed {
  std::vector<double> px, py, pz, qx, qy, qz;
  std::vector<float> fx[6];  // px, py, pz, qx, qy, qz centred on their means
  std::vector<int> source, target;
  double extent = 0;  // largest centred coordinate [m]
  explicit Packed(const std::vector<Correspondence>& c) {
    Eigen::Vector3d mp = Eigen::Vector3d::Zero(), mq = Eigen::Vector3d::Zero();
    for (const auto& x : c) {
      px.push_back(x.p.x());
      py.push_back(x.p.y());
      pz.push_back(x.p.z());
      qx.push_back(x.q.x());
      qy.push_back(x.q.y());
      qz.push_back(x.q.z());
      source.push_back(x.source);
      target.push_back(x.target);
      mp += x.p;
      mq += x.q;
    }
    if (!c.empty()) {
      mp /= double(c.size());
      mq /= double(c.size());
    }
    const std::vector<double>* exact[6] = {&px, &py, &pz, &qx, &qy, &qz};
    const double mean[6] = {mp.x(), mp.y(), mp.z(), mq.x(), mq.y(), mq.z()};
    for (int a = 0; a < 6; ++a) {
      fx[a].reserve(c.size());
      for (double v : *exact[a]) {
        fx[a].push_back(static_cast<float>(v - mean[a]));
        extent = std::max(extent, std::abs(v - mean[a]));
      }
    }
  }
};

// The exact test of pair (i, j), i < j: appends the edge when it is consistent at some level.
inline void exact_pair(const Packed& c, const GraphParams& params, int i, int j, EdgeRows& out) {
  const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
  const double dpx = c.px[si] - c.px[sj], dpy = c.py[si] - c.py[sj], dpz = c.pz[si] - c.pz[sj];
  const double dqx = c.qx[si] - c.qx[sj], dqy = c.qy[si] - c.qy[sj], dqz = c.qz[si] - c.qz[sj];
  const double a2 = dpx * dpx + dpy * dpy + dpz * dpz;
  const double b2 = dqx * dqx + dqy * dqy + dqz * dqz;
  const double min_sq = params.min_length * params.min_length;
  if (a2 < min_sq || b2 < min_sq) return;
  if (c.source[si] == c.source[sj] || c.target[si] == c.target[sj])
    return;  // one landmark, two roles
  const auto& eps = params.thresholds;
  const double tv = trim_value(params.trim, std::sqrt(a2), std::sqrt(b2));
  if (!(tv <= eps.back())) return;
  const auto level = std::lower_bound(eps.begin(), eps.end(), tv) - eps.begin();
  out.edges.push_back(edge(j, static_cast<int>(level)));
  if (out.with_trims) out.trims.push_back(static_cast<float>(tv));
  ++out.lower[sj];
}

constexpr int kBlock = 256;  // pairs tested at once by the single-precision pass

// The single-precision pass over pairs (i, j), j in [j0, j0 + n): the j that may be consistent,
// written to `keep`; returns how many. Its margins are far wider than single precision's error on
// centred coordinates, so that every pair the exact test accepts passes (the exact test decides).
// Compiled for AVX2 too where the CPU has it.
PAGOR_AVX2_CLONES int prefilter(const Packed& c, int i, int j0, int n, bool ratio, float min_sq,
                                float ratio_sq, float ratio_slack, float diff, int* keep) {
  const auto si = static_cast<std::size_t>(i);
  const float pxi = c.fx[0][si], pyi = c.fx[1][si], pzi = c.fx[2][si];
  const float qxi = c.fx[3][si], qyi = c.fx[4][si], qzi = c.fx[5][si];
  const float* px = c.fx[0].data() + j0;
  const float* py = c.fx[1].data() + j0;
  const float* pz = c.fx[2].data() + j0;
  const float* qx = c.fx[3].data() + j0;
  const float* qy = c.fx[4].data() + j0;
  const float* qz = c.fx[5].data() + j0;
  unsigned char pass[kBlock];
  // One branch-free loop per TRIM kind (`consistent` is inlined into each), so that the compiler
  // runs it on vector lanes.
  const auto scan = [&](const auto& consistent) {
    for (int t = 0; t < n; ++t) {
      const float dpx = pxi - px[t], dpy = pyi - py[t], dpz = pzi - pz[t];
      const float dqx = qxi - qx[t], dqy = qyi - qy[t], dqz = qzi - qz[t];
      const float a2 = dpx * dpx + dpy * dpy + dpz * dpz;
      const float b2 = dqx * dqx + dqy * dqy + dqz * dqz;
      const float lo = a2 < b2 ? a2 : b2, hi = a2 < b2 ? b2 : a2;
      pass[t] = static_cast<unsigned char>((lo >= min_sq) & consistent(lo, hi));
    }
  };
  if (ratio)
    scan([&](float lo, float hi) { return hi <= ratio_sq * lo + ratio_slack; });
  else
    scan([&](float lo, float hi) { return std::sqrt(hi) - std::sqrt(lo) <= diff; });
  int k = 0;
  for (int t = 0; t < n; ++t) {
    keep[k] = j0 + t;
    k += pass[t];
  }
  return k;
}

// The exact test of pairs (i, keep[t]), t < k, as exact_pair does it to the last bit, in two
// passes: the lengths, TRIM values and levels side by side (vectorised, with AVX2 where the CPU
// has it), then the edges appended.
PAGOR_AVX2_CLONES void exact_block(const Packed& c, const GraphParams& params, int i,
                                   const int* keep, int k, EdgeRows& rows) {
  const auto si = static_cast<std::size_t>(i);
  const double pxi = c.px[si], pyi = c.py[si], pzi = c.pz[si];
  const double qxi = c.qx[si], qyi = c.qy[si], qzi = c.qz[si];
  const double* px = c.px.data();
  const double* py = c.py.data();
  const double* pz = c.pz.data();
  const double* qx = c.qx.data();
  const double* qy = c.qy.data();
  const double* qz = c.qz.data();
  const double min_sq = params.min_length * params.min_length;
  const bool ratio = params.trim == TrimKind::ratio;
  const auto& eps = params.thresholds;
  const int levels = static_cast<int>(eps.size());
  double tv[kBlock];
  unsigned char ok[kBlock];
  // One branch-free loop per TRIM kind (vector lanes). The ratio's lo = 0 gives inf or NaN here
  // where trim_value() gives HUGE_VAL: rejected all the same.
  const double largest = eps.back();
  if (ratio) {
    for (int t = 0; t < k; ++t) {
      const int j = keep[t];
      const double dpx = pxi - px[j], dpy = pyi - py[j], dpz = pzi - pz[j];
      const double dqx = qxi - qx[j], dqy = qyi - qy[j], dqz = qzi - qz[j];
      const double a2 = dpx * dpx + dpy * dpy + dpz * dpz;
      const double b2 = dqx * dqx + dqy * dqy + dqz * dqz;
      const double a = std::sqrt(a2), b = std::sqrt(b2);
      const double lo = a < b ? a : b, hi = a < b ? b : a;
      tv[t] = hi / lo - 1.0;
      ok[t] = static_cast<unsigned char>((a2 >= min_sq) & (b2 >= min_sq) & (tv[t] <= largest));
    }
  } else {
    for (int t = 0; t < k; ++t) {
      const int j = keep[t];
      const double dpx = pxi - px[j], dpy = pyi - py[j], dpz = pzi - pz[j];
      const double dqx = qxi - qx[j], dqy = qyi - qy[j], dqz = qzi - qz[j];
      const double a2 = dpx * dpx + dpy * dpy + dpz * dpz;
      const double b2 = dqx * dqx + dqy * dqy + dqz * dqz;
      tv[t] = std::abs(std::sqrt(a2) - std::sqrt(b2));
      ok[t] = static_cast<unsigned char>((a2 >= min_sq) & (b2 >= min_sq) & (tv[t] <= largest));
    }
  }
  // Each pair's level: the epsilons below its TRIM value, counted branch-free a level at a time
  // (a search per pair mispredicted on most edges).
  unsigned char lvl[kBlock];
  for (int t = 0; t < k; ++t) lvl[t] = 0;
  for (int l = 0; l + 1 < levels; ++l) {
    const double e = eps[static_cast<std::size_t>(l)];
    for (int t = 0; t < k; ++t) lvl[t] = static_cast<unsigned char>(lvl[t] + (e < tv[t]));
  }
  const int s = c.source[si], tg = c.target[si];
  // Room for the whole block (left uninitialised: zeroing it was a fifth of the graph's time on
  // m = 5000), written in place, then cut to the edges kept.
  auto& out = rows.edges;
  int* const lower = rows.lower.data();
  const std::size_t base = out.size();
  out.resize(base + static_cast<std::size_t>(k));
  if (rows.with_trims) rows.trims.resize(base + static_cast<std::size_t>(k));
  Edge* e = out.data() + base;
  float* const tr = rows.with_trims ? rows.trims.data() + base : nullptr;
  int kept = 0;
  for (int t = 0; t < k; ++t) {
    if (!ok[t]) continue;
    const int j = keep[t];
    const auto sj = static_cast<std::size_t>(j);
    if (s == c.source[sj] || tg == c.target[sj]) continue;  // one landmark, two roles
    if (tr) tr[kept] = static_cast<float>(tv[t]);
    e[kept++] = edge(j, lvl[t]);
    ++lower[sj];
  }
  out.resize(base + static_cast<std::size_t>(kept));
  if (tr) rows.trims.resize(base + static_cast<std::size_t>(kept));
}

// Appends the edges (i, j), i < j, for i in [begin, end), in increasing (i, j) order, to `out`
// (whose `lower` has room for every vertex), with each row's start. A single-precision pass over
// blocks of pairs rejects most pairs; the exact test runs on the rest (all pairs when the
// coordinates are too far from their centre for single precision to be safe).
void collect_edges(const Packed& c, const GraphParams& params, int begin, int end, EdgeRows& out) {
  const double largest = params.thresholds.back();
  const bool ratio = params.trim == TrimKind::ratio;
  const int m = static_cast<int>(c.px.size());
  // Single precision on centred coordinates (|x| <= extent) errs on a length by less than
  // delta = 1e-6 (extent + 1) m, and on a squared length by a relative 1e-6 more; the pass widens
  // every test by that (with a factor of safety), so it keeps every pair the exact test accepts.
  const bool fast = c.extent < 1e5;
  const double delta = 1e-6 * (c.extent + 1.0);
  const double longest = 2 * std::sqrt(3.0) * c.extent + delta;
  const double shortest = std::max(0.0, params.min_length - delta);
  const float min_sq = static_cast<float>(shortest * shortest * (1 - 1e-5));
  const double r = 1.0 + largest;
  const float ratio_sq = static_cast<float>(r * r * (1 + 1e-5));
  // hi <= r lo exactly => hi' <= r lo' + (1 + r) delta => hi'^2 <= r^2 lo'^2 + slack
  const double spread = (1 + r) * delta;
  const float ratio_slack = static_cast<float>(2 * r * longest * spread + spread * spread);
  const float diff = static_cast<float>(largest + 2 * delta + 1e-6 * longest);
  int keep[kBlock];
  for (int i = begin; i < end; ++i) {
    out.starts.push_back(out.edges.size());
    if (!fast) {
      for (int j = i + 1; j < m; ++j) exact_pair(c, params, i, j, out);
      continue;
    }
    for (int j0 = i + 1; j0 < m; j0 += kBlock) {
      const int n = std::min(kBlock, m - j0);
      const int k = prefilter(c, i, j0, n, ratio, min_sq, ratio_sq, ratio_slack, diff, keep);
      exact_block(c, params, i, keep, k, out);
    }
  }
  out.starts.push_back(out.edges.size());
}

// Adds to at_most[l] the edges among levels[0, n) at level l or below (a byte compare per level,
// on vector lanes; counting them one by one chained each count on the last).
void count_levels(const std::uint8_t* levels, std::size_t n, std::vector<std::size_t>& at_most) {
  for (std::size_t l = 0; l + 1 < at_most.size(); ++l) {
    std::size_t count = 0;
    for (std::size_t t = 0; t < n; ++t) count += levels[t] <= l;
    at_most[l] += count;
  }
  at_most.back() += n;
}

}  // namespace

double PyramidGraph::weight(std::size_t e, int l) const {
  if (level[e] > l) return 0.0;
  if (affinity == AffinityKind::binary) return 1.0;
  const double sigma = sigma_ratio * thresholds[static_cast<std::size_t>(l)];
  return std::exp(-double(trim[e]) * trim[e] / (2 * sigma * sigma));
}

bool PyramidGraph::adjacent(int u, int v, int l) const {
  const auto first = neighbors.begin() + offsets[static_cast<std::size_t>(u)];
  const auto last = neighbors.begin() + offsets[static_cast<std::size_t>(u) + 1];
  const auto it = std::lower_bound(first, last, v);
  return it != last && *it == v && level[static_cast<std::size_t>(it - neighbors.begin())] <= l;
}

std::size_t PyramidGraph::active_vertices(int l) const {
  std::size_t n = 0;
  for (int v = 0; v < vertices; ++v)
    for (auto e = offsets[static_cast<std::size_t>(v)];
         e < offsets[static_cast<std::size_t>(v) + 1]; ++e)
      if (level[static_cast<std::size_t>(e)] <= l) {
        ++n;
        break;
      }
  return n;
}

namespace {

// What a build needs besides the graph, kept by PyramidGraphBuilder between builds.
struct GraphScratch {
  std::vector<EdgeRows> parts;     // each thread's rows
  EdgeRows sample;                 // edges of the rows that estimate the room
  std::vector<std::int64_t> fill;  // next free place in each row
};

// Builds `g` in place: its arrays (and the scratch) keep their storage, so a build no larger than
// the last allocates nothing, and resizing them zeroes only what grows.
void build_into(const std::vector<Correspondence>& c, const GraphParams& params, int threads,
                PyramidGraph& g, GraphScratch& scratch) {
  const auto t0 = std::chrono::steady_clock::now();
  g.vertices = static_cast<int>(c.size());
  g.thresholds = params.thresholds;
  g.affinity = params.affinity;
  g.sigma_ratio = params.sigma_ratio;
  g.edges_at_level.assign(params.thresholds.size(), 0);
  g.offsets.assign(c.size() + 1, 0);
  // An edge keeps its other end in 24 bits; a graph of more vertices would have ~1.4e14 pairs.
  if (c.size() > kEdgeVertexMask)
    throw std::length_error("a consistency graph of " + std::to_string(c.size()) +
                            " correspondences: at most 16,777,215");
  // The edges' TRIM values only where the affinity weighs them.
  const bool with_trims = params.affinity != AffinityKind::binary;

  // Rows are split so that each thread gets about the same number of pairs.
  const int m = g.vertices;
  // A thread pays off from ~1M pairs on: m = 972 (471k pairs) built in 1.2 ms on one thread and
  // 1.6 ms on two (bench section 1; starting a thread costs ~0.1 ms in a virtual machine).
  threads = std::max(1, std::min(threads, static_cast<int>(0.5 * m * (m - 1.0) / 1e6) + 1));
  std::vector<int> bounds{0};
  const double pairs = 0.5 * m * (m - 1.0);
  for (int t = 1; t < threads; ++t) {
    // Rows [0, r) hold r*m - r*(r+1)/2 pairs; solve for the t-th share.
    const double share = pairs * t / threads;
    const double r = (2.0 * m - 1 - std::sqrt((2.0 * m - 1) * (2.0 * m - 1) - 8 * share)) / 2;
    bounds.push_back(std::clamp(static_cast<int>(r), bounds.back(), m));
  }
  bounds.push_back(m);
  std::vector<EdgeRows>& parts = scratch.parts;
  parts.resize(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t)
    parts[static_cast<std::size_t>(t)].reset(m, bounds[static_cast<std::size_t>(t)], with_trims);
  const Packed packed(c);
  // Room for the edges, estimated on a sample of rows (growing the lists copies them; small
  // graphs grow cheaply, and the sample would cost more than it saves).
  if (m >= 512) {
    EdgeRows& sample = scratch.sample;
    sample.reset(m, 0, false);
    const int step = std::max(1, m / 32);
    double sampled_pairs = 0;
    for (int i = 0; i < m; i += step) {
      collect_edges(packed, params, i, i + 1, sample);
      sampled_pairs += m - 1 - i;
    }
    const double fraction = sampled_pairs > 0 ? double(sample.edges.size()) / sampled_pairs : 0.0;
    for (int t = 0; t < threads; ++t) {
      const double rows_pairs =
          (bounds[t + 1] - bounds[t]) * (m - 0.5 * (bounds[t] + bounds[t + 1]));
      detail::reserve_fresh(parts[static_cast<std::size_t>(t)].edges,
                            static_cast<std::size_t>(1.2 * fraction * rows_pairs) + 16);
    }
  }
  if (threads == 1) {
    collect_edges(packed, params, 0, m, parts[0]);
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back(collect_edges, std::cref(packed), std::cref(params), bounds[t],
                        bounds[t + 1], std::ref(parts[static_cast<std::size_t>(t)]));
    for (auto& th : pool) th.join();
  }

  // Symmetric CSR with sorted neighbour lists. Row v holds its lower neighbours (from rows i < v,
  // in increasing i), then its higher ones (its own run, in increasing j).
  for (const EdgeRows& part : parts) {
    for (std::size_t r = 0; r + 1 < part.starts.size(); ++r)
      g.offsets[static_cast<std::size_t>(part.first) + r + 1] +=
          static_cast<std::int64_t>(part.starts[r + 1] - part.starts[r]);
    for (std::size_t v = 0; v < part.lower.size(); ++v) g.offsets[v + 1] += part.lower[v];
  }
  for (std::size_t v = 0; v < c.size(); ++v) g.offsets[v + 1] += g.offsets[v];
  const std::size_t directed = static_cast<std::size_t>(g.offsets.back());
  // Every place is written below; storage kept from an earlier build is not zeroed again.
  const auto room = [directed](auto& v) {
    detail::reserve_fresh(v, directed);
    v.resize(directed);
  };
  room(g.neighbors);
  room(g.level);
  if (with_trims)
    room(g.trim);
  else
    g.trim.clear();
  std::vector<std::int64_t>& fill = scratch.fill;
  fill.assign(g.offsets.begin(), g.offsets.end() - 1);
  // Row i's run is copied after its lower neighbours, and each of its edges (i, j) is placed in row
  // j as a lower neighbour, in increasing i. Placing them row by row scattered the writes over
  // every row's end (3 cache lines a row: ~1 MiB at m = 5000, more than a core's L2); so the rows
  // are taken in blocks, and a block's edges are placed a tile of target rows at a time, each
  // target row receiving a block's edges in a burst. Raw pointers: through the vectors, each
  // one-byte level store (which may alias anything) made the loops reload every data pointer.
  constexpr std::size_t kRows = 128;  // source rows per block
  constexpr int kTile = 1024;         // target rows per tile
  std::int64_t* const next = fill.data();
  int* const neighbors = g.neighbors.data();
  std::uint8_t* const levels = g.level.data();
  float* const trims = with_trims ? g.trim.data() : nullptr;
  const std::int64_t* const offsets = g.offsets.data();
  std::size_t cursor[kRows];
  for (const EdgeRows& part : parts) {
    const std::size_t rows = part.starts.size() - 1;
    const Edge* const edges = part.edges.data();
    for (std::size_t r0 = 0; r0 < rows; r0 += kRows) {
      const std::size_t r1 = std::min(rows, r0 + kRows);
      for (std::size_t r = r0; r < r1; ++r) {
        const int i = part.first + static_cast<int>(r);
        const Edge* const run = edges + part.starts[r];
        const std::size_t n = part.starts[r + 1] - part.starts[r];
        const auto higher = static_cast<std::size_t>(offsets[i + 1]) - n;
        for (std::size_t t = 0; t < n; ++t) {
          neighbors[higher + t] = edge_vertex(run[t]);
          levels[higher + t] = edge_level(run[t]);
          if (trims) trims[higher + t] = part.trims[part.starts[r] + t];
        }
        count_levels(levels + higher, n, g.edges_at_level);
        cursor[r - r0] = part.starts[r];
      }
      for (int tile = part.first + static_cast<int>(r0) + 1; tile < m; tile += kTile) {
        const int tile_end = tile + kTile;  // beyond m when it is the last tile
        for (std::size_t r = r0; r < r1; ++r) {
          const int i = part.first + static_cast<int>(r);
          std::size_t e = cursor[r - r0];
          const std::size_t end = part.starts[r + 1];
          for (; e < end && edge_vertex(edges[e]) < tile_end; ++e) {
            const auto k = static_cast<std::size_t>(next[edge_vertex(edges[e])]++);
            neighbors[k] = i;
            levels[k] = edge_level(edges[e]);
            if (trims) trims[k] = part.trims[e];
          }
          cursor[r - r0] = e;
        }
      }
    }
  }
  g.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

struct PyramidGraphBuilder::Scratch : GraphScratch {};

PyramidGraph build_pyramid_graph(const std::vector<Correspondence>& c, const GraphParams& params,
                                 int threads) {
  PyramidGraph g;
  GraphScratch scratch;
  build_into(c, params, threads, g, scratch);
  return g;
}

PyramidGraphBuilder::PyramidGraphBuilder() : scratch_(std::make_unique<Scratch>()) {}
PyramidGraphBuilder::~PyramidGraphBuilder() = default;
PyramidGraphBuilder::PyramidGraphBuilder(const PyramidGraphBuilder& other)
    : scratch_(std::make_unique<Scratch>()), graph_(other.graph_) {}
PyramidGraphBuilder& PyramidGraphBuilder::operator=(const PyramidGraphBuilder& other) {
  graph_ = other.graph_;
  return *this;
}
PyramidGraphBuilder::PyramidGraphBuilder(PyramidGraphBuilder&& other) noexcept
    : scratch_(std::move(other.scratch_)), graph_(std::exchange(other.graph_, PyramidGraph{})) {}
PyramidGraphBuilder& PyramidGraphBuilder::operator=(PyramidGraphBuilder&& other) noexcept {
  scratch_ = std::move(other.scratch_);
  graph_ = std::exchange(other.graph_, PyramidGraph{});
  return *this;
}

const PyramidGraph& PyramidGraphBuilder::build(const std::vector<Correspondence>& c,
                                               const GraphParams& params, int threads) {
  if (!scratch_) scratch_ = std::make_unique<Scratch>();  // moved from
  try {
    build_into(c, params, threads, graph_, *scratch_);
  } catch (...) {
    graph_ = PyramidGraph{};  // not half of a new graph over the old one's arrays
    throw;
  }
  return graph_;
}

}  // namespace pagor
