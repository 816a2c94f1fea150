// The pipeline on a matcher's correspondences (Pipeline::set_matches): without clouds (the back
// end alone), with clouds (verification as usual), fused with the landmarks, and on the real
// gedi-dev problems when the shared data is there.

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "pagor/eval/association_problem.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/registration.hpp"
#include "pagor/verify/diagnosis.hpp"
#include "pagor/verify/level_selection.hpp"

using namespace pagor;

namespace {

constexpr double kTranslationTolerance = 0.05;  // [m], inlier noise is 0.02 m
constexpr double kRotationTolerance = 0.5;      // [deg]

// A dense generated problem: 1000 correspondences, 10 % inliers, a rotation about a tilted axis.
AssociationProblem dense_problem() {
  AssociationParams a;
  a.m = 1000;
  a.seed = 5;
  return association_problem(a);
}

std::array<int, kStageCount> runs(const Pipeline& p) {
  std::array<int, kStageCount> r{};
  for (int s = 0; s < kStageCount; ++s)
    r[static_cast<std::size_t>(s)] = p.runs(static_cast<Stage>(s));
  return r;
}

}  // namespace

TEST_CASE("a matcher's correspondences register without clouds, with the defaults") {
  // Any rotation: the default pose model fits SE(3) where 4-DoF does not explain the clique.
  const AssociationProblem problem = dense_problem();
  Pipeline p;
  p.set_matches(problem.correspondences);
  p.set_ground_truth(problem.T_target_source);
  CHECK(p.has_input());
  CHECK_FALSE(p.has_clouds());
  p.run();
  CHECK(p.source_landmarks().landmarks.empty());
  CHECK(p.verifier() == nullptr);
  REQUIRE(p.correspondences().items.size() == problem.correspondences.size());
  CHECK(p.correspondences().matches == problem.correspondences.size());
  for (const Correspondence& c : p.correspondences().items) {
    CHECK(c.origin == CorrespondenceOrigin::matcher);
    CHECK(c.class_index == -1);
  }
  REQUIRE(p.selected_level() >= 0);
  const auto e = p.selected_error();
  REQUIRE(e);
  CHECK(e->translation < kTranslationTolerance);
  CHECK(e->rotation_deg < kRotationTolerance);
  CHECK(p.poses()[static_cast<std::size_t>(p.selected_level())].model == PoseModel::se3);
  // Nothing to verify on: neither accepted nor rejected on evidence, and it says so.
  CHECK_FALSE(p.acceptance().verified);
  CHECK_FALSE(p.acceptance().accepted);
  CHECK(p.acceptance().reason.find("nothing to verify on") != std::string::npos);
  CHECK(p.level_errors().size() == p.cliques().size());
  // Every level's clique is a clique, and the planted inliers dominate it.
  for (const CliqueResult& c : p.cliques()) {
    CHECK(is_clique(p.graph(), c.level, c.vertices));
    const InlierQuality q = inlier_quality(c.vertices, problem.inlier);
    CHECK(q.precision > 0.9);
  }
  const std::string report = to_json(make_registration(p, {"matches", "matches"}));
  CHECK(report.find("\"selected_by\": \"without_clouds\"") != std::string::npos);
  const auto origin = nlohmann::json::parse(report)["correspondences"]["origin"];
  CHECK(origin["matcher"]["count"] == 1000);
  CHECK(origin["landmark"]["count"] == 0);
  const auto sel = static_cast<std::size_t>(p.selected_level());
  CHECK(origin["matcher"]["selected_clique"] == p.cliques()[sel].vertices.size());
  CHECK(origin["matcher"]["selected_inliers"] == p.poses()[sel].inliers.size());
  CHECK(origin["landmark"]["selected_clique"] == 0);
  // The diagnosis counts the matcher's correspondences as a class of their own.
  const auto d = diagnose(p);
  REQUIRE(d);
  REQUIRE(d->classes.size() == 1);
  CHECK(d->classes[0].name == "matcher");
  CHECK(d->classes[0].correspondences == 1000);
  CHECK(d->verdict == DiagnosisVerdict::success);
}

