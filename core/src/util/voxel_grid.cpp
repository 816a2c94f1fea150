#include "util/voxel_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

#include "pagor/errors.hpp"

namespace pagor {
namespace {

// Open-addressing tables of packed cell keys (voxel downsampling and RadiusGrid): an empty slot,
// and the slot a key's probe starts from.
constexpr std::uint64_t kEmpty = ~std::uint64_t(0);  // packed keys use 63 bits
constexpr float kMaxCells = 1048576.0f;              // 2^20 cells per axis, keys of 3 x 21 bits
// A RadiusGrid's box up to this many cells per point is dense (a bit per cell: 32 bytes per
// point at most).
constexpr std::uint64_t kDenseCellsPerPoint = 256;

std::uint64_t hash_key(std::uint64_t k) {
  k ^= k >> 31;
  k *= 0x9E3779B97F4A7C15ull;
  return k ^ (k >> 29);
}

// The slot of `key` in a table of keys (linear probing), or the empty slot where it would go.
std::size_t probe(const std::vector<std::uint64_t>& keys, std::size_t mask, std::uint64_t key) {
  std::size_t s = hash_key(key) & mask;
  while (keys[s] != kEmpty && keys[s] != key) s = (s + 1) & mask;
  return s;
}

// The bounding box of point(0 .. n-1) (n >= 1); false when a coordinate is not finite (the min
// and max alone pass a NaN over).
template <class Point>
bool bounding_box(std::size_t n, const Point& point, Eigen::Vector3f& lo, Eigen::Vector3f& hi) {
  lo = hi = point(0);
  bool finite = true;
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(point(i));
    hi = hi.cwiseMax(point(i));
    finite = finite && point(i).allFinite();
  }
  return finite;
}

// A point's voxel is floor(coordinate / voxel size) per axis on the global lattice, computed in
// float as always, but keyed relative to the lowest voxel of the points' bounding box: up to 2^21
// voxels per axis the three relative indices are packed into one 63-bit key, wider clouds (a
// georeferenced map, or a scan 300 km from the origin with a fine grid) use a key of three 64-bit
// integers, so far-apart points never share a key. Lattice indices beyond 2^52 (where the
// conversion would lose voxels or overflow) are rejected.
constexpr double kPackedAxis = 2097152.0;         // 2^21
constexpr double kMaxIndex = 4503599627370496.0;  // 2^52

struct WideKey {
  std::int64_t x, y, z;
  bool operator==(const WideKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct WideHash {
  std::size_t operator()(const WideKey& k) const {
    std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(k.y) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(k.z) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

template <class Key, class Hash, class Point, class MakeKey>
void bin(std::size_t n, const Point& point, const MakeKey& make_key, VoxelDownsample& out) {
  std::unordered_map<Key, int, Hash> index;
  index.reserve(n / 2 + 16);
  std::vector<Eigen::Vector3d> sums;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [it, inserted] = index.emplace(make_key(point(i)), static_cast<int>(sums.size()));
    if (inserted) {
      sums.emplace_back(Eigen::Vector3d::Zero());
      out.counts.push_back(0);
    }
    sums[static_cast<std::size_t>(it->second)] += point(i).template cast<double>();
    ++out.counts[static_cast<std::size_t>(it->second)];
    if (!out.voxel_of.empty()) out.voxel_of[i] = it->second;
  }
  out.points.resize(sums.size());
  for (std::size_t v = 0; v < sums.size(); ++v)
    out.points[v] = (sums[v] / out.counts[v]).cast<float>();
}

// The same for packed keys, on an open-addressing table (linear probing) instead of a node-based
// map: voxels still numbered in order of first appearance, so the output is the map's exactly.
// The table starts small and doubles at half load: sized for every point at once it would cost
// more in fresh pages (a page fault each) than the probing saves.
template <class Point, class MakeKey>
void bin_packed(std::size_t n, const Point& point, const MakeKey& make_key, VoxelDownsample& out) {
  std::size_t mask = 1023;
  std::vector<std::uint64_t> keys(mask + 1, kEmpty);
  std::vector<int> voxel(mask + 1);
  std::vector<Eigen::Vector3d> sums;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t key = make_key(point(i));
    std::size_t s = probe(keys, mask, key);
    if (keys[s] == kEmpty) {
      if (2 * (sums.size() + 1) > mask + 1) {  // grow, then find the key's new slot
        const std::vector<std::uint64_t> old_keys = std::move(keys);
        const std::vector<int> old_voxel = std::move(voxel);
        mask = 2 * mask + 1;
        keys.assign(mask + 1, kEmpty);
        voxel.assign(mask + 1, 0);
        for (std::size_t o = 0; o < old_keys.size(); ++o) {
          if (old_keys[o] == kEmpty) continue;
          const std::size_t t = probe(keys, mask, old_keys[o]);
          keys[t] = old_keys[o];
          voxel[t] = old_voxel[o];
        }
        s = probe(keys, mask, key);
      }
      keys[s] = key;
      voxel[s] = static_cast<int>(sums.size());
      sums.emplace_back(Eigen::Vector3d::Zero());
      out.counts.push_back(0);
    }
    const int v = voxel[s];
    sums[static_cast<std::size_t>(v)] += point(i).template cast<double>();
    ++out.counts[static_cast<std::size_t>(v)];
    if (!out.voxel_of.empty()) out.voxel_of[i] = v;
  }
  out.points.resize(sums.size());
  for (std::size_t v = 0; v < sums.size(); ++v)
    out.points[v] = (sums[v] / out.counts[v]).cast<float>();
}

}  // namespace

VoxelDownsample voxel_downsample(const std::vector<Eigen::Vector3f>& points, double voxel_size,
                                 const std::vector<int>* subset, bool with_voxel_of) {
  const std::size_t n = subset ? subset->size() : points.size();
  const auto point = [&](std::size_t i) -> const Eigen::Vector3f& {
    return points[subset ? static_cast<std::size_t>((*subset)[i]) : i];
  };
  VoxelDownsample out;
  if (with_voxel_of) out.voxel_of.resize(n);
  if (voxel_size <= 0 || n == 0) {
    out.points.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      out.points.push_back(point(i));
      out.counts.push_back(1);
      if (with_voxel_of) out.voxel_of[i] = static_cast<int>(i);
    }
    return out;
  }
  Eigen::Vector3f lo, hi;
  const bool finite = bounding_box(n, point, lo, hi);
  const float inv = static_cast<float>(1.0 / voxel_size);
  const double reach =
      std::max(lo.cast<double>().cwiseAbs().maxCoeff(), hi.cast<double>().cwiseAbs().maxCoeff()) *
      static_cast<double>(inv);
  if (!finite || !(reach < kMaxIndex))
    throw InputError("voxel size " + std::to_string(voxel_size) + " m for coordinates up to " +
                     std::to_string(reach * voxel_size) +
                     " m: voxel indices beyond 2^52 (or a non-finite coordinate)");
  // floor(v * inv) as an integer: truncation, one down below zero (|v * inv| < 2^52 here; from
  // 2^23 on a float has no fraction and truncation is exact).
  const auto index = [inv](float v) {
    const float x = v * inv;
    const auto t = static_cast<std::int64_t>(x);
    return t - (x < static_cast<float>(t) ? 1 : 0);
  };
  const std::int64_t base[3] = {index(lo.x()), index(lo.y()), index(lo.z())};
  const std::int64_t span =
      std::max({index(hi.x()) - base[0], index(hi.y()) - base[1], index(hi.z()) - base[2]});
  const auto cell = [&](const Eigen::Vector3f& p, int axis) { return index(p[axis]) - base[axis]; };
  if (static_cast<double>(span) < kPackedAxis) {
    const auto key = [&](const Eigen::Vector3f& p) {
      return (static_cast<std::uint64_t>(cell(p, 0)) << 42) |
             (static_cast<std::uint64_t>(cell(p, 1)) << 21) |
             static_cast<std::uint64_t>(cell(p, 2));
    };
    bin_packed(n, point, key, out);
  } else {
    const auto key = [&](const Eigen::Vector3f& p) {
      return WideKey{cell(p, 0), cell(p, 1), cell(p, 2)};
    };
    bin<WideKey, WideHash>(n, point, key, out);
  }
  return out;
}

RadiusGrid::Cell RadiusGrid::cell_of(const Eigen::Vector3f& p) const {
  const auto axis = [&](int a) {
    // floor, with queries off the grid clamped (truncation is floor once clamped to >= 0)
    const float c = (p[a] - lo_[a]) / cell_;
    return static_cast<std::uint64_t>(std::min(std::max(0.0f, c), kMaxCells + 1.0f)) + 1;
  };
  return {axis(0), axis(1), axis(2)};
}

int RadiusGrid::find(std::uint64_t key) const {
  const std::size_t s = probe(slots_, mask_, key);
  return slots_[s] == key ? slot_cell_[s] : -1;
}

RadiusGrid::RadiusGrid(const std::vector<Eigen::Vector3f>& points, double cell)
    : cell_(static_cast<float>(cell)) {
  if (!(cell > 0)) throw InputError("radius grid: cell size must be > 0");
  const std::size_t n = points.size();
  if (n == 0) return;
  const auto point = [&](std::size_t i) -> const Eigen::Vector3f& { return points[i]; };
  Eigen::Vector3f hi;
  if (!bounding_box(n, point, lo_, hi)) throw InputError("radius grid: a coordinate is not finite");
  cell_ = std::max(cell_, (hi - lo_).maxCoeff() / kMaxCells);
  const float across = (hi - lo_).maxCoeff() / cell_ + 2.0f;  // cells across the cloud
  slack_ = cell_ * std::max(1e-4f, 8.0f * std::numeric_limits<float>::epsilon() * across);
  std::vector<int> number(n);  // each point's cell number
  // A box of at most kDenseCellsPerPoint cells per point gets a bit per cell (with a cell of
  // margin on every side, as searches look one cell beyond a point), cells numbered in bit order;
  // a larger (sparse or elongated) one the hash table, cells numbered in order of first
  // appearance. Then the points are scattered cell by cell (a counting sort: linear in the
  // points, which keeps input order within a cell).
  std::uint64_t bits = 1;
  for (int a = 0; a < 3; ++a) {
    dims_[a] = static_cast<std::uint64_t>(std::floor((hi[a] - lo_[a]) / cell_)) + 3;
    bits *= dims_[a];
  }
  if (bits <= kDenseCellsPerPoint * n + 4096) {
    occupancy_.assign((bits + 63) / 64, 0);
    std::vector<std::uint64_t> bit_at(n);  // each point's bit
    for (std::size_t i = 0; i < n; ++i) {
      bit_at[i] = bit_of(cell_of(points[i]));
      occupancy_[bit_at[i] >> 6] |= std::uint64_t(1) << (bit_at[i] & 63);
    }
    rank_.resize(occupancy_.size());
    std::uint32_t cells = 0;
    for (std::size_t w = 0; w < occupancy_.size(); ++w) {
      rank_[w] = cells;
      cells += static_cast<std::uint32_t>(popcount(occupancy_[w]));
    }
    start_.assign(cells, 0);
    for (std::size_t i = 0; i < n; ++i) {
      number[i] = rank(bit_at[i]);
      ++start_[static_cast<std::size_t>(number[i])];
    }
  } else {
    std::size_t capacity = 16;
    while (capacity < 2 * n) capacity *= 2;
    mask_ = capacity - 1;
    slots_.assign(capacity, kEmpty);
    slot_cell_.assign(capacity, -1);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t key = pack(cell_of(points[i]));
      const std::size_t s = probe(slots_, mask_, key);
      if (slots_[s] == kEmpty) {
        slots_[s] = key;
        slot_cell_[s] = static_cast<int>(start_.size());
        start_.push_back(0);
      }
      number[i] = slot_cell_[s];
      ++start_[static_cast<std::size_t>(number[i])];
    }
  }
  int total = 0;  // counts -> starts
  for (int& c : start_) {
    const int count = c;
    c = total;
    total += count;
  }
  start_.push_back(total);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  sorted_.resize(n);
  index_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto at = static_cast<std::size_t>(fill[static_cast<std::size_t>(number[i])]++);
    sorted_[at] = points[i];
    index_[at] = static_cast<int>(i);
  }
}

