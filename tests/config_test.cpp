#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "support/test_util.hpp"

using namespace pagor;

TEST_CASE("the default config has the paper's outdoor classes and survives a JSON round trip") {
  const Config c = default_config();
  REQUIRE(c.landmarks.classes.size() == 5);
  CHECK(c.landmarks.classes[0].name == "car");
  CHECK(c.landmarks.classes[3].name == "traffic-sign");
  CHECK(c.landmarks.classes[4].name == "building");
  CHECK(c.landmarks.classes[4].method == LandmarkMethod::fpfh);
  CHECK(c.graph.trim == TrimKind::ratio);
  CHECK(c.graph.thresholds.size() == 4);
  const std::string text = config_to_json(c);
  const Config back = parse_config(text);
  CHECK(config_to_json(back) == text);
}

TEST_CASE("absent keys keep their defaults") {
  const Config c = parse_config(R"({"verification": {"mu": 2.5}})");
  CHECK(c.verification.mu == 2.5);
  CHECK(c.verification.voxel_size == default_config().verification.voxel_size);
  CHECK(c.landmarks.classes.size() == 5);
}

TEST_CASE("unknown keys, wrong types and bad values name the key path") {
  CHECK_THROWS_WITH(parse_config(R"({"graph": {"thresholdz": [1]}})", "my.json"),
                    Catch::Contains("my.json") && Catch::Contains("graph.thresholdz") &&
                        Catch::Contains("unknown key"));
  CHECK_THROWS_WITH(parse_config(R"({"bogus": 1})"), Catch::Contains("bogus"));
  CHECK_THROWS_WITH(parse_config(R"({"graph": {"thresholds": [0.1, "x"]}})"),
                    Catch::Contains("graph.thresholds[1]") && Catch::Contains("expected a number"));
  CHECK_THROWS_WITH(parse_config(R"({"graph": {"thresholds": [0.2, 0.1]}})"),
                    Catch::Contains("graph.thresholds[1]") && Catch::Contains("increase"));
  CHECK_THROWS_WITH(parse_config(R"({"graph": {"trim": "diff"}})"),
                    Catch::Contains("graph.trim") && Catch::Contains("\"difference\""));
  CHECK_THROWS_WITH(parse_config(R"({"clique": {"max_inner_iterations": 1.5}})"),
                    Catch::Contains("clique.max_inner_iterations") && Catch::Contains("integer"));
  CHECK_THROWS_WITH(
      parse_config(R"({"landmarks": {"classes": [{"name": "car", "voxel_size": "big"}]}})"),
      Catch::Contains("landmarks.classes[0].voxel_size"));
  CHECK_THROWS_WITH(parse_config(R"({"landmarks": {"classes": [{"name": "lamp"}]}})"),
                    Catch::Contains("landmarks.classes[0].name") && Catch::Contains("lamp"));
  CHECK_THROWS_WITH(parse_config(R"({"verification": {"mu": -1}})"),
                    Catch::Contains("verification.mu"));
  CHECK_THROWS_WITH(parse_config("{not json"), Catch::Contains("not valid JSON"));
  CHECK_THROWS_AS(parse_config("[1, 2]"), ConfigError);
}

TEST_CASE("label schemes: built-in by name, or custom") {
  const Config raw = parse_config(R"({"label_scheme": "semantickitti"})");
  CHECK(raw.label_scheme.ids_of("car") == std::vector<std::uint32_t>{10});
  CHECK(raw.label_scheme.ids_of("building") == std::vector<std::uint32_t>{50});
  CHECK(raw.label_scheme.ids_of("pole") == std::vector<std::uint32_t>{80});
  CHECK(default_config().label_scheme.automatic());  // detected per cloud
  CHECK(default_config().label_scheme.find("pole") >= 0);
  CHECK(parse_config(config_to_json(default_config())).label_scheme.automatic());
  CHECK(parse_config(R"({"label_scheme": "none"})").label_scheme.ignores_labels());
  CHECK_THROWS_WITH(parse_config(R"({"label_scheme": {"name": "auto", "classes": {"car": [1]}}})"),
                    Catch::Contains("label_scheme.name") && Catch::Contains("built-in"));
  const Config train = parse_config(R"({"label_scheme": "semantickitti-train"})");
  CHECK(train.label_scheme.ids_of("car") == std::vector<std::uint32_t>{0});
  CHECK(train.label_scheme.ids_of("pole") == std::vector<std::uint32_t>{17});
  CHECK(train.label_scheme.ids_of("trunk") == std::vector<std::uint32_t>{15});

  const Config custom = parse_config(R"({
    "label_scheme": {"name": "lab", "classes": {"column": [2, 3], "wall": [1]}},
    "landmarks": {"classes": [{"name": "column", "voxel_size": 0.05}]}})");
  CHECK(custom.label_scheme.ids_of("column") == std::vector<std::uint32_t>{2, 3});
  CHECK(parse_config(config_to_json(custom)).label_scheme.ids_of("wall") ==
        std::vector<std::uint32_t>{1});
  CHECK_THROWS_WITH(parse_config(R"({"label_scheme": "nuscenes"})"),
                    Catch::Contains("label_scheme") && Catch::Contains("semantickitti-train"));
}

TEST_CASE("a config file is read, and a missing one is reported") {
  test::TempDir dir;
  CHECK_THROWS_WITH(load_config(dir.file("none.json")), Catch::Contains("none.json"));
}

TEST_CASE("section_json tells sections apart") {
  Config a = default_config();
  Config b = a;
  b.verification.mu = 3.0;
  CHECK(section_json(a, "verification") != section_json(b, "verification"));
  CHECK(section_json(a, "graph") == section_json(b, "graph"));
}