TEST_CASE("the exact solver's proof, bound and budget reach the report") {
  const AssociationProblem problem = dense_problem();
  Config config = default_config();
  config.clique.solver = CliqueSolver::exact;
  Pipeline p(config);
  p.set_matches(problem.correspondences);
  p.run();
  for (const CliqueResult& c : p.cliques()) {
    CHECK(is_clique(p.graph(), c.level, c.vertices));
    CHECK(c.proven);  // a planted clique of 100 among random points: proven at once
    CHECK(c.clique_number_bound == static_cast<int>(c.vertices.size()));
    CHECK(c.budget == CliqueBudget::none);
  }
  std::string report = to_json(make_registration(p, {"matches", "matches"}));
  CHECK(report.find("\"clique_proven\": true") != std::string::npos);
  CHECK(report.find("\"clique_budget_hit\": \"none\"") != std::string::npos);
  // A budget of one node: a level that the colouring bound does not prove at once stops, and says
  // so.
  config.clique.exact_max_nodes = 1;
  p.set_config(config);
  p.run();
  int stopped = 0;
  for (const CliqueResult& c : p.cliques()) {
    CHECK(is_clique(p.graph(), c.level, c.vertices));
    CHECK(c.clique_number_bound >= static_cast<int>(c.vertices.size()));
    if (!c.proven) {
      CHECK(c.budget == CliqueBudget::nodes);
      ++stopped;
    }
  }
  report = to_json(make_registration(p, {"matches", "matches"}));
  CHECK((stopped == 0) == (report.find("\"clique_budget_hit\": \"nodes\"") == std::string::npos));
}

TEST_CASE("negative matcher ids become their positions; shared ids are never consistent") {
  std::vector<Correspondence> m(4);
  const Eigen::Vector3d t(1, 2, 3);
  const Eigen::Vector3d pts[] = {{0, 0, 0}, {5, 0, 0}, {0, 5, 0}, {0, 0, 5}};
  for (std::size_t i = 0; i < 4; ++i) {
    m[i].p = pts[i];
    m[i].q = pts[i] + t;
    m[i].score = 0.5;
  }
  Pipeline p;
  p.set_matches(m);
  p.run();
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(p.correspondences().items[i].source == static_cast<int>(i));
    CHECK(p.correspondences().items[i].score == 0.5);  // the matcher's weight is kept
  }
  CHECK(p.graph().edges_at_level.back() == 6);
  // Two matches of one source keypoint: the pair is not an edge.
  m[1].source = 0;
  p.set_matches(m);
  p.run();
  CHECK(p.graph().edges_at_level.back() == 5);
  CHECK_FALSE(p.graph().adjacent(0, 1, p.graph().levels() - 1));
}

TEST_CASE("matches with clouds are verified on them; clearing them brings the landmarks back") {
  SyntheticScene scene = make_synthetic_scene();
  // The matcher's correspondences: source points and where the ground truth puts them, plus
  // outliers pairing unrelated points.
  std::vector<Correspondence> m;
  const Transform& T = scene.T_target_source;
  for (std::size_t i = 0; i < scene.source.size() && m.size() < 200; i += 97) {
    Correspondence c;
    c.p = scene.source.points[i].cast<double>();
    const bool inlier = m.size() % 4 == 0;
    const Eigen::Vector3d x =
        inlier ? c.p : scene.source.points[(i * 7919) % scene.source.size()].cast<double>();
    c.q = T.block<3, 3>(0, 0) * x + T.block<3, 1>(0, 3);
    m.push_back(c);
  }
  Pipeline p;
  p.set_input(scene.source, scene.target);
  p.set_ground_truth(scene.T_target_source);
  p.set_matches(m);
  p.run();
  CHECK(p.source_landmarks().landmarks.empty());  // the matches replace the landmarks
  // ... but the clouds' labels are read as the landmarks would read them (the report names the
  // scheme; a viewer colours each cloud by it).
  CHECK_FALSE(p.source_landmarks().labels.scheme.classes.empty());
  CHECK(p.source_landmarks().labels.scheme.name == p.target_landmarks().labels.scheme.name);
  REQUIRE(p.verifier() != nullptr);
  CHECK(p.correspondences().items.size() == m.size());
  REQUIRE(p.selected_level() >= 0);
  CHECK(std::isfinite(p.verification().scores[static_cast<std::size_t>(p.selected_level())]));
  CHECK(p.acceptance().verified);
  CHECK(p.acceptance().accepted);
  REQUIRE(p.selected_error());
  CHECK(p.selected_error()->success);

  SECTION("fused: landmark and matcher correspondences in one pyramid, ids apart") {
    Config c = p.config();
    c.correspondences.fuse_matches = true;
    const auto before = runs(p);
    p.set_config(c);
    p.run();
    CHECK(p.runs(Stage::landmarks) == before[0] + 1);
    const CorrespondenceSet& set = p.correspondences();
    CHECK(set.matches == m.size());
    REQUIRE(set.items.size() > m.size());
    const int source_landmarks = static_cast<int>(p.source_landmarks().landmarks.size());
    for (const Correspondence& x : set.items) {
      if (x.origin == CorrespondenceOrigin::matcher) {
        CHECK(x.class_index == -1);
        CHECK(x.source >= source_landmarks);
      } else {
        CHECK(x.class_index >= 0);
        CHECK(x.source < source_landmarks);
      }
    }
    CHECK(correspondence_class_name(set.items.back(), p.source_landmarks()) == "matcher");
    const OriginCounts all = count_by_origin(set.items);
    CHECK(all.matcher == m.size());
    CHECK(all.landmark == set.items.size() - m.size());
    REQUIRE(p.selected_error());
    CHECK(p.selected_error()->success);
  }
  SECTION("cleared: the landmark correspondences again") {
    p.set_matches({});
    p.run();
    CHECK_FALSE(p.source_landmarks().landmarks.empty());
    CHECK(p.correspondences().matches == 0);
    for (const Correspondence& x : p.correspondences().items)
      CHECK(x.origin == CorrespondenceOrigin::landmark);
  }
}

