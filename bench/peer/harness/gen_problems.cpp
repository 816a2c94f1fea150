// gen_problems: dense, learned-matcher-like correspondence problems with a known ground truth.
//
// usage: gen_problems OUT_DIR [COUNT=20] [FIRST_SEED=1]
// writes OUT_DIR/gen-SS.txt  (px py pz qx qy qz 1 inlier, inlier = |T p - q| < 0.6 m as in gedi-dev)
//        OUT_DIR/gen-SS.T.txt (4x4 row-major, q ~ T p)
// and prints one manifest line per problem.
//
// Per problem (seed s, std::mt19937_64(s), libstdc++ distributions):
//  - n ~ U{1000..2000} correspondences, inlier ratio ~ U[0.05, 0.15], noise radius ~ U[0.1, 0.3] m
//    (inlier residual uniform in a ball of that radius);
//  - scene: source keypoints in a 100 m x 100 m x 10 m box, 60 % of them in 40 Gaussian blobs
//    (sigma 2 m horizontal, 1 m vertical: keypoints concentrate on structures), 40 % uniform;
//  - T: yaw ~ U[-180, 180] deg, pitch and roll ~ U[-3, 3] deg, t ~ U[-20, 20]^2 x U[-1, 1] m;
//  - outliers, structured like a learned matcher's:
//      * 3 "repetitive structure" clusters, each of size U[0.3, 0.6] x inliers: source points near
//        one blob, target = T p + s_k + noise with a horizontal shift |s_k| ~ U[3, 10] m, i.e.
//        mutually consistent (a competing rigid hypothesis, smaller than the true one);
//      * 40 % of the rest "near misses": target = T p + d, |d| ~ U[0.8, 6] m (close to true match);
//      * 30 % of the rest "shared source": p reuses an already used source point (one-to-many
//        matching), target = T p' + noise with p' another keypoint within ~10 m;
//      * the remaining ones uniform: p random keypoint, target uniform in T(box).
//  - correspondences are shuffled.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

