#include "verify/ambiguity.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>

#include "util/parallel.hpp"

namespace pagor {
namespace {

// Correlation peaks scored by E, and of those the best refined locally: each costs one search of
// the counted points per step (a scene repeating along two axes, turned or not, has at most four
// look-alikes within the range worth a look; beyond them the peaks are echoes of the same).
constexpr std::size_t kPeaksScored = 6, kPeaksRefined = 2;
// Points added to both sides of the ratio of disagreeing points: with nothing that tells two poses
// apart (a corridor a period on, a street sliding along itself) the ratio is 1, ambiguous, and a
// handful of points cannot make it 0 or 10. Ten points of the verification's 0.5 m voxels are
// 2.5 m^2 of surface, the end of a car.
constexpr double kPriorPoints = 10.0;

// Cells a grid holds at most: 16 MB a grid of flags.
constexpr double kMaxGridCells = 1 << 24;

// `cell` [m], coarsened where a grid over `span` with `pad` more cells along each axis would pass
// kMaxGridCells (a tiny mu, or distinct distance, against a wide target). At most 2^20 cells
// across first: a cell that rounds to 0, or divides the span to infinity, would leave the loop
// nothing finite to work on.
template <int N>
double fitted_cell(double cell, const Eigen::Matrix<double, N, 1>& span, double pad) {
  cell = std::max({cell, span.maxCoeff() / 1048576.0, 1e-6});
  for (;;) {
    const double cells = ((span / cell).array().floor() + pad).prod();
    if (cells <= kMaxGridCells) return cell;
    const double excess = cells / kMaxGridCells;
    cell *= std::max(1.01, N == 3 ? std::cbrt(excess) : std::sqrt(excess));
  }
}

// The target structure's horizontal principal axes (columns, major first) and, in that frame
// (u, v, z), the grid's lower corner.
struct Frame {
  Eigen::Matrix2d axes = Eigen::Matrix2d::Identity();
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  Eigen::Vector3d to_frame(const Eigen::Vector3d& p) const {
    const Eigen::Vector2d uv = axes.transpose() * p.head<2>();
    return {uv.x(), uv.y(), p.z()};
  }
};

// The angle [rad, in [0, pi/2)] of the two perpendicular horizontal directions along which
// `points` project most sharply (the sum of squared counts of their projections on both, in bins
// of `cell`): the directions walls, rows of columns and facades run along. The principal axes of
// the points' spread turn with where the structure happens to be: a car park's plan, fuller on one
// side, had them 4-6 degrees off its rows of columns, which put a repetition a column spacing on
// up to a metre across the line searched, where nothing agreed (seed 17, scan 75: a pose a column
// spacing off accepted; seed 7, scan 18).
double sharpest_angle(const std::vector<Eigen::Vector2d>& points, double cell) {
  const auto score = [&](double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    std::unordered_map<long long, int> u, v;
    u.reserve(points.size());
    v.reserve(points.size());
    for (const Eigen::Vector2d& p : points) {
      ++u[static_cast<long long>(std::floor((c * p.x() + s * p.y()) / cell))];
      ++v[static_cast<long long>(std::floor((c * p.y() - s * p.x()) / cell))];
    }
    double sum = 0;
    for (const auto& [bin, n] : u) sum += static_cast<double>(n) * n;
    for (const auto& [bin, n] : v) sum += static_cast<double>(n) * n;
    return sum;
  };
  constexpr double kDeg = 3.14159265358979323846 / 180;
  double best = 0, best_score = -1;
  for (int d = 0; d < 90; ++d)  // whole degrees, then tenths around the best
    if (const double v = score(d * kDeg); v > best_score) best_score = v, best = d * kDeg;
  const double coarse = best;
  for (int t = -9; t <= 9; ++t)
    if (const double v = score(coarse + t * 0.1 * kDeg); v > best_score)
      best_score = v, best = coarse + t * 0.1 * kDeg;
  return best < 0 ? best + 90 * kDeg : best;  // the same pair of axes
}

// Occupied cells of the target structure on a grid of `cell` [m] in its principal frame.
class Occupancy {
 public:
  // `drawn`: the target is a plan (drawn along its walls): the axes are those it runs along
  // (sharpest_angle); otherwise the principal axes of its spread (a street scan's run along the
  // street: on the shared scans and the self-similar scenes the walls' directions lost a right
  // pose of semreg-dev and let a facade's wrong one through).
  Occupancy(const std::vector<Eigen::Vector3f>& points, const std::vector<char>& counts,
            double cell, bool drawn)
      : cell_(cell) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    std::size_t n = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (counts[i]) mean += points[i].head<2>().cast<double>(), ++n;
    if (n == 0) return;
    mean /= static_cast<double>(n);
    for (std::size_t i = 0; i < points.size(); ++i)
      if (counts[i]) {
        const Eigen::Vector2d d = points[i].head<2>().cast<double>() - mean;
        cov += d * d.transpose();
      }
    if (!drawn) {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
      frame_.axes.col(0) = eig.eigenvectors().col(1);  // eigenvalues ascend: the major axis last
      frame_.axes.col(1) = eig.eigenvectors().col(0);
    } else {
      // The axes the structure runs along (sharpest_angle), on its cells (each once), the one of
      // the larger spread first. Keys of at most 2^20 cells from the mean each way (a tiny cell is
      // coarsened for this).
      double radius = 0;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (counts[i])
          radius =
              std::max(radius, (points[i].head<2>().cast<double>() - mean).cwiseAbs().maxCoeff());
      const double key_cell = std::max({cell_, radius / 1048576.0, 1e-9});
      std::unordered_set<long long> seen;
      std::vector<Eigen::Vector2d> cells;
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (!counts[i]) continue;
        const Eigen::Vector2d p = points[i].head<2>().cast<double>() - mean;
        const auto k = [&](double v) { return static_cast<long long>(std::floor(v / key_cell)); };
        if (seen.insert(k(p.x()) * 4194304LL + k(p.y())).second) cells.push_back(p);
      }
      const double angle = sharpest_angle(cells, cell_);
      const Eigen::Vector2d a(std::cos(angle), std::sin(angle)), b(-a.y(), a.x());
      const bool a_major = a.dot(cov * a) >= b.dot(cov * b);
      frame_.axes.col(0) = a_major ? a : b;
      frame_.axes.col(1) = a_major ? b : a;
    }
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (counts[i]) {
        const Eigen::Vector3d f = frame_.to_frame(points[i].cast<double>());
        lo = lo.cwiseMin(f);
        hi = hi.cwiseMax(f);
      }
    frame_.lower = lo;
    middle_ = Eigen::Vector2d(lo.x() + hi.x(), lo.y() + hi.y()) / 2;
    // A grid too fine for the target is coarsened: the correlation then finds its peaks there.
    const Eigen::Vector3d span = hi - lo;
    cell_ = fitted_cell<3>(cell_, span, 1);
    for (int k = 0; k < 3; ++k) size_[k] = static_cast<int>(span[k] / cell_) + 1;
    occupied_.assign(static_cast<std::size_t>(size_[0]) * size_[1] * size_[2], 0);
    along_y_ = occupied_;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (counts[i]) {
        const Eigen::Vector3i k = key(points[i].cast<double>());
        occupied_[index(k)] = 1;
        along_y_[(static_cast<std::size_t>(k.z()) * size_[0] + k.x()) * size_[1] + k.y()] = 1;
      }
  }

