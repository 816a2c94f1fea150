// The floor-plan readers (JSON, SVG), their errors naming the element, and plan sampling.

#include <catch2/catch.hpp>
#include <fstream>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/front/landmarks.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

const char* kPlan = R"({"format": "pagor.floor_plan/1",
  "walls": [{"points": [[0, 0], [10, 0], [10, 5]]}, {"points": [[0, 0], [0, 5]], "closed": false}],
  "columns": [{"center": [3, 2], "radius": 0.3}, {"center": [7, 2], "radius": 0.25}]})";

std::string json_error(const std::string& text) {
  return test::input_error_of([&] { parse_floor_plan_json(text, "plan.json"); });
}

std::string svg_error(const std::string& text) {
  return test::input_error_of([&] { parse_floor_plan_svg(text, "plan.svg"); });
}

}  // namespace

TEST_CASE("a JSON plan gives its walls and columns in metres") {
  const FloorPlan plan = parse_floor_plan_json(kPlan, "plan.json");
  REQUIRE(plan.walls.size() == 2);
  REQUIRE(plan.walls[0].points.size() == 3);
  CHECK(plan.walls[0].points[2].isApprox(Eigen::Vector2d(10, 5)));
  REQUIRE(plan.columns.size() == 2);
  CHECK(plan.columns[1].center.isApprox(Eigen::Vector2d(7, 2)));
  CHECK(plan.columns[1].radius == Approx(0.25));
  // Written and read back, the plan is the same.
  const FloorPlan again = parse_floor_plan_json(floor_plan_to_json(plan), "again.json");
  REQUIRE(again.walls.size() == 2);
  CHECK(again.columns[0].center.isApprox(plan.columns[0].center));
}

TEST_CASE("a malformed JSON plan names the element at fault") {
  CHECK_THAT(json_error(R"({"walls": [{"points": [[0, 0], [1, 0]]}, {"points": [[0, 0], [1]]}]})"),
             Catch::Contains("plan.json: walls[1].points[1]: expected a point [x, y]"));
  CHECK_THAT(json_error(R"({"walls": [{"points": [[0, 0], [1, "a"]]}]})"),
             Catch::Contains("walls[0].points[1][1]: expected a number"));
  CHECK_THAT(json_error(R"({"columns": [{"center": [1, 1], "radius": -0.3}]})"),
             Catch::Contains("columns[0].radius: must be in (0, 100] [m]"));
  CHECK_THAT(json_error(R"({"columns": [{"centre": [1, 1], "radius": 0.3}]})"),
             Catch::Contains("columns[0].centre: unknown key"));
  CHECK_THAT(json_error(R"({"walls": [{"points": [[0, 0]]}]})"),
             Catch::Contains("walls[0].points: a wall needs at least two points"));
  CHECK_THAT(json_error(R"({"walls": [{"closed": true}]})"),
             Catch::Contains("walls[0]: missing \"points\""));
  CHECK_THAT(json_error(R"({"format": "dxf", "walls": []})"), Catch::Contains("format: expected"));
  CHECK_THAT(json_error(R"({"walls": [], "columns": []})"),
             Catch::Contains("neither walls nor columns"));
  CHECK_THAT(json_error(R"({"walls": [)"), Catch::Contains("plan.json"));
  CHECK_THAT(json_error("[1, 2]"), Catch::Contains("expected a JSON object"));
}

TEST_CASE("an SVG plan is scaled to metres with y up") {
  const std::string svg = R"(<?xml version="1.0"?>
<!-- exported from CAD -->
<svg xmlns="http://www.w3.org/2000/svg" data-scale="0.01">
  <g id="walls">
    <line x1="0" y1="0" x2="1000" y2="0"/>
    <polyline points="0,0 0,500 200,500"/>
    <rect x="100" y="100" width="200" height="100"/>
    <path d="M 0 0 L 100 0 l 0 100 H 0 Z m 10 10 v 20"/>
  </g>
  <circle cx="300" cy="200" r="30"/>
  <ellipse cx="700" cy="200" rx="25" ry="25"/>
</svg>)";
  const FloorPlan plan = parse_floor_plan_svg(svg, "plan.svg");
  REQUIRE(plan.walls.size() == 5);
  CHECK(plan.walls[0].points[1].isApprox(Eigen::Vector2d(10, 0)));
  CHECK(plan.walls[1].points[1].isApprox(Eigen::Vector2d(0, -5)));  // y flipped
  CHECK(plan.walls[2].closed);
  REQUIRE(plan.walls[3].points.size() == 4);
  CHECK(plan.walls[3].closed);
  CHECK(plan.walls[3].points[2].isApprox(Eigen::Vector2d(1, -1)));
  // After Z the relative move starts from the closed subpath's start (0, 0).
  REQUIRE(plan.walls[4].points.size() == 2);
  CHECK(plan.walls[4].points[0].isApprox(Eigen::Vector2d(0.1, -0.1)));
  CHECK(plan.walls[4].points[1].isApprox(Eigen::Vector2d(0.1, -0.3)));
  REQUIRE(plan.columns.size() == 2);
  CHECK(plan.columns[0].center.isApprox(Eigen::Vector2d(3, -2)));
  CHECK(plan.columns[0].radius == Approx(0.3));
  CHECK(plan.columns[1].radius == Approx(0.25));

  // The scale from a width in metres and a viewBox: 80 m over 8000 units.
  const FloorPlan b = parse_floor_plan_svg(
      R"(<svg width="80m" height="50m" viewBox="0 0 8000 5000"><circle cx="100" cy="0" r="30"/></svg>)",
      "b.svg");
  CHECK(b.columns[0].center.x() == Approx(1.0));
}