TEST_CASE("a pipeline without clouds or matches has no input") {
  Pipeline p;
  CHECK_FALSE(p.has_input());
  CHECK_THROWS_AS(p.run(), InputError);
}

#ifdef PAGOR_GEDI_DIR
TEST_CASE("gedi-dev: a learned matcher's correspondences of real KITTI pairs, all ten right") {
  // 650-1350 correspondences a pair, 4-25 % inliers. Pair 08 has a spurious clique (points matched
  // to themselves near the sensor: a near-identity pose) that is the largest at levels 2 and 3;
  // selected without clouds by what every correspondence says, the true pose of levels 0-1 wins.
  const std::string dir = PAGOR_GEDI_DIR;
  for (int n = 3; n <= 12; ++n) {
    const std::string name = (n < 10 ? "0" : "") + std::to_string(n);
    INFO("gedi-dev " << name);
    const CorrespondenceFile input = read_correspondence_file(dir + "/" + name + ".txt");
    Pipeline p;
    p.set_matches(input.items);
    p.set_ground_truth(read_transform_file(dir + "/" + name + ".T.txt"));
    p.run();
    REQUIRE(p.selected_error());
    CHECK(p.selected_error()->success);
    for (const CliqueResult& c : p.cliques()) CHECK(is_clique(p.graph(), c.level, c.vertices));
    if (n == 8) CHECK(p.selected_level() <= 1);
  }
}

