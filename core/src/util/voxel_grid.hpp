#pragma once
/// \file voxel_grid.hpp
/// Voxel downsampling that can remember which voxel every input point fell into, and fixed-radius
/// neighbour searches over points sorted into the cells of a grid.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace pagor {

/// Result of voxel downsampling.
struct VoxelDownsample {
  std::vector<Eigen::Vector3f>
      points;                 ///< one point per occupied voxel: the mean of its points [m]
  std::vector<int> counts;    ///< input points per voxel
  std::vector<int> voxel_of;  ///< per input point (or subset entry): its voxel; may be empty
};

/// Downsamples `points` (or only `points[subset[i]]` when `subset` is given) on a grid of
/// `voxel_size` [m]. Voxels come out in order of first appearance, so the result is deterministic.
/// A voxel size <= 0 keeps every point as its own voxel. Voxels are cells of the global lattice
/// (multiples of `voxel_size`), keyed relative to the cloud's lowest cell, so a cloud far from the
/// origin (georeferenced) is binned as finely as one near it and far-apart points never merge.
/// Throws InputError when a lattice index would exceed 2^52 or a coordinate is not finite.
/// `voxel_of` is left empty when `with_voxel_of` is false (a table as long as the input).
VoxelDownsample voxel_downsample(const std::vector<Eigen::Vector3f>& points, double voxel_size,
                                 const std::vector<int>* subset = nullptr,
                                 bool with_voxel_of = true);

/// Fixed-radius neighbour search: the points sorted into the cells of a grid at least as coarse as
/// the search radius, so a search looks at the 27 cells around the query (what a kd-tree's radius
/// search does with a tree walk). Cells are counted from the cloud's lowest corner.
class RadiusGrid {
 public:
  /// Sorts `points` into cells of `cell` [m] (> 0); the cell grows when the cloud is more than
  /// 2^20 cells wide, which keeps every search correct and only scans more points. Throws
  /// InputError for a non-finite coordinate.
  RadiusGrid(const std::vector<Eigen::Vector3f>& points, double cell);

  /// The points strictly closer than `radius` [m] (at most the cell) to `q`, appended to `index`
  /// (input indices) and `distance_sq` [m^2], in no particular order; a point of the input
  /// finds itself at distance 0.
  void within(const Eigen::Vector3f& q, float radius, std::vector<int>& index,
              std::vector<float>& distance_sq) const;

  /// The point nearest to `q` strictly closer than `radius` [m] (at most the cell), skipping the
  /// input point `exclude`: its input index and squared distance, or -1 and radius^2.
  std::pair<int, float> nearest(const Eigen::Vector3f& q, float radius, int exclude = -1) const;

  /// Whether some point is strictly closer than `radius` [m] (at most the cell) to `q`: the
  /// search stops at the first it finds.
  bool any_within(const Eigen::Vector3f& q, float radius) const;

  /// Cell size actually used [m].
  float cell() const { return cell_; }

  /// Cells holding at least one point.
  std::size_t cell_count() const { return start_.empty() ? 0 : start_.size() - 1; }

  /// Calls f(i, j, d2) once for every pair of input points i != j strictly closer than `radius`
  /// [m] (at most the cell), with their squared distance, in no particular order: each cell is
  /// paired with itself and its 13 neighbours that come after it, so no pair is looked at twice.
  template <class F>
  void for_each_pair_within(float radius, F&& f) const {
    const float r2 = radius * radius;
    const auto pair_cells = [&](int a, int b) {
      const int a_end = start_[static_cast<std::size_t>(a) + 1];
      const int b_end = start_[static_cast<std::size_t>(b) + 1];
      for (int i = start_[static_cast<std::size_t>(a)]; i < a_end; ++i) {
        const Eigen::Vector3f& p = sorted_[static_cast<std::size_t>(i)];
        for (int j = a == b ? i + 1 : start_[static_cast<std::size_t>(b)]; j < b_end; ++j) {
          const float d2 = (sorted_[static_cast<std::size_t>(j)] - p).squaredNorm();
          if (d2 < r2)
            f(index_[static_cast<std::size_t>(i)], index_[static_cast<std::size_t>(j)], d2);
        }
      }
    };
    // The 13 offsets after (0, 0, 0) in lexicographic order.
    static constexpr int kForward[13][3] = {
        {0, 0, 1},  {0, 1, -1}, {0, 1, 0}, {0, 1, 1},  {1, -1, -1}, {1, -1, 0}, {1, -1, 1},
        {1, 0, -1}, {1, 0, 0},  {1, 0, 1}, {1, 1, -1}, {1, 1, 0},   {1, 1, 1}};
    const auto each_cell = [&](const Cell& c, int cell) {  // (all coordinates >= 1)
      pair_cells(cell, cell);
      for (const auto& o : kForward) {
        const int other = number_of({c[0] + static_cast<std::uint64_t>(o[0]),
                                     c[1] + static_cast<std::uint64_t>(o[1]),
                                     c[2] + static_cast<std::uint64_t>(o[2])});
        if (other >= 0) pair_cells(cell, other);
      }
    };
    if (dense()) {
      int cell = 0;
      for (std::size_t w = 0; w < occupancy_.size(); ++w)
        for (std::uint64_t bits = occupancy_[w]; bits; bits &= bits - 1) {
          const std::uint64_t b = w * 64 + static_cast<std::uint64_t>(__builtin_ctzll(bits));
          each_cell({b / (dims_[1] * dims_[2]), (b / dims_[2]) % dims_[1], b % dims_[2]}, cell++);
        }
    } else {
      for (std::size_t s = 0; s < slots_.size(); ++s)
        if (slots_[s] != kEmptySlot) each_cell(unpack(slots_[s]), slot_cell_[s]);
    }
  }

