#pragma once
/// \file pyramid_graph.hpp
/// The pyramid of consistency graphs. Vertices are correspondences; (i, j) is an edge at level l
/// when their TRIM is at most epsilon_l. Consistency at epsilon_l implies consistency at every
/// larger epsilon, so all levels are built in one pass and stored once, sparsely: each edge keeps
/// the lowest level it belongs to (and its TRIM, for Gaussian weights).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pagor/graph/trim.hpp"
#include "pagor/params.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// All levels of the pyramid in one symmetric CSR adjacency.
struct PyramidGraph {
  int vertices = 0;                ///< number of correspondences
  std::vector<double> thresholds;  ///< epsilon per level, increasing
  AffinityKind affinity = AffinityKind::binary;
  double sigma_ratio = 0.5;  ///< gaussian: sigma = sigma_ratio * epsilon_l

  std::vector<std::int64_t> offsets;  ///< vertex v's edges are [offsets[v], offsets[v+1])
  std::vector<int> neighbors;         ///< other end of each directed edge
  std::vector<std::uint8_t> level;    ///< lowest level at which the edge exists
  /// TRIM value of each edge, for the gaussian affinity's weights; empty under the binary
  /// affinity, which needs none (a dense graph's megabytes)
  std::vector<float> trim;
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

/// Builds pyramid graphs one after another in the same storage, for a caller that registers pair
/// after pair (a loop-closing node; `Pipeline` keeps one). The graph's arrays and the edge pass's
/// scratch (the megabytes of a build) are kept between builds, so a build no larger than an
/// earlier one reuses them instead of faulting fresh memory in: on m = 5000 correspondences,
/// faulting in and zeroing the ~90 MiB a build needs was a third of its time. The storage of the
/// largest build is kept until the builder dies. The graphs are those build_pyramid_graph()
/// gives. A copy copies the graph, not the scratch; a moved-from builder holds an empty graph.
class PyramidGraphBuilder {
 public:
  PyramidGraphBuilder();
  ~PyramidGraphBuilder();
  PyramidGraphBuilder(const PyramidGraphBuilder& other);
  PyramidGraphBuilder& operator=(const PyramidGraphBuilder& other);
  PyramidGraphBuilder(PyramidGraphBuilder&&) noexcept;
  PyramidGraphBuilder& operator=(PyramidGraphBuilder&&) noexcept;

  /// Rebuilds graph() from these correspondences; references to graph() stay valid and see the
  /// new graph. If it throws (out of memory, no thread), graph() is left empty.
  const PyramidGraph& build(const std::vector<Correspondence>& correspondences,
                            const GraphParams& params, int threads = 1);
  /// The last graph built (empty before the first build).
  const PyramidGraph& graph() const { return graph_; }

 private:
  struct Scratch;
  std::unique_ptr<Scratch> scratch_;
  PyramidGraph graph_;
};

}  // namespace pagor