// settle_selected: the selected level is settled, or its pose is the same answer as a settled
// level's (the levels the first pass could not prove get the full search and the fallback only
// where that decides the result), and a re-run of the selection alone (a verification setting
// changed and changed back) gives what the first run gave.
TEST_CASE("gedi-dev: the selected level is settled, the others keep the first pass's search") {
  const CorrespondenceFile input =
      read_correspondence_file(std::string(PAGOR_GEDI_DIR) + "/03.txt");
  Config config = default_config();
  config.clique.probe_nodes = 0;  // the colouring's proof only: levels are left to settle
  Pipeline p(config);
  p.set_matches(input.items);
  p.set_ground_truth(read_transform_file(std::string(PAGOR_GEDI_DIR) + "/03.T.txt"));
  p.run();
  REQUIRE(p.selected_level() >= 0);
  REQUIRE(p.selected_error());
  CHECK(p.selected_error()->success);
  int probed = 0;
  std::vector<char> settled;
  for (const CliqueResult& c : p.cliques()) {
    INFO("level " << c.level);
    CHECK(is_clique(p.graph(), c.level, c.vertices));
    probed += c.budget == CliqueBudget::probe;
    CHECK(c.settled == (c.budget != CliqueBudget::probe));
    settled.push_back(c.settled);
  }
  CHECK(probed > 0);  // the first pass left levels it could not prove
  const CliqueResult& selected = p.cliques()[static_cast<std::size_t>(p.selected_level())];
  if (!selected.settled)  // then a settled level gives the same answer
    CHECK(same_answer_as(p.poses(), p.selected_level(), settled, config.acceptance.distinct()) >=
          0);
  // With poses distinct at any distance, the selected level is settled unless a settled level
  // has its very pose (the same clique).
  Config strict = config;
  strict.acceptance.distinct_translation = 1e-9;
  strict.acceptance.distinct_rotation = 1e-9;
  Pipeline q(strict);
  q.set_matches(input.items);
  q.set_ground_truth(read_transform_file(std::string(PAGOR_GEDI_DIR) + "/03.T.txt"));
  q.run();
  REQUIRE(q.selected_level() >= 0);
  const auto sel = static_cast<std::size_t>(q.selected_level());
  bool twin = false;
  for (std::size_t l = 0; l < q.cliques().size(); ++l)
    twin |= l != sel && q.cliques()[l].settled &&
            q.poses()[l].T_target_source.isApprox(q.poses()[sel].T_target_source, 1e-12);
  CHECK((q.cliques()[sel].settled || twin));
  REQUIRE(q.selected_error());
  CHECK(q.selected_error()->success);
  const std::vector<CliqueResult> first = p.cliques();
  const auto T = p.selected_transform();
  for (double mu : {config.verification.mu * 2, config.verification.mu}) {
    config.verification.mu = mu;
    p.set_config(config);
    p.run();
  }
  CHECK(p.runs(Stage::clique) == 1);  // the selection alone ran again
  // What counts as the same answer decides the settling: changing it runs the selection again.
  const int selections = p.runs(Stage::verification);
  Config wider = config;
  wider.acceptance.distinct_translation *= 2;
  p.set_config(wider);
  CHECK(p.stale(Stage::verification));
  p.run();
  CHECK(p.runs(Stage::verification) == selections + 1);
  p.set_config(config);
  p.run();
  REQUIRE(p.cliques().size() == first.size());
  for (std::size_t l = 0; l < first.size(); ++l) {
    CHECK(p.cliques()[l].vertices == first[l].vertices);
    CHECK(p.cliques()[l].settled == first[l].settled);
  }
  CHECK(p.selected_transform()->isApprox(*T));
}

TEST_CASE("gedi-dev: a warm start that loses to the cold one falls back to it, and says so") {
  // Pair 03, level 2: the warm start settles on 66 where the cold one finds 68.
  const CorrespondenceFile input =
      read_correspondence_file(std::string(PAGOR_GEDI_DIR) + "/03.txt");
  const Config config = default_config();
  const PyramidGraph g = build_pyramid_graph(input.items, config.graph, 1);
  CliqueParams cp = config.clique;
  cp.cascade_check_nodes = 0;  // the fallback alone
  cp.settle_selected = false;  // on every level
  const auto cascaded = solve_pyramid(g, cp);
  cp.solver = CliqueSolver::independent;
  const auto independent = solve_pyramid(g, cp);
  int fallbacks = 0;
  for (std::size_t l = 0; l < cascaded.size(); ++l) {
    INFO("level " << l);
    CHECK(is_clique(g, static_cast<int>(l), cascaded[l].vertices));
    CHECK(cascaded[l].vertices.size() >= independent[l].vertices.size());
    CHECK(cascaded[l].start == (l == 0                                       ? CliqueStart::cold
                                : cascaded[l].start == CliqueStart::fallback ? CliqueStart::fallback
                                                                             : CliqueStart::warm));
    if (cascaded[l].start == CliqueStart::fallback) {
      ++fallbacks;
      CHECK(cascaded[l].vertices == independent[l].vertices);  // the cold start's clique
    }
  }
  CHECK(fallbacks > 0);
}
#endif