  const Frame& frame() const { return frame_; }
  /// The middle of the structure's horizontal extent, in the target frame.
  Eigen::Vector2d centre() const { return frame_.axes * middle_; }
  double cell() const { return cell_; }
  double extent(int axis) const { return size_[axis] * cell_; }
  Eigen::Vector3i key(const Eigen::Vector3d& p) const {
    // Clamped: a point far off the grid (a wild pose) stays off it without overflowing an int.
    const Eigen::Vector3d f =
        ((frame_.to_frame(p) - frame_.lower) / cell_).array().floor().cwiseMax(-1e9).cwiseMin(1e9);
    return f.cast<int>();
  }
  int size(int axis) const { return size_[axis]; }
  /// Whether cell `k` holds target structure (false off the grid).
  bool occupied(const Eigen::Vector3i& k) const {
    for (int a = 0; a < 3; ++a)
      if (k[a] < 0 || k[a] >= size_[a]) return false;
    return occupied_[index(k)] != 0;
  }
  /// The cells along `axis` (0 or 1) through `k`, one flag each (size(axis) of them), or null
  /// when k's other two indices are off the grid.
  const char* row(int axis, const Eigen::Vector3i& k) const {
    const int other = 1 - axis;
    if (k[other] < 0 || k[other] >= size_[other] || k.z() < 0 || k.z() >= size_[2]) return nullptr;
    return axis == 0 ? &occupied_[index({0, k.y(), k.z()})]
                     : &along_y_[(static_cast<std::size_t>(k.z()) * size_[0] + k.x()) * size_[1]];
  }

