// The ground of a cloud without labels: a street that climbs stays ground, walls, cars and bushes
// do not; a single height layer gets the climbing street wrong.

#include <catch2/catch.hpp>
#include <random>

#include "pagor/front/ground.hpp"
#include "pagor/front/landmarks.hpp"

using namespace pagor;

namespace {

// A street 80 m long climbing at `grade` (m per m) along x, sampled every 0.3 m with 2 cm noise,
// with a 3 m high wall along it (on the pavement) and a 1.5 m high car on it. `labels`: 1 ground,
// 0 the rest.
struct Street {
  std::vector<Eigen::Vector3f> points;
  std::vector<int> labels;
};
Street street(double grade) {
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.0f, 0.02f);
  Street s;
  const auto road = [&](double x) { return static_cast<float>(grade * x - 1.7); };
  for (double x = -40; x < 40; x += 0.3)
    for (double y = -6; y < 8; y += 0.3) {  // the road, and the pavement under the wall
      s.points.emplace_back(x, y, road(x) + noise(rng));
      s.labels.push_back(1);
    }
  for (double x = -40; x < 40; x += 0.3)
    for (double z = 0.6; z < 3.0; z += 0.3) {  // the wall from 0.6 m above the road
      s.points.emplace_back(x, 6.5, road(x) + z);
      s.labels.push_back(0);
    }
  for (double x = 10; x < 14.5; x += 0.3)
    for (double z = 0.6; z < 1.5; z += 0.3) {  // a car's sides
      s.points.emplace_back(x, 0.0, road(x) + z);
      s.points.emplace_back(x, 1.8, road(x) + z);
      s.labels.insert(s.labels.end(), {0, 0});
    }
  return s;
}

// Fraction of the points of label `label` that `ground` says are ground.
double share(const Street& s, const std::vector<char>& ground, int label) {
  double n = 0, g = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (s.labels[i] == label) ++n, g += ground[i];
  return g / n;
}

}  // namespace

TEST_CASE("the ground surface follows a climbing street and leaves walls and cars") {
  for (double grade : {0.0, 0.05, 0.12}) {
    INFO("grade " << grade);
    const Street s = street(grade);
    const std::vector<char> ground = ground_points(s.points);
    CHECK(share(s, ground, 1) > 0.99);  // the road, end to end
    CHECK(share(s, ground, 0) == 0.0);  // walls and cars from 0.6 m up
  }
  // A single height layer keeps a flat street but leaves the upper half of the climbing one as
  // structure: what made a pose sliding along a sloped street look aligned.
  const Street climb = street(0.12);
  const float top = ground_layer_top(climb.points, 0.4f);
  double layer = 0, road = 0;
  for (std::size_t i = 0; i < climb.points.size(); ++i)
    if (climb.labels[i] == 1) ++road, layer += climb.points[i].z() <= top;
  CHECK(layer / road < 0.6);
}

TEST_CASE("a steeper slope than allowed is not ground; empty, tiny and non-finite input") {
  const Street s = street(0.12);
  GroundParams flat;
  flat.max_slope = 0.02;  // a street that climbs 12 % then leaves the surface behind
  CHECK(share(s, ground_points(s.points, flat), 1) < 0.5);
  CHECK(ground_points({}).empty());
  const std::vector<Eigen::Vector3f> one{{1.0f, 2.0f, 3.0f}};
  CHECK(ground_points(one) == std::vector<char>{1});
  const std::vector<Eigen::Vector3f> nan{{NAN, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}};
  CHECK(ground_points(nan) == std::vector<char>{0, 1});
  // A cloud far from the origin (georeferenced; float keeps 3 cm there) is segmented as near it.
  Street far = street(0.05);
  for (auto& p : far.points) p += Eigen::Vector3f(300000.0f, 200000.0f, 0.0f);
  const std::vector<char> g = ground_points(far.points);
  CHECK(share(far, g, 1) > 0.99);
  CHECK(share(far, g, 0) == 0.0);
}