  /// True when cells are found through a bit per cell of the cloud's box (with a cell of margin
  /// on every side) rather than the hash table: a box of at most 256 cells per point, plus 4096.
  bool dense() const { return !occupancy_.empty(); }

 private:
  // A cell: its index along each axis, counted from 1 at the cloud's lowest corner (so that the
  // neighbours of the lowest cell are cells too). The hash table keys a cell by its three indices
  // packed in 21 bits each; the dense box numbers its bits x-major.
  using Cell = std::array<std::uint64_t, 3>;
  Cell cell_of(const Eigen::Vector3f& p) const;  // (queries off the grid clamped to it)
  static std::uint64_t pack(const Cell& c) { return (c[0] << 42) | (c[1] << 21) | c[2]; }
  static Cell unpack(std::uint64_t key) {
    constexpr std::uint64_t kAxis = (std::uint64_t(1) << 21) - 1;
    return {key >> 42, (key >> 21) & kAxis, key & kAxis};
  }
  std::uint64_t bit_of(const Cell& c) const { return (c[0] * dims_[1] + c[1]) * dims_[2] + c[2]; }
  int find(std::uint64_t key) const;  // cell number in the hash table, or -1
  // Cell number of cell c, or -1 when it holds no point (or lies off the dense box).
  int number_of(const Cell& c) const {
    if (!dense()) return find(pack(c));
    if (c[0] >= dims_[0] || c[1] >= dims_[1] || c[2] >= dims_[2] || !has(bit_of(c))) return -1;
    return rank(bit_of(c));
  }
  // Cell number of bit `b` of the dense box (a set bit): the set bits before it.
  int rank(std::uint64_t b) const {
    const std::uint64_t below = occupancy_[b >> 6] & ((std::uint64_t(1) << (b & 63)) - 1);
    return static_cast<int>(rank_[b >> 6]) + popcount(below);
  }
  // Set bits of x, inline (without a popcnt instruction the builtin is a library call).
  static int popcount(std::uint64_t x) {
    x -= (x >> 1) & 0x5555555555555555ull;
    x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
    x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Full;
    return static_cast<int>((x * 0x0101010101010101ull) >> 56);
  }
  bool has(std::uint64_t b) const { return (occupancy_[b >> 6] >> (b & 63)) & 1; }
  // Bits b, b + 1, b + 2 of the dense box as the low three bits (b within it; bits past its end
  // read as zero).
  unsigned three_bits(std::uint64_t b) const {
    const std::uint64_t w = b >> 6, s = b & 63;
    std::uint64_t v = occupancy_[w] >> s;
    if (s > 61 && w + 1 < occupancy_.size()) v |= occupancy_[w + 1] << (64 - s);
    return static_cast<unsigned>(v & 7u);
  }