#if defined(PAGOR_GEDI_DIR) && defined(PAGOR_HAVE_SEMREG_DATA)
// Pair 08: 730 correspondences of which 57 true; the matcher alone misses it, the landmarks of
// its class-poor clouds are few. Fused, both take part in the selected clique and the pose is
// right.
TEST_CASE("gedi-dev fused with the landmarks of the semreg-dev clouds") {
  const std::string pair = "08";
  const std::string clouds = std::string(PAGOR_SEMREG_DIR) + "/" + pair;
  const CorrespondenceFile input =
      read_correspondence_file(std::string(PAGOR_GEDI_DIR) + "/" + pair + ".txt");
  Config c = default_config();
  c.correspondences.fuse_matches = true;
  Pipeline p(c);
  p.set_matches(input.items);
  p.set_input(load_cloud(clouds + "/source.pcd").cloud, load_cloud(clouds + "/target.pcd").cloud);
  p.set_ground_truth(read_transform_file(std::string(PAGOR_GEDI_DIR) + "/" + pair + ".T.txt"));
  p.run();
  const OriginCounts all = count_by_origin(p.correspondences().items);
  CHECK(all.matcher == input.items.size());
  CHECK(all.landmark > 0);
  REQUIRE(p.selected_level() >= 0);
  REQUIRE(p.selected_error());
  CHECK(p.selected_error()->success);
  CHECK(p.acceptance().accepted);
  const auto sel = static_cast<std::size_t>(p.selected_level());
  const OriginCounts clique = count_by_origin(p.correspondences().items, p.cliques()[sel].vertices);
  CHECK(clique.landmark > 0);
  CHECK(clique.matcher > 0);
  CHECK(clique.landmark + clique.matcher == p.cliques()[sel].vertices.size());

  // The diagnosis and the report say the same per origin.
  const std::optional<Diagnosis> d = diagnose(p);
  REQUIRE(d);
  const LevelDiagnosis& l = d->levels[sel];
  CHECK(l.clique_origin.landmark == clique.landmark);
  CHECK(l.clique_origin.matcher == clique.matcher);
  CHECK(l.clique_true_origin.landmark > 0);
  CHECK(l.clique_true_origin.matcher > 0);
  CHECK(l.clique_true_origin.landmark + l.clique_true_origin.matcher == l.clique_true);
  CHECK(d->explanation.find("landmark") != std::string::npos);
  const auto report = nlohmann::json::parse(to_json(make_registration(p, {"s", "t"})));
  const auto& origin = report["correspondences"]["origin"];
  CHECK(origin["landmark"]["count"] == all.landmark);
  CHECK(origin["matcher"]["count"] == all.matcher);
  CHECK(origin["landmark"]["selected_clique"] == clique.landmark);
  CHECK(origin["matcher"]["selected_clique"] == clique.matcher);
  CHECK(report["diagnosis"]["levels"][sel]["origin"]["matcher"]["clique_true"] ==
        l.clique_true_origin.matcher);
}
#endif

TEST_CASE(
    "a pair's time budget stops the clique search with the best cliques so far, and says so") {
  // 3000 generated correspondences: building their graph alone takes longer than a 1 ms budget,
  // so every level of the clique search starts past the deadline.
  AssociationParams a;
  a.m = 3000;
  a.seed = 5;
  const AssociationProblem problem = association_problem(a);
  for (const CliqueSolver solver :
       {CliqueSolver::cascaded, CliqueSolver::independent, CliqueSolver::exact}) {
    INFO("solver " << to_string(solver));
    Config config = default_config();
    config.clique.solver = solver;
    config.clique.pair_time_budget_ms = 1;
    Pipeline p(config);
    p.set_matches(problem.correspondences);
    p.run();
    CHECK(p.pair_time_budget_hit());
    bool any_time = false;
    for (int l = 0; l < p.graph().levels(); ++l) {
      const CliqueResult& c = p.cliques()[static_cast<std::size_t>(l)];
      CHECK(is_clique(p.graph(), l, c.vertices));
      CHECK_FALSE(c.vertices.empty());  // at least the lower bound
      if (c.budget == CliqueBudget::time) CHECK_FALSE(c.proven);
      any_time |= c.budget == CliqueBudget::time;
    }
    CHECK(any_time);
    const auto w = p.warnings();
    CHECK(std::any_of(w.begin(), w.end(), [](const std::string& s) {
      return s.find("pair_time_budget_ms") != std::string::npos;
    }));
    const nlohmann::json j =
        nlohmann::json::parse(to_json(make_registration(p, {"matches", "matches"})));
    CHECK(j["pair_time_budget_hit"] == true);
  }
  // With the default budget the same problem finishes: nothing is cut short.
  Pipeline p(default_config());
  p.set_matches(problem.correspondences);
  p.run();
  CHECK_FALSE(p.pair_time_budget_hit());
  for (const CliqueResult& c : p.cliques()) CHECK(c.budget != CliqueBudget::time);
}