TEST_CASE("a malformed SVG plan names the element and its line") {
  CHECK_THAT(svg_error("<svg>\n<line x1='0' y1='0' x2='1' y2='1'/></svg>"),
             Catch::Contains("plan.svg:1: <svg> #1: no scale"));
  CHECK_THAT(svg_error("<svg data-scale='1'>\n<line x1='0' y1='0' x2='1'/></svg>"),
             Catch::Contains("plan.svg:2: <line> #1: missing attribute y2"));
  CHECK_THAT(
      svg_error(
          "<svg data-scale='1'>\n<circle cx='0' cy='0' r='1'/>\n<circle cx='a' cy='0' r='1'/>"),
      Catch::Contains("plan.svg:3: <circle> #2: attribute cx=\"a\" is not a number"));
  CHECK_THAT(svg_error("<svg data-scale='1'>\n\n<path d='M 0 0 C 1 1 2 2 3 3'/></svg>"),
             Catch::Contains("plan.svg:3: <path> #1: d: command 'C' (a curve or arc)"));
  CHECK_THAT(svg_error("<svg data-scale='1'><rect width='1' height='1' transform='rotate(4)'/>"),
             Catch::Contains("<rect> #1: transform attributes are not supported"));
  CHECK_THAT(svg_error("<svg data-scale='1'><polyline points='0,0 1'/>"),
             Catch::Contains("<polyline> #1: points: an odd count"));
  CHECK_THAT(svg_error("<svg data-scale='1'><line x1=0 y1='0'/>"),
             Catch::Contains("attribute x1: value must be quoted"));
  CHECK_THAT(svg_error("<svg data-scale='1'><ellipse cx='0' cy='0' rx='1' ry='2'/>"),
             Catch::Contains("<ellipse> #1: an ellipse with rx != ry"));
  CHECK_THAT(svg_error("<html></html>"), Catch::Contains("not an SVG file"));
  CHECK_THAT(svg_error("<svg data-scale='1'><!-- open"), Catch::Contains("unterminated comment"));
}

TEST_CASE("read_floor_plan goes by extension and names the file") {
  test::TempDir dir;
  std::ofstream(dir.file("p.json")) << kPlan;
  CHECK(read_floor_plan(dir.file("p.json")).columns.size() == 2);
  CHECK_THROWS_WITH(read_floor_plan(dir.file("missing.svg")),
                    Catch::Contains("missing.svg: floor plan does not exist"));
  CHECK_THROWS_WITH(read_floor_plan(dir.file("p.txt")), Catch::Contains("must be a .json or .svg"));
  CHECK(is_floor_plan_path("a/b.SVG"));
  CHECK_FALSE(is_floor_plan_path("a/b.pcd"));
}

TEST_CASE("a sampled plan has wall points and columns whose landmarks sit at their centres") {
  const FloorPlan plan = parse_floor_plan_json(kPlan, "plan.json");
  const PointCloud cloud = sample_floor_plan(plan, 0.05);
  std::size_t walls = 0, columns = 0;
  for (std::uint32_t l : cloud.labels) (l == kWallLabel ? walls : columns)++;
  // 15 m + 5 m of walls at 0.05 m: about 400 points; columns 38 + 32 points.
  CHECK(walls == Approx(400).margin(4));
  CHECK(columns == 38 + 32);
  for (const auto& p : cloud.points) CHECK(p.z() == 0.0f);
  const Config c = preset_config("indoor");
  const LandmarkSet set = extract_landmarks(cloud, c.label_scheme, c.landmarks);
  REQUIRE(set.landmarks.size() == 2);
  for (const Landmark& lm : set.landmarks) {
    const double d = std::min((lm.centroid.head<2>() - Eigen::Vector2d(3, 2)).norm(),
                              (lm.centroid.head<2>() - Eigen::Vector2d(7, 2)).norm());
    CHECK(d < 0.02);  // centroids of 5 cm voxel means
  }
  CHECK_THROWS_AS(sample_floor_plan(plan, 0.0), InputError);
}