  // Calls f(begin, end) with the range of sorted_ of each occupied cell of the 27 around q whose
  // box is nearer to q than sqrt(bound()) (bound() may shrink as f finds points), q's own cell
  // first, then by x, y, z. A box's distance is taken a little short: points sit in their cell up
  // to rounding. Cells come from the bits of the dense box, else from the hash table; either way
  // the same cells in the same order, and a cell's points in input order.
  template <class Bound, class F>
  void for_cells_near(const Eigen::Vector3f& q, const Bound& bound, F&& f) const {
    if (sorted_.empty()) return;
    const Cell c = cell_of(q);
    const auto range = [&](int cell) {
      f(start_[static_cast<std::size_t>(cell)], start_[static_cast<std::size_t>(cell) + 1]);
    };
    // gap[a][k]: squared distance along axis a from q to the slab of the cell at offset k - 1,
    // relative to the lowest corner (as cells are assigned), less the slack.
    float gap[3][3];
    for (int a = 0; a < 3; ++a) {
      const float rel = q[a] - lo_[a];
      const float low = static_cast<float>(c[a] - 1) * cell_;  // cells count from 1
      const float below = std::max(0.0f, rel - low - slack_);
      const float above = std::max(0.0f, low + cell_ - rel - slack_);
      gap[a][0] = below * below;
      gap[a][1] = 0.0f;
      gap[a][2] = above * above;
    }
    if (dense()) {
      // Queries off the box (clamped to its edge or beyond) see only the axis offsets inside it.
      bool inside[3][3];
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k)
          inside[a][k] = c[a] + static_cast<std::uint64_t>(k) - 1 < dims_[a];
      const auto bit = [&](int x, int y, int z) {
        return bit_of({c[0] + static_cast<std::uint64_t>(x) - 1,
                       c[1] + static_cast<std::uint64_t>(y) - 1,
                       c[2] + static_cast<std::uint64_t>(z) - 1});
      };
      const unsigned z_inside =
          (inside[2][0] ? 1u : 0u) | (inside[2][1] ? 2u : 0u) | (inside[2][2] ? 4u : 0u);
      if (inside[0][1] && inside[1][1] && inside[2][1] && has(bit(1, 1, 1)))
        range(rank(bit(1, 1, 1)));
      for (int x = 0; x < 3 && z_inside; ++x) {
        if (!inside[0][x]) continue;
        for (int y = 0; y < 3; ++y) {
          const float gxy = gap[0][x] + gap[1][y];
          if (!inside[1][y] || gxy >= bound()) continue;
          // The column's three cells are consecutive bits: the occupied ones at once.
          const std::uint64_t b0 = bit(x, y, 0);
          unsigned occupied = three_bits(b0) & z_inside;
          if (x == 1 && y == 1) occupied &= ~2u;  // the own cell came first
          for (int z = 0; occupied; ++z, occupied >>= 1)
            if ((occupied & 1u) && gxy + gap[2][z] < bound())
              range(rank(b0 + static_cast<std::uint64_t>(z)));
        }
      }
      return;
    }
    const auto visit = [&](const Cell& at) {
      const int cell = find(pack(at));
      if (cell >= 0) range(cell);
    };
    visit(c);
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y) {
        const float gxy = gap[0][x] + gap[1][y];
        if (gxy >= bound()) continue;
        for (int z = 0; z < 3; ++z)
          if (!(x == 1 && y == 1 && z == 1) && gxy + gap[2][z] < bound())
            visit({c[0] + static_cast<std::uint64_t>(x) - 1,
                   c[1] + static_cast<std::uint64_t>(y) - 1,
                   c[2] + static_cast<std::uint64_t>(z) - 1});
      }
  }

  float cell_ = 1.0f;
  // How far a point may sit outside its cell's box by rounding [m]: a cell index is computed to
  // a few float ulps of itself, so this grows with the number of cells across the cloud.
  float slack_ = 1e-4f;
  Eigen::Vector3f lo_ = Eigen::Vector3f::Zero();
  std::vector<Eigen::Vector3f> sorted_;  // the points, cell by cell
  std::vector<int> index_;               // input index of sorted_[i]
  std::vector<int> start_;               // cell c holds sorted_[start_[c], start_[c + 1])
  // Dense box: a bit per cell (cell numbers from 0 on each axis, one cell of margin around the
  // points), and the set bits before each word; cells numbered in bit order.
  std::vector<std::uint64_t> occupancy_;
  std::vector<std::uint32_t> rank_;
  std::uint64_t dims_[3] = {0, 0, 0};
  // Otherwise an open-addressing table of cell keys, cells numbered in order of first appearance.
  static constexpr std::uint64_t kEmptySlot = ~std::uint64_t(0);  // (keys use 63 bits)
  std::vector<std::uint64_t> slots_;
  std::vector<int> slot_cell_;  // the cell of each slot
  std::uint64_t mask_ = 0;
};

}  // namespace pagor
