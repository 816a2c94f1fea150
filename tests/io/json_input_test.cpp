// Depth-limited JSON parsing and checked getters, and the config reader built on them: every
// number a user can write ends in the value it says or in an error naming the file and key.

#include <catch2/catch.hpp>
#include <limits>
#include <string>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/json_input.hpp"

using namespace pagor;
using nlohmann::json;

TEST_CASE("JSON nesting is limited while parsing, even 100000 levels deep") {
  const std::string deep =
      "{\"graph\": {\"trim\": " + std::string(100000, '[') + std::string(100000, ']') + "}}";
  CHECK_THROWS_WITH(parse_json_limited(deep, "deep.json"),
                    Catch::StartsWith("deep.json: nesting deeper than 64"));
  CHECK_THROWS_WITH(parse_config(deep, "deep.json"), Catch::StartsWith("deep.json: nesting"));
  const std::string ok = std::string(63, '[') + std::string(63, ']');
  CHECK(parse_json_limited(ok, "ok.json").is_array());
  const std::string over = std::string(65, '[') + std::string(65, ']');
  CHECK_THROWS_AS(parse_json_limited(over, "x"), ConfigError);
  // Brackets inside strings (escaped quotes too) are no nesting.
  const std::string text = "{\"a\": \"" + std::string(100, '[') + "\\\"[{\"}";
  CHECK(parse_json_limited(text, "s.json")["a"].get<std::string>().size() == 103);
  CHECK_THROWS_WITH(parse_json_limited("{\n\"a\":\n" + over + "}", "l.json"),
                    Catch::Contains("(line 3)"));
}

TEST_CASE("JSON numbers beyond a double and malformed text name the origin") {
  CHECK_THROWS_WITH(parse_json_limited("{\"a\": 1e400}", "big.json"),
                    Catch::StartsWith("big.json: not valid JSON"));
  CHECK_THROWS_WITH(parse_json_limited("{\"a\": ", "cut.json"),
                    Catch::StartsWith("cut.json: not valid JSON"));
  CHECK_THROWS_WITH(parse_json_limited("\"\xff\"", "utf.json"),
                    Catch::StartsWith("utf.json: not valid JSON"));
}

TEST_CASE("checked integers: the range is checked before any conversion") {
  const std::int64_t imax = std::numeric_limits<int>::max();
  CHECK(json_integer(json::parse("7"), "f: k", 0, imax) == 7);
  CHECK(json_integer(json::parse("3.0"), "f: k", 0, imax) == 3);
  CHECK(json_integer(json::parse("-2"), "f: k", -5, imax) == -2);
  CHECK_THROWS_WITH(json_integer(json::parse("4294967296"), "f: k", 0, imax),
                    Catch::StartsWith("f: k: expected an integer in [0, 2147483647]"));
  CHECK_THROWS_WITH(json_integer(json::parse("10000000000"), "f: k", 0, imax),
                    Catch::Contains("10000000000"));
  CHECK_THROWS_WITH(json_integer(json::parse("1e30"), "f: k", 0, imax), Catch::Contains("1e+30"));
  CHECK_THROWS_WITH(
      json_integer(json::parse("9.3e18"), "f: k", std::numeric_limits<std::int64_t>::min(),
                   std::numeric_limits<std::int64_t>::max()),
      Catch::Contains("expected an integer in"));
  CHECK_THROWS_WITH(json_integer(json::parse("2.5"), "f: k", 0, imax),
                    Catch::Contains("expected an integer, got 2.5"));
  CHECK_THROWS_WITH(json_integer(json::parse("\"3\""), "f: k", 0, imax),
                    Catch::Contains("expected an integer, got string"));
  CHECK(json_unsigned(json::parse("18446744073709551615"), "f: k",
                      std::numeric_limits<std::uint64_t>::max()) ==
        std::numeric_limits<std::uint64_t>::max());
  CHECK_THROWS_WITH(json_unsigned(json::parse("-1.0"), "f: k", 100),
                    Catch::Contains("expected a non-negative integer"));
  CHECK_THROWS_WITH(json_unsigned(json::parse("-1"), "f: k", 100),
                    Catch::Contains("expected a non-negative integer"));
  CHECK_THROWS_WITH(json_unsigned(json::parse("1.8446744073709552e19"), "f: k",
                                  std::numeric_limits<std::uint64_t>::max()),
                    Catch::Contains("expected an integer in"));
  CHECK(json_finite(json::parse("0.5"), "f: k") == 0.5);
  CHECK_THROWS_WITH(json_finite(json::parse("null"), "f: k"), Catch::Contains("expected a number"));
}

TEST_CASE("config: integers that used to wrap or truncate are errors naming file and key") {
  const auto fails = [](const std::string& text, const std::string& key) {
    CHECK_THROWS_WITH(parse_config(text, "c.json"), Catch::StartsWith("c.json: " + key));
  };
  fails(R"({"correspondences":{"max_correspondences":4294967296}})",
        "correspondences.max_correspondences: expected an integer in");
  fails(R"({"correspondences":{"max_correspondences":10000000000}})",
        "correspondences.max_correspondences");
  fails(R"({"correspondences":{"max_correspondences":1e30}})",
        "correspondences.max_correspondences");
  fails(R"({"clique":{"seed":-1.0}})", "clique.seed: expected a non-negative integer");
  fails(R"({"graph":{"thresholds":[1e400]}})", "not valid JSON");
  fails(R"({"verification":{"voxel_size":1e-300}})",
        "verification.voxel_size: 1e-300 is outside [0.001, 100] or 0 (off) [m]");
  CHECK(parse_config(R"({"clique":{"seed":18446744073709551615}})", "c.json").clique.seed ==
        std::numeric_limits<std::uint64_t>::max());
  CHECK(parse_config(R"({"correspondences":{"max_correspondences":2000.0}})", "c.json")
            .correspondences.max_correspondences == 2000);
}