TEST_CASE("the paper preset is the published configuration, and a document can start from it") {
  const Config paper = preset_config("paper");
  REQUIRE(paper.landmarks.classes.size() == 4);  // car, trunk, pole clusters; building FPFH
  CHECK(paper.landmarks.classes[3].name == "building");
  CHECK(paper.graph.trim == TrimKind::ratio);
  CHECK(paper.graph.thresholds == std::vector<double>{0.02, 0.04, 0.08, 0.16});
  CHECK(paper.gnc.model == PoseModel::se3);
  CHECK(paper.verification.score == ScoreKind::truncated);
  CHECK(paper.verification.mu == 1.0);
  CHECK_FALSE(paper.landmarks.adapt_to_spacing);
  CHECK(paper.landmarks.fallback.mode == FallbackMode::never);
  CHECK(preset_config("default").gnc.model == PoseModel::automatic);

  const Config c = parse_config(R"({"preset": "paper", "gnc": {"noise_bound": 0.5}})");
  CHECK(c.gnc.model == PoseModel::se3);
  CHECK(c.gnc.noise_bound == 0.5);
  CHECK(parse_config("{}", "x", "paper").gnc.model == PoseModel::se3);
  CHECK_THROWS_WITH(parse_config(R"({"preset": "fast"})", "my.json"),
                    Catch::Contains("my.json: preset") && Catch::Contains("paper"));
  CHECK_THROWS_WITH(parse_config(R"({"acceptance": {"min_overlap": 2}})", "my.json"),
                    Catch::Contains("acceptance.min_overlap"));
  CHECK_THROWS_WITH(parse_config(R"({"gnc": {"model": "se4"}})", "my.json"),
                    Catch::Contains("four_dof"));
  // Every preset survives a JSON round trip.
  for (const auto& name : preset_names())
    CHECK(config_to_json(parse_config(config_to_json(preset_config(name)))) ==
          config_to_json(preset_config(name)));
}

// ---- the parameter tables ----------------------------------------------------------------------

TEST_CASE("every parameter is documented, and every number has an upper limit") {
  for (const std::string& preset : preset_names()) {
    const Config c = preset_config(preset);
    const std::vector<ConfigField> fields = config_fields(c);
    CHECK(fields.size() > 80);
    for (const ConfigField& f : fields) {
      INFO(preset << ": " << f.path);
      CHECK(std::string(f.info.key).size() > 0);
      CHECK(std::string(f.info.doc).size() > 10);
      const bool numeric = f.kind == FieldKind::number || f.kind == FieldKind::integer ||
                           f.kind == FieldKind::numbers;
      // A seed is any integer; every other number, iteration counts and budgets above all, is
      // bounded above so that no configuration makes a loop unbounded.
      if (numeric && f.path != "clique.seed") CHECK(std::isfinite(f.info.range.max));
      if (f.kind == FieldKind::choice) CHECK(f.choices.size() >= 2);
    }
  }
}

TEST_CASE("a number beyond its field's range is an error naming the field and the range") {
  const Config base = default_config();
  int tried = 0;
  for (const ConfigField& f : config_fields(base)) {
    if (f.kind != FieldKind::number && f.kind != FieldKind::integer) continue;
    if (!std::isfinite(f.info.range.max)) continue;
    INFO(f.path);
    Config c = base;
    const double beyond = f.info.range.max + std::max(1.0, std::abs(f.info.range.max));
    CHECK_THROWS_WITH(set_field_number(c, f.path, beyond),
                      Catch::Contains(f.path) && Catch::Contains("is outside") &&
                          Catch::Contains(f.info.range.text()));
    CHECK(config_to_json(c) == config_to_json(base));  // unchanged on error
    ++tried;
  }
  CHECK(tried > 60);
}

TEST_CASE("every parameter reads back what was written, by path") {
  Config c = default_config();
  for (const ConfigField& f : config_fields(c)) {
    INFO(f.path);
    const std::string before = config_to_json(c);
    set_field_json(c, f.path, field_json(c, f.path));
    CHECK(config_to_json(c) == before);
    if (const auto v = field_number(c, f.path)) {
      set_field_number(c, f.path, *v);
      CHECK(config_to_json(c) == before);
    }
  }
  set_field_number(c, "verification.mu", 0.7);
  CHECK(c.verification.mu == 0.7);
  set_field_number(c, "landmarks.classes[2].min_points", 12.4);
  CHECK(c.landmarks.classes[2].min_points == 12);
  set_field_json(c, "gnc.model", "\"se3\"");
  CHECK(c.gnc.model == PoseModel::se3);
  CHECK_THROWS_WITH(set_field_number(c, "graph.nope", 1), Catch::Contains("graph.nope"));
  CHECK_THROWS_WITH(set_field_json(c, "gnc.model", "\"sideways\""),
                    Catch::Contains("gnc.model") && Catch::Contains("\"four_dof\""));
  CHECK_FALSE(field_number(c, "gnc.model"));
}

TEST_CASE("the document's sections are the table's") {
  const nlohmann::json j = nlohmann::json::parse(config_to_json(default_config()));
  std::vector<std::string> keys;
  Config::sections([&](auto, const FieldInfo& f) { keys.push_back(f.key); });
  CHECK(keys.size() == j.size());
  for (const std::string& k : keys) {
    INFO(k);
    CHECK(j.contains(k));
    CHECK_NOTHROW(section_json(default_config(), k));
  }
  CHECK_THROWS_AS(section_json(default_config(), "nope"), ConfigError);
}