using V3 = Eigen::Vector3d;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: gen_problems OUT_DIR [COUNT=20] [FIRST_SEED=1]\n");
    return 2;
  }
  const std::string out = argv[1];
  const int count = argc > 2 ? std::atoi(argv[2]) : 20;
  const int first = argc > 3 ? std::atoi(argv[3]) : 1;
  const double kPi = 3.14159265358979323846;

  for (int s = first; s < first + count; ++s) {
    std::mt19937_64 rng(static_cast<uint64_t>(s) * 7919u + 12345u);
    auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    auto UI = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
    std::normal_distribution<double> N01(0.0, 1.0);
    auto ball = [&](double r) {  // uniform in a ball of radius r
      V3 d;
      do { d = V3(U(-1, 1), U(-1, 1), U(-1, 1)); } while (d.squaredNorm() > 1.0);
      return V3(r * d);
    };

    const int n = UI(1000, 2000);
    const double ratio = U(0.05, 0.15);
    const double noise = U(0.1, 0.3);
    const int n_in = static_cast<int>(std::lround(n * ratio));

    const double yaw = U(-180, 180) * kPi / 180, pitch = U(-3, 3) * kPi / 180,
                 roll = U(-3, 3) * kPi / 180;
    Eigen::Matrix3d R = (Eigen::AngleAxisd(yaw, V3::UnitZ()) * Eigen::AngleAxisd(pitch, V3::UnitY()) *
                         Eigen::AngleAxisd(roll, V3::UnitX()))
                            .toRotationMatrix();
    V3 t(U(-20, 20), U(-20, 20), U(-1, 1));
    auto Tf = [&](const V3& p) { return V3(R * p + t); };

    // Scene keypoints (source side).
    std::vector<V3> centers(40);
    for (auto& c : centers) c = V3(U(-50, 50), U(-50, 50), U(-2, 8));
    auto clampBox = [](V3 p) {
      p.x() = std::clamp(p.x(), -50.0, 50.0);
      p.y() = std::clamp(p.y(), -50.0, 50.0);
      p.z() = std::clamp(p.z(), -2.0, 8.0);
      return p;
    };
    auto scenePoint = [&]() {
      if (U(0, 1) < 0.6) {
        const V3& c = centers[UI(0, 39)];
        return clampBox(c + V3(2 * N01(rng), 2 * N01(rng), 1 * N01(rng)));
      }
      return V3(U(-50, 50), U(-50, 50), U(-2, 8));
    };

    std::vector<std::pair<V3, V3>> corr;
    corr.reserve(n);
    std::vector<V3> used_src;
    // Inliers.
    for (int i = 0; i < n_in; ++i) {
      V3 p = scenePoint();
      corr.emplace_back(p, Tf(p) + ball(noise));
      used_src.push_back(p);
    }
    // Repetitive-structure clusters.
    int n_cluster_total = 0;
    for (int k = 0; k < 3; ++k) {
      const int sz = static_cast<int>(std::lround(U(0.3, 0.6) * n_in));
      const double ang = U(0, 2 * kPi), mag = U(3, 10);
      V3 shift(mag * std::cos(ang), mag * std::sin(ang), 0);
      const V3& c = centers[UI(0, 39)];
      for (int i = 0; i < sz && int(corr.size()) < n; ++i) {
        V3 p = clampBox(c + V3(5 * N01(rng), 5 * N01(rng), 1.5 * N01(rng)));
        corr.emplace_back(p, Tf(p) + shift + ball(noise));
        used_src.push_back(p);
        ++n_cluster_total;
      }
    }
    const int rest = n - int(corr.size());
    const int n_near = static_cast<int>(std::lround(0.4 * rest));
    const int n_shared = static_cast<int>(std::lround(0.3 * rest));
    for (int i = 0; i < n_near; ++i) {
      V3 p = scenePoint();
      V3 dir;
      do { dir = V3(N01(rng), N01(rng), 0.3 * N01(rng)); } while (dir.norm() < 1e-6);
      corr.emplace_back(p, Tf(p) + dir.normalized() * U(0.8, 6));
      used_src.push_back(p);
    }
    for (int i = 0; i < n_shared; ++i) {
      V3 p = used_src[UI(0, int(used_src.size()) - 1)];
      V3 p2 = clampBox(p + V3(U(-10, 10), U(-10, 10), U(-2, 2)));
      corr.emplace_back(p, Tf(p2) + ball(noise));
    }
    while (int(corr.size()) < n) {
      V3 p = scenePoint();
      V3 q = Tf(V3(U(-50, 50), U(-50, 50), U(-2, 8)));
      corr.emplace_back(p, q);
    }
    std::shuffle(corr.begin(), corr.end(), rng);

    char name[64];
    std::snprintf(name, sizeof name, "gen-%02d", s);
    const std::string base = out + "/" + name;
    FILE* f = std::fopen((base + ".txt").c_str(), "w");
    FILE* g = std::fopen((base + ".T.txt").c_str(), "w");
    if (!f || !g) { std::perror(base.c_str()); return 1; }
    int flagged = 0;
    for (const auto& [p, q] : corr) {
      const int in = (Tf(p) - q).norm() < 0.6;
      flagged += in;
      std::fprintf(f, "%.4f %.4f %.4f %.4f %.4f %.4f 1 %d\n", p.x(), p.y(), p.z(), q.x(), q.y(),
                   q.z(), in);
    }
    Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
    T.topLeftCorner<3, 3>() = R;
    T.topRightCorner<3, 1>() = t;
    for (int r = 0; r < 4; ++r)
      std::fprintf(g, "%.9f %.9f %.9f %.9f\n", T(r, 0), T(r, 1), T(r, 2), T(r, 3));
    std::fclose(f);
    std::fclose(g);
    std::printf("%s seed=%d n=%d inliers_planted=%d flagged=%d ratio=%.3f noise_radius=%.3f "
                "cluster_outliers=%d near=%d shared=%d uniform=%d yaw_deg=%.1f\n",
                name, s, n, n_in, flagged, double(flagged) / n, noise, n_cluster_total, n_near,
                n_shared, rest - n_near - n_shared, yaw * 180 / kPi);
  }
  return 0;
}