std::pair<int, float> RadiusGrid::nearest(const Eigen::Vector3f& q, float radius,
                                          int exclude) const {
  std::pair<int, float> best{-1, radius * radius};
  for_cells_near(
      q, [&] { return best.second; },
      [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
          const float d2 = (sorted_[static_cast<std::size_t>(i)] - q).squaredNorm();
          if (d2 < best.second && index_[static_cast<std::size_t>(i)] != exclude)
            best = {index_[static_cast<std::size_t>(i)], d2};
        }
      });
  return best;
}

bool RadiusGrid::any_within(const Eigen::Vector3f& q, float radius) const {
  const float r2 = radius * radius;
  bool found = false;
  // Once found, a bound of 0 skips every cell left (their gaps are >= 0).
  for_cells_near(
      q, [&] { return found ? 0.0f : r2; },
      [&](int begin, int end) {
        for (int i = begin; i < end && !found; ++i)
          found = (sorted_[static_cast<std::size_t>(i)] - q).squaredNorm() < r2;
      });
  return found;
}

void RadiusGrid::within(const Eigen::Vector3f& q, float radius, std::vector<int>& index,
                        std::vector<float>& distance_sq) const {
  const float r2 = radius * radius;
  for_cells_near(
      q, [r2] { return r2; },
      [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
          const float d2 = (sorted_[static_cast<std::size_t>(i)] - q).squaredNorm();
          if (d2 < r2) {
            index.push_back(index_[static_cast<std::size_t>(i)]);
            distance_sq.push_back(d2);
          }
        }
      });
}

}  // namespace pagor
