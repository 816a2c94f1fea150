#pragma once
/// \file pyramid_graph.hpp
/// The pyramid of consistency graphs. Vertices are correspondences; (i, j) is an edge at level l
/// when their TRIM is at most epsilon_l. Consistency at epsilon_l implies consistency at every
/// larger epsilon, so all levels are built in one pass and stored once, sparsely: each edge keeps
/// the lowest level it belongs to (and its TRIM, for Gaussian weights).

#include <cstdint>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// All levels of the pyramid in one symmetric CSR adjacency.
struct PyramidGraph {
  int vertices = 0;                ///< number of correspondences
  std::vector<double> thresholds;  ///< epsilon per level, increasing
  AffinityKind affinity = AffinityKind::binary;
  double sigma_ratio = 0.5;  ///< gaussian: sigma = sigma_ratio * epsilon_l

  std::vector<std::int64_t> offsets;        ///< vertex v's edges are [offsets[v], offsets[v+1])
  std::vector<int> neighbors;               ///< other end of each directed edge
  std::vector<std::uint8_t> level;          ///< lowest level at which the edge exists
  std::vector<float> trim;                  ///< TRIM value of the edge
  std::vector<std::size_t> edges_at_level;  ///< undirected edges present at each level
  double time_ms = 0.0;                     ///< construction wall time [ms]

  int levels() const { return static_cast<int>(thresholds.size()); }
  /// Affinity of directed edge e at level l (0 if the edge is absent at that level).
  double weight(std::size_t e, int l) const;
  /// Whether u and v are adjacent at level l (binary search in u's sorted neighbours).
  bool adjacent(int u, int v, int l) const;
  /// Vertices of level l with at least one edge.
  std::size_t active_vertices(int l) const;
};

/// Builds all levels in one pass over the pairs. Pairs sharing a source or a target landmark, and
/// pairs whose landmarks are closer than `min_length` on either side, are never consistent.
/// `threads` > 1 splits the pass over that many threads (same result).
PyramidGraph build_pyramid_graph(const std::vector<Correspondence>& correspondences,
                                 const GraphParams& params, int threads = 1);

}  // namespace pagor
