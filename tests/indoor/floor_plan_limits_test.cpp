// Floor plans from hostile files: sampling stays within its budget, SVG placements the reader
// cannot apply are refused instead of ignored, scales and radii stay physical, and a large plan
// loads in linear time.

#include <catch2/catch.hpp>
#include <fstream>

#include "pagor/errors.hpp"
#include "pagor/eval/dataset.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

std::string svg_error(const std::string& text) {
  return test::input_error_of([&] { parse_floor_plan_svg(text, "plan.svg"); });
}

std::string sample_error(const FloorPlan& plan, double spacing) {
  return test::input_error_of([&] { sample_floor_plan(plan, spacing); });
}

}  // namespace

TEST_CASE("a plan that would sample into too many points is an error naming the element") {
  // 72 bytes asked for 7.4 GB: one wall 1.5·10^7 m... of a 1e7 m plan at 5 cm.
  const std::string tiny = R"({"walls": [{"points": [[-9e6, 0], [9e6, 0]]}]})";
  const FloorPlan plan = parse_floor_plan_json(tiny, "long.json");
  CHECK_THAT(sample_error(plan, 0.05),
             Catch::Contains("walls[0]: sampling the plan every 0.05 m would make more than "
                             "10000000 points"));
  // A spacing so small that the step count would overflow an int (it once gave 2 points).
  FloorPlan small;
  small.walls.push_back({{Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)}, false});
  CHECK_THAT(sample_error(small, 1e-12), Catch::Contains("walls[0]: sampling the plan"));
  FloorPlan columns;
  columns.columns.assign(3, PlanColumn{Eigen::Vector2d(0, 0), 100.0});
  // 6.3·10^6 points a column: the second passes the budget.
  CHECK_THAT(sample_error(columns, 1e-4), Catch::Contains("columns[1]: sampling the plan"));
  // Within the budget the walls are sampled as before: 10 m at 5 cm, 200 steps and the end.
  CHECK(sample_floor_plan(small, 0.05).size() == 201);

  // Through load_pair the message names the plan's file too.
  test::TempDir dir;
  std::ofstream(dir.file("long.json")) << tiny;
  std::ofstream(dir.file("scan.bin"), std::ios::binary) << std::string(16, '\0');
  PairSource src;
  src.kind = PairSource::Kind::files;
  src.source = dir.file("scan.bin");
  src.target = dir.file("long.json");
  CHECK_THROWS_WITH(load_pair(src), Catch::Contains("long.json: walls[0]: sampling the plan"));
}

TEST_CASE("plan coordinates and column radii stay physical") {
  CHECK_THROWS_WITH(parse_floor_plan_json(R"({"walls": [{"points": [[0, 0], [2e7, 0]]}]})", "p"),
                    Catch::Contains("walls[0].points[1]: lies more than 1e7 m from the origin"));
  CHECK_THAT(svg_error("<svg data-scale='1'><circle cx='0' cy='0' r='1e9'/></svg>"),
             Catch::Contains("<circle> #1: radius 1000000000.000000 m is outside (0, 100] m"));
  CHECK_THAT(svg_error("<svg data-scale='0.001'><circle cx='0' cy='0' r='250'/></svg>"),
             Catch::Contains("no error"));  // 0.25 m in millimetre units
  CHECK_THAT(svg_error("<svg data-scale='1'><line x1='0' y1='0' x2='3e7' y2='0'/></svg>"),
             Catch::Contains("<line> #1: a point lies more than 1e7 m from the origin"));
}

TEST_CASE("an SVG scale of 0, a denormal or infinity is refused") {
  const std::string circle = "<circle cx='1' cy='1' r='0.3'/></svg>";
  CHECK_THAT(svg_error("<svg data-scale='0'>" + circle), Catch::Contains("data-scale gives 0"));
  CHECK_THAT(svg_error("<svg data-scale='1e-310'>" + circle),
             Catch::Contains("outside [1e-06, 10000]"));
  CHECK_THAT(svg_error("<svg data-scale='inf'>" + circle), Catch::Contains("is not a number"));
  CHECK_THAT(svg_error("<svg width='inf m' viewBox='0 0 10 10'>" + circle),
             Catch::Contains("no scale"));
  CHECK_THAT(svg_error("<svg width='infm' viewBox='0 0 10 10'>" + circle),
             Catch::Contains("width / viewBox width gives inf"));
  CHECK_THAT(svg_error("<svg width='1e-300m' viewBox='0 0 1e300 10'>" + circle),
             Catch::Contains("width / viewBox width gives 0"));
}

TEST_CASE("SVG placements the reader cannot apply are refused, not ignored") {
  // Each of these drew the plan 5 m off and was accepted.
  const std::string wall = "<rect x='0' y='0' width='10' height='5'/>";
  CHECK_THAT(svg_error("<svg data-scale='1'><g transform='translate(5 0)'>" + wall + "</g></svg>"),
             Catch::Contains("<g> #1: transform attributes are not supported"));
  CHECK_THAT(
      svg_error("<svg data-scale='1'><g style='transform: translate(5px)'>" + wall + "</g></svg>"),
      Catch::Contains("<g> #1: a CSS transform in style is not supported"));
  CHECK_THAT(svg_error("<svg data-scale='1'><style>g { transform: translate(5px) }</style><g>" +
                       wall + "</g></svg>"),
             Catch::Contains("<style> #1: a CSS transform in a style sheet"));
  CHECK_THAT(svg_error("<svg data-scale='1'><svg x='5'>" + wall + "</svg></svg>"),
             Catch::Contains("<svg> #2: nested <svg> elements are not supported"));
  CHECK_THAT(svg_error("<svg data-scale='1'><use href='#w' x='5'/></svg>"),
             Catch::Contains("<use> #1: <use> is not supported"));
  CHECK_THAT(svg_error("<svg data-scale='1' transform='scale(2)'>" + wall + "</svg>"),
             Catch::Contains("<svg> #1: transform attributes are not supported"));
  // Shapes in definitions are not drawn where they stand: not walls.
  const FloorPlan p = parse_floor_plan_svg(
      "<svg data-scale='1'><defs><rect x='50' y='50' width='1' height='1'/><g><circle cx='0' "
      "cy='0' r='0.3'/></g></defs><clipPath id='c'><rect width='2' height='2'/></clipPath>" +
          wall + "<marker><circle cx='0' cy='0' r='0.3'/></marker><symbol/></svg>",
      "plan.svg");
  REQUIRE(p.walls.size() == 1);
  CHECK(p.columns.empty());
  CHECK(p.walls[0].points[2].isApprox(Eigen::Vector2d(10, -5)));
}

TEST_CASE("a large JSON plan loads whole") {
  // 100 000 walls: the depth-limited parse was quadratic in the number of values.
  std::string text = R"({"walls": [)";
  for (int i = 0; i < 100000; ++i)
    text += (i ? "," : "") + std::string(R"({"points": [[)") + std::to_string(i) + R"(, 0], [)" +
            std::to_string(i) + ", 1]]}";
  text += "]}";
  const FloorPlan plan = parse_floor_plan_json(text, "big.json");
  REQUIRE(plan.walls.size() == 100000);
  CHECK(plan.walls[99999].points[1].isApprox(Eigen::Vector2d(99999, 1)));
}