 private:
  std::size_t index(const Eigen::Vector3i& k) const {
    return (static_cast<std::size_t>(k.z()) * size_[1] + k.y()) * size_[0] + k.x();
  }
  double cell_;
  Frame frame_;
  Eigen::Vector2d middle_ = Eigen::Vector2d::Zero();  // of the structure, in the frame (u, v)
  int size_[3] = {0, 0, 0};
  std::vector<char> occupied_;  // x fastest
  std::vector<char> along_y_;   // the same, y fastest
};

// A peak of a correlation profile: the pose it stands for and how many cells agree there.
struct Peak {
  Transform T = Transform::Identity();
  double agreement = 0.0;
  bool turned = false;
  int axis = 0;   // the axis it was found along
  int shift = 0;  // how many cells along it the pose it was found from moved
};

Transform moved(const Transform& T, const Eigen::Vector2d& shift) {
  Transform out = T;
  out.block<2, 1>(0, 3) += shift;
  return out;
}

// The occupied cells of the counted source points under T, each once.
std::vector<Eigen::Vector3i> source_cells(const Verifier& verifier, const std::vector<char>& counts,
                                          const Transform& T, const Occupancy& occ) {
  std::vector<Eigen::Vector3i> cells;
  const auto& src = verifier.source_points();
  for (std::size_t i = 0; i < src.size(); ++i)
    if (counts[i])
      cells.push_back(occ.key(T.block<3, 3>(0, 0) * src[i].cast<double>() + T.block<3, 1>(0, 3)));
  const auto less = [](const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(cells.begin(), cells.end(), less);
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

// A peak is found along one principal axis; the repetition it stands for may lie off that line
// (the axes of a car park's plan turned 4 degrees from its rows of columns put a peak 15.5 m on
// 1.1 m across the true pose, too far for the local search to see: nothing aligned on the way).
// Moves the peak's pose across its axis, within `reach` [m], to where the clouds' occupancy agrees
// best (the nearest such; the pose itself on a tie), then along it by up to two cells the same way.
// `cells`: source_cells of the pose the peak was found from (the peak's are those moved by its
// shift along its axis).
Transform centre_across(const std::vector<Eigen::Vector3i>& cells, const Peak& peak,
                        const Occupancy& occ, double reach) {
  Eigen::Vector3i base = Eigen::Vector3i::Zero();
  base[peak.axis] = peak.shift;
  const auto agreement = [&](const Eigen::Vector3i& d) {
    std::size_t n = 0;
    const Eigen::Vector3i o = base + d;
    for (const Eigen::Vector3i& c : cells) n += occ.occupied(c + o);
    return n;
  };
  // The best shift of at most `w` cells along `axis` from `from`, nearest first.
  const auto best_along = [&](int axis, int w, Eigen::Vector3i from) {
    std::size_t best = agreement(from);
    Eigen::Vector3i at = from;
    for (int k = 1; k <= w; ++k)
      for (int sign : {-1, 1}) {
        Eigen::Vector3i d = from;
        d[axis] += sign * k;
        const std::size_t n = agreement(d);
        if (n > best) best = n, at = d;
      }
    return at;
  };
  const int across = 1 - peak.axis;
  const int w = std::min(64, static_cast<int>(std::ceil(reach / occ.cell())));
  Eigen::Vector3i d = best_along(across, w, Eigen::Vector3i::Zero());
  d = best_along(peak.axis, 2, d);
  return moved(peak.T, occ.frame().axes * Eigen::Vector2d(d.x(), d.y()) * occ.cell());
}

// The correlation of the counted source points under `T` with the target's occupancy, for every
// shift along each principal axis within `range`, and its peaks: shifts that agree at least as
// well as every other within `separation` [m].
// `cells`: source_cells of T.
void profile_peaks(const std::vector<Eigen::Vector3i>& cells, const Transform& T,
                   const Occupancy& occ, double range, double separation, bool turned,
                   std::vector<Peak>& peaks) {
  const int w = std::max(1, static_cast<int>(std::ceil(separation / occ.cell())));
  for (int axis = 0; axis < 2; ++axis) {
    const int K = static_cast<int>(std::min(range, occ.extent(axis)) / occ.cell());
    // Per shift the raw agreement and the agreement per comparable cell (those the shift keeps
    // within the target's grid): the latter finds the peaks without the fall-off of a shrinking
    // overlap (walls that slide along themselves agree less at every step away).
    // Each cell adds its row of the target's occupancy to the shifts that keep it on the grid.
    std::vector<int> agree(static_cast<std::size_t>(2 * K + 1), 0);
    std::vector<int> comparable(static_cast<std::size_t>(2 * K + 2), 0);  // as differences
    std::size_t on_rows = 0;  // cells some shift along the axis brings onto the target's grid
    for (const Eigen::Vector3i& cell : cells) {
      const char* row = occ.row(axis, cell);
      const int x = cell[axis], lo = std::max(-K, -x), hi = std::min(K, occ.size(axis) - 1 - x);
      if (!row || lo > hi) continue;
      ++on_rows;
      int* out = agree.data() + K;
      for (int k = lo; k <= hi; ++k) out[k] += row[x + k];
      ++comparable[static_cast<std::size_t>(lo + K)];
      --comparable[static_cast<std::size_t>(hi + K + 1)];
    }
    std::vector<double> raw(static_cast<std::size_t>(2 * K + 1), 0.0), rate = raw;
    // Shifts that leave less than half of the cells comparable tell little. Where that leaves no
    // peak, the half is taken of the cells some shift along this axis brings onto the target's
    // grid at all: under a pose that puts most of the source beside the target (a wrong one, a
    // street's width off), no shift left half of all cells comparable, and the pose met no rival.
    const auto find = [&](double least) {
      const std::size_t before = peaks.size();
      for (int k = -K, open = 0; k <= K; ++k) {
        const auto at = static_cast<std::size_t>(k + K);
        open += comparable[at];
        raw[at] = agree[at];
        rate[at] = open > 0 && open >= least ? agree[at] / double(open) : 0.0;
      }
      for (int k = -K; k <= K; ++k) {
        const double v = rate[static_cast<std::size_t>(k + K)];
        bool peak = v > 0;
        for (int j = std::max(-K, k - w); peak && j <= std::min(K, k + w); ++j) {
          const double u = rate[static_cast<std::size_t>(j + K)];
          peak = j < k ? u < v : u <= v;
        }
        if (!peak) continue;
        const Eigen::Vector2d shift = occ.frame().axes.col(axis) * (k * occ.cell());
        peaks.push_back({moved(T, shift), raw[static_cast<std::size_t>(k + K)], turned, axis, k});
      }
      return peaks.size() > before;
    };
    if (!find(0.5 * static_cast<double>(cells.size())) && on_rows > 0 && on_rows < cells.size())
      find(0.5 * static_cast<double>(on_rows));
  }
}

// Where the target looked: the horizontal cells of `cell` [m] that hold a target point, gaps of a
// cell closed (a cell between two looked-at ones counts). Not widened beyond the last points: a
// source point just beyond the target's range is unaligned by the right pose and aligned by a pose
// that moves it inwards, which made right poses with objects look rivalled (1.4).
class Footprint {
 public:
  Footprint(const std::vector<Eigen::Vector3f>& target, double cell, bool everywhere)
      : cell_(cell), everywhere_(everywhere) {
    if (target.empty() || everywhere) return;
    Eigen::Vector2f lo = target[0].head<2>(), hi = lo;
    for (const auto& p : target) lo = lo.cwiseMin(p.head<2>()), hi = hi.cwiseMax(p.head<2>());
    const Eigen::Vector2d span = (hi - lo).cast<double>();
    cell_ = fitted_cell<2>(cell_, span, 3);
    lower_ = lo.cast<double>() - Eigen::Vector2d::Constant(cell_);
    nx_ = static_cast<int>(span.x() / cell_) + 3;
    ny_ = static_cast<int>(span.y() / cell_) + 3;
    std::vector<char> held(static_cast<std::size_t>(nx_) * ny_, 0);
    for (const auto& p : target) {
      const auto [x, y] = key(p.cast<double>());
      held[static_cast<std::size_t>(y) * nx_ + x] = 1;
    }
    looked_ = held;
    const auto at = [&](int x, int y) { return held[static_cast<std::size_t>(y) * nx_ + x] != 0; };
    for (int y = 1; y + 1 < ny_; ++y)
      for (int x = 1; x + 1 < nx_; ++x)
        if ((at(x - 1, y) && at(x + 1, y)) || (at(x, y - 1) && at(x, y + 1)))
          looked_[static_cast<std::size_t>(y) * nx_ + x] = 1;
  }
  bool covers(const Eigen::Vector3d& q) const {
    if (everywhere_) return true;
    const auto [x, y] = key(q);
    return x >= 0 && y >= 0 && x < nx_ && y < ny_ && looked_[static_cast<std::size_t>(y) * nx_ + x];
  }

 private:
  std::pair<int, int> key(const Eigen::Vector3d& q) const {
    const Eigen::Vector2d f =
        ((q.head<2>() - lower_) / cell_).array().floor().cwiseMax(-1e9).cwiseMin(1e9);
    return {static_cast<int>(f.x()), static_cast<int>(f.y())};
  }
  double cell_;
  bool everywhere_;
  Eigen::Vector2d lower_ = Eigen::Vector2d::Zero();
  int nx_ = 0, ny_ = 0;
  std::vector<char> looked_;
};

Eigen::Vector3d apply(const Transform& T, const Eigen::Vector3f& p) {
  return T.block<3, 3>(0, 0) * p.cast<double>() + T.block<3, 1>(0, 3);
}

// Scores an alternative against the selected pose by the points on which they disagree: those one
// aligns (within the inlier distance r) and the other clearly does not (beyond 2 r), among the
// counted points both put where the target looked. What both align (a wall sliding along itself,
// a row of pillars a period on) says nothing either way; counted in, a car in a corridor was 4 %
// of the evidence. The margin between r and 2 r keeps out points that only the voxel grid's phase
// moves across r (the refined pose fits the voxel centroids, an alternative does not). A point
// moved out of the target's view can be neither aligned nor refuted (moving a stretch of corridor
// further into view gains wall it did not earn).
class Comparison {
 public:
  explicit Comparison(const AmbiguityInput& in)
      : in_(in),
        // No finer than the inlier distance: finer cells leave holes between the target's
        // points, and a pose that moves the evidence into them looked unrivalled.
        footprint_(in.verifier->target_points(),
                   std::max(in.distinct.max_translation_error / 2, in.inlier_distance),
                   in.target_complete),
        r_(static_cast<float>(in.inlier_distance)) {
    d_sel_ = in.selected_distances ? *in.selected_distances
                                   : in.verifier->distances(in.T_selected, 2 * r_, *in.counts);
    const auto& src = in.verifier->source_points();
    seen_.assign(src.size(), 0);
    for (std::size_t i = 0; i < src.size(); ++i) {
      seen_[i] = (*in.counts)[i] && footprint_.covers(apply(in.T_selected, src[i]));
      aligned_ += seen_[i] && d_sel_[i] <= r_;
    }
    if (in.furniture) {
      const std::vector<float> d = in.verifier->distances(in.T_selected, r_, *in.furniture);
      on_sel_.assign(src.size(), 0);
      off_sel_.assign(src.size(), 0);
      for (std::size_t i = 0; i < src.size(); ++i) {
        if (!(*in.furniture)[i]) continue;
        (d[i] <= r_ ? on_sel_ : off_sel_)[i] = 1;
        on_sel_count_ += d[i] <= r_;
      }
    }
  }

  /// (points only `T` aligns + prior) / (points only the selected pose aligns + prior); 0 when
  /// `T` puts most of what the selected pose aligns where the target did not look.
  double ratio(const Transform& T) const {
    const Support s = support(T);
    return s.away ? 0.0 : s.ratio();
  }

  /// The points only `T` aligns and those only the selected pose aligns (above).
  struct Support {
    std::size_t only_alt = 0, only_sel = 0;
    bool away = false;  // T puts most of the evidence where the target did not look
    double ratio() const {
      return (static_cast<double>(only_alt) + kPriorPoints) /
             (static_cast<double>(only_sel) + kPriorPoints);
    }
  };
  Support support(const Transform& T) const {
    // Only the points that can tell the poses apart are searched: those the selected pose aligns
    // (does T leave them beyond 2 r?) and those it leaves beyond 2 r (does T align them?).
    const auto& src = in_.verifier->source_points();
    std::vector<char> aligned(src.size(), 0), unaligned(src.size(), 0);
    std::size_t judged = 0;
    for (std::size_t i = 0; i < src.size(); ++i) {
      if (!seen_[i] || (d_sel_[i] > r_ && d_sel_[i] <= 2 * r_)) continue;
      if (!footprint_.covers(apply(T, src[i]))) continue;
      aligned[i] = d_sel_[i] <= r_;
      unaligned[i] = !aligned[i];
      judged += aligned[i];
    }
    // A pose that puts most of the evidence where the target did not look is no competitor (in a
    // 30 m hall, a pose moved 17 m kept a handful of points, and matched them).
    if (2 * judged < aligned_) return {0, 0, true};
    std::size_t only_sel = judged - in_.verifier->count_within(T, 2 * r_, aligned);
    std::size_t only_alt = in_.verifier->count_within(T, r_, unaligned);
    // Furniture one pose puts on the target's structure and the other does not speaks for the
    // other.
    if (in_.furniture) {
      only_sel += in_.verifier->count_within(T, r_, off_sel_);
      only_alt += on_sel_count_ - in_.verifier->count_within(T, r_, on_sel_);
    }
    return {only_alt, only_sel, false};
  }

  /// The centre of what the selected pose aligns, in the target frame.
  Eigen::Vector2d aligned_centre() const {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    std::size_t n = 0;
    for (std::size_t i = 0; i < d_sel_.size(); ++i)
      if ((*in_.counts)[i] && d_sel_[i] <= r_)
        sum += apply(in_.T_selected, in_.verifier->source_points()[i]).head<2>(), ++n;
    return n ? Eigen::Vector2d(sum / static_cast<double>(n)) : in_.T_selected.block<2, 1>(0, 3);
  }

 private:
  const AmbiguityInput& in_;
  Footprint footprint_;
  float r_;
  std::vector<float> d_sel_;
  std::vector<char> on_sel_, off_sel_;  // furniture the selected pose puts on structure, or not
  std::size_t on_sel_count_ = 0;
  std::vector<char> seen_;   // counted, and put where the target looked by the selected pose
  std::size_t aligned_ = 0;  // of those, aligned by the selected pose
};

Transform half_turn(const Transform& T, const Eigen::Vector2d& centre) {
  Transform R = Transform::Identity();
  R.block<2, 2>(0, 0) = -Eigen::Matrix2d::Identity();
  R.block<2, 1>(0, 3) = 2 * centre;  // p -> centre - (p - centre)
  return R * T;
}

std::string describe(const Transform& alt, const Transform& selected, bool turned) {
  const Eigen::Vector2d d = alt.block<2, 1>(0, 3) - selected.block<2, 1>(0, 3);
  char buf[128];
  std::snprintf(buf, sizeof(buf), "%s %.1f m (x %+.1f, y %+.1f)",
                turned ? "the pose turned 180 deg and moved" : "a pose moved", d.norm(), d.x(),
                d.y());
  return buf;
}

// Moves T in the horizontal plane by steps of `step` [m] while its ratio improves; halves the step
// once.
Transform climb(const Comparison& cmp, Transform T, double& e, double step) {
  const Eigen::Vector2d dirs[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  // At most four moves a step size: the alternative is a peak of the correlation already, within
  // a cell of its best; on a plateau (a wall sliding along itself) it is not chased back. The way
  // back of the last move is not tried again: it scored less.
  for (int round = 0; round < 2; ++round, step /= 2)
    for (int moves = 0, better = 1, back = -1; better && moves < 4; ++moves) {
      better = 0;
      for (int d = 0; d < 4; ++d) {
        if (d == back) continue;
        const Transform next = moved(T, step * dirs[d]);
        const double en = cmp.ratio(next);
        if (en > e) {
          T = next, e = en, better = 1, back = d ^ 1;
          break;
        }
      }
    }
  return T;
}

}  // namespace

AcceptanceAlternative find_best_alternative(const AmbiguityInput& in,
                                            const std::vector<Transform>& candidates,
                                            const std::vector<std::string>& names) {
  AcceptanceAlternative best;
  // The correlation's grid: mu / 2, no finer than half the inlier distance (what aligns is
  // judged at that scale).
  const Occupancy occ(in.verifier->target_points(), *in.target_counts,
                      std::max(in.mu, in.inlier_distance) / 2, in.target_complete);
  const Comparison cmp(in);
  const auto distinct = [&](const Transform& T) {
    return !pose_error(T, in.T_selected, in.distinct).success;
  };
  const auto offer = [&](const Transform& T, double ratio, std::string description) {
    if (best.description.empty() || ratio > best.ratio) best = {T, std::move(description), ratio};
  };
  // The searches run as tasks over `threads` (a search of the points is too short to split; the
  // offers are made in the same order whatever the threads).
  const auto each = [&](std::size_t n, const auto& f) {
    parallel_ranges(in.threads, n, 1, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) f(i);
    });
  };
  std::vector<double> e(candidates.size(), 0.0);
  each(candidates.size(), [&](std::size_t i) {
    if (distinct(candidates[i])) e[i] = cmp.ratio(candidates[i]);
  });
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (distinct(candidates[i])) offer(candidates[i], e[i], names[i]);

  // Repetitions: correlation peaks of the pose and of its half turn.
  const double separation = in.distinct.max_translation_error;
  const Transform poses[2] = {in.T_selected, half_turn(in.T_selected, cmp.aligned_centre())};
  std::vector<Peak> found[2];
  std::vector<Eigen::Vector3i> cells[2];
  each(2, [&](std::size_t k) {
    cells[k] = source_cells(*in.verifier, *in.counts, poses[k], occ);
    profile_peaks(cells[k], poses[k], occ, in.search_range, separation, k == 1, found[k]);
  });
  std::vector<Peak> peaks = std::move(found[0]);
  peaks.insert(peaks.end(), found[1].begin(), found[1].end());
  peaks.erase(
      std::remove_if(peaks.begin(), peaks.end(), [&](const Peak& p) { return !distinct(p.T); }),
      peaks.end());
  std::sort(peaks.begin(), peaks.end(),
            [](const Peak& a, const Peak& b) { return a.agreement > b.agreement; });
  if (peaks.size() > kPeaksScored) peaks.resize(kPeaksScored);
  // A peak centred across its axis keeps whichever of the two rivals the selection more. Against
  // a plan every peak is (a peak off the true repetition by a metre across scores as if nothing
  // repeated there, and was passed over for climbing: car park seed 17); against a scan, whose
  // axes follow its spread, the two best (each centring costs a search of the points: on KITTI,
  // every peak added 1.2 ms to the acceptance's 13).
  const auto centre = [&](std::size_t i) {
    const Transform T =
        centre_across(cells[peaks[i].turned ? 1 : 0], peaks[i], occ, 2 * separation);
    if (T == peaks[i].T) return;
    if (const double c = cmp.ratio(T); c > e[i]) e[i] = c, peaks[i].T = T;
  };
  e.assign(peaks.size(), 0.0);
  std::vector<std::size_t> order(peaks.size());
  each(peaks.size(), [&](std::size_t i) {
    e[i] = cmp.ratio(peaks[i].T);
    if (in.target_complete) centre(i);
  });
  for (std::size_t i = 0; i < peaks.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return e[a] > e[b]; });
  if (!in.target_complete) {
    each(std::min(kPeaksRefined, order.size()), [&](std::size_t r) { centre(order[r]); });
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return e[a] > e[b]; });
  }
  // The best few moved to their own optimum: a peak is found on the occupancy's grid (mu / 2, or
  // coarser against a target too wide for it).
  std::vector<Transform> moved_to(peaks.size());
  for (std::size_t i = 0; i < peaks.size(); ++i) moved_to[i] = peaks[i].T;
  each(std::min(kPeaksRefined, order.size()), [&](std::size_t r) {
    const std::size_t i = order[r];
    moved_to[i] = climb(cmp, peaks[i].T, e[i], occ.cell() / 2);
  });
  for (std::size_t i : order)
    if (distinct(moved_to[i]))
      offer(moved_to[i], e[i], describe(moved_to[i], in.T_selected, peaks[i].turned));
  // Against a flat target (a floor plan), the pose's twin across its middle (a building symmetric
  // under a half turn: off both axes through what the pose aligns, so no shift along one reaches
  // it).
  if (in.target_complete) {
    Transform twin = half_turn(in.T_selected, occ.centre());
    if (distinct(twin)) {
      double r = cmp.ratio(twin);
      twin = climb(cmp, twin, r, occ.cell() / 2);
      if (distinct(twin)) offer(twin, r, describe(twin, in.T_selected, true));
    }
  }
  if (!best.description.empty()) {
    const Comparison::Support s = cmp.support(best.T_target_source);
    best.only_alternative = s.only_alt;
    best.only_selected = s.only_sel;
  }
  return best;
}

}  // namespace pagor
