// A matcher's correspondences in the studio (issue 22 item 6, issue 23 "a user's own files"):
// opened through the file browser, a drop, the recent list and the session; registered alone or
// verified on clouds, with the same figures as `pagor register --correspondences`; the 3D view
// shows them without clouds; an epsilon or mu change on a dense problem re-runs on the worker.

#include <imgui.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "pagor/io/correspondence_file.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/report.hpp"
#include "pagor/verify/diagnosis.hpp"
#include "panels/panels.hpp"
#include "panels/pyramid_chart.hpp"
#include "scene/scene_overlay.hpp"
#include "state/open_file.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

std::string gedi(const std::string& file) {
  return studio::absolute_path(shared_data() + "/gedi-dev/" + file);
}
std::string semreg(const std::string& file) {
  return studio::absolute_path(shared_data() + "/semreg-dev/" + file);
}

// As `pagor register --correspondences FILE [--source S --target T] --ground-truth G` runs it.
Pipeline cli_run(const std::string& file, const std::string& truth, bool clouds) {
  Pipeline p(default_config());
  p.set_matches(read_correspondence_file(file).items);
  if (clouds) {
    PairSource src;
    src.kind = PairSource::Kind::files;
    src.source = semreg("03/source.pcd");
    src.target = semreg("03/target.pcd");
    src.ground_truth = truth;
    LoadedPair pair = load_pair(src);
    p.set_input(std::move(pair.source.cloud), std::move(pair.target.cloud));
    p.set_ground_truth(pair.T_target_source_gt);
  } else {
    p.set_ground_truth(read_transform_file(truth));
  }
  p.run();
  return p;
}

// The studio's snapshot holds the CLI pipeline's figures.
void check_same(const studio::Snapshot& s, const Pipeline& p) {
  REQUIRE(s.levels.size() == p.cliques().size());
  CHECK(s.correspondences.size() == p.correspondences().items.size());
  CHECK(s.selected == p.selected_level());
  for (std::size_t l = 0; l < s.levels.size(); ++l) {
    CHECK(s.levels[l].clique == p.cliques()[l].vertices);
    // How each level's search ended, as the CLI reports it (proven, bound, budget, start).
    CHECK(s.levels[l].clique_proven == p.cliques()[l].proven);
    CHECK(s.levels[l].clique_number_bound == p.cliques()[l].clique_number_bound);
    CHECK(s.levels[l].clique_budget == p.cliques()[l].budget);
    CHECK(s.levels[l].clique_start == p.cliques()[l].start);
    CHECK(s.levels[l].pose.T_target_source.isApprox(p.poses()[l].T_target_source, 1e-12));
  }
  CHECK(s.acceptance.verified == p.acceptance().verified);
  CHECK(s.acceptance.accepted == p.acceptance().accepted);
  REQUIRE(s.selected_error.has_value() == p.selected_error().has_value());
  if (s.selected_error) {
    CHECK(s.selected_error->translation == Approx(p.selected_error()->translation));
    CHECK(s.selected_error->rotation_deg == Approx(p.selected_error()->rotation_deg));
    CHECK(s.selected_error->success == p.selected_error()->success);
  }
  CHECK(s.upper_bound == p.upper_bound_success());
}

studio::AppState empty_files_state(const TempDir& tmp) {
  studio::AppState s = base_state(tmp);
  s.data.kind = PairSource::Kind::files;
  s.have_data = false;
  return s;
}

// gedi-dev problem 03 alone (no clouds), with its ground truth when `truth`.
studio::AppState gedi_state(const TempDir& tmp, bool truth = true) {
  studio::AppState s = empty_files_state(tmp);
  s.data.correspondences = gedi("03.txt");
  if (truth) s.data.ground_truth = gedi("03.T.txt");
  s.have_data = true;
  return s;
}

}  // namespace

TEST_CASE("a correspondences file is told apart from pairs files and transforms") {
  CHECK(studio::classify_file(gedi("03.txt")) == studio::FilePurpose::correspondences);
  CHECK(studio::classify_file(gedi("03.T.txt")) == studio::FilePurpose::ground_truth);
}

TEST_CASE("a gedi-dev problem opened alone through the file browser: the back end as the CLI") {
  TempDir tmp;
  UiDriver d(empty_files_state(tmp), 1280, 800);
  d.frames(2);
  const auto* field = d.find("correspondences", "Pagor Studio");
  REQUIRE(field);
  ImGuiID browse = 0;  // the "..." beside the field
  for (const auto& w : d.widgets())
    if (w.label == "..." && std::abs(w.min.y - field->min.y) < 3) browse = w.id;
  REQUIRE(browse);
  REQUIRE(d.click_id(browse));
  CHECK(d.state().dialog.purpose == studio::FilePurpose::correspondences);
  // A directory that is not there is said, not listed as empty (found clicking through).
  d.state().dialog.directory = gedi("no-such-directory");
  d.frames(2);
  CHECK(d.state().dialog.listing_error.find("no such directory") != std::string::npos);
  d.state().dialog.directory = gedi("");
  d.frames(2);
  CHECK(d.state().dialog.listing_error.empty());
  CHECK(d.find("README.md##dialog") == nullptr);  // not a .txt: not listed
  REQUIRE(d.click_widget("03.txt##dialog"));
  REQUIRE(d.click_widget("open##dialog"));
  CHECK(d.state().data.correspondences == gedi("03.txt"));
  CHECK(d.state().recent.front() == gedi("03.txt"));
  // Its ground truth, dropped on the window.
  d.studio().open_files({gedi("03.T.txt")});
  CHECK(d.state().data.ground_truth == gedi("03.T.txt"));
  d.settle();
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(snap);
  CHECK(d.studio().worker().status().error.empty());
  CHECK_FALSE(snap->source);  // no clouds: nothing to verify on
  CHECK(snap->correspondences.size() == read_correspondence_file(gedi("03.txt")).items.size());
  CHECK(snap->description.find("03.txt") != std::string::npos);
  check_same(*snap, cli_run(gedi("03.txt"), gedi("03.T.txt"), false));
  CHECK_FALSE(snap->acceptance.verified);
  // The result in the CLI's schema names the file and each level's precision against its flags.
  const auto report = nlohmann::json::parse(snap->report_json);
  CHECK(report["correspondences"]["file"] == gedi("03.txt"));
  CHECK(report["correspondences"]["inlier_flags"] == true);
  CHECK(report["levels"][0].contains("precision"));
  // The 3D view has the correspondences' points to frame without clouds.
  Eigen::Vector3f lo, hi;
  CHECK(studio::shown_bounds(*snap, d.state().view, Transform::Identity(), lo, hi));
  CHECK((hi - lo).norm() > 10.0f);  // a KITTI scene, tens of metres
  d.frames(3);
  // Drawn without clouds (it said "nothing to show yet"), and not verified rather than rejected.
  CHECK(d.studio().scene().cloud_uploads() > 0);
  CHECK(studio::acceptance_text(*snap).rfind("not verified: ", 0) == 0);
  // The legend names what is drawn: the matcher's points, no "unlabelled points" of no cloud.
  const auto entries = studio::point_entries(*snap, d.state().view, studio::ClassColors(), {});
  const auto has = [&](const std::string& text) {
    return std::any_of(entries.begin(), entries.end(),
                       [&](const auto& e) { return e.second == text; });
  };
  CHECK(has("matcher's source points p"));
  CHECK(has("matcher's target points q"));
  CHECK_FALSE(has("unlabelled points"));
}

TEST_CASE("a matcher's clique stands out: members marked at both ends, the rest faint") {
  TempDir tmp;
  studio::AppState st = gedi_state(tmp);
  st.view.pose = studio::PoseShown::ground_truth;  // true members: lines of (almost) no length
  UiDriver d(st, 1280, 800);
  d.settle();
  d.frames(2);
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(snap);
  REQUIRE(snap->ground_truth);
  const int level = snap->selected;
  REQUIRE(level >= 0);
  const std::vector<int>& clique = snap->levels[static_cast<std::size_t>(level)].clique;
  REQUIRE(clique.size() >= 3);
  // The other matcher points are faint while the clique's lines are shown; all strong without.
  CHECK(d.studio().scene().faint_keypoints() == snap->correspondences.size() - clique.size());
  d.state().view.layers.correspondences = false;
  d.frames(2);
  CHECK(d.studio().scene().faint_keypoints() == 0);
  d.state().view.layers.correspondences = true;
  d.frames(2);

  // Drawn as the 3D view draws them, on a 600 px view of the scene, one member at a time: each
  // whose line is shorter than a pixel still shows a ring around its target point.
  studio::Camera camera;
  Eigen::Vector3f lo, hi;
  REQUIRE(studio::shown_bounds(*snap, d.state().view, *snap->ground_truth, lo, hi));
  camera.fit(lo, hi, 1.0f);
  studio::ViewRect r{ImVec2(0, 0), 600, 600, camera.projection(1.0f) * camera.view()};
  studio::Snapshot one = *snap;
  int short_lines = 0, ringed = 0;
  for (int v : clique) {
    const Correspondence& c = snap->correspondences[static_cast<std::size_t>(v)];
    Eigen::Vector2f a, b;
    REQUIRE(studio::project_to_screen(
        r.view_projection, studio::transform_point(*snap->ground_truth, c.p), 600, 600, a));
    REQUIRE(studio::project_to_screen(r.view_projection, c.q.cast<float>(), 600, 600, b));
    if ((a - b).norm() >= 1.0f) continue;
    ++short_lines;
    one.levels[static_cast<std::size_t>(level)].clique = {v};
    ImDrawList dl(ImGui::GetDrawListSharedData());
    dl._ResetForNewFrame();
    dl.PushClipRectFullScreen();
    REQUIRE(studio::draw_correspondence_lines(&dl, r, one, d.state().view, *snap->ground_truth,
                                              level, studio::ClassColors()) == 1);
    // A line alone reaches its half width and antialiasing from the point (under 3.5 px): a
    // vertex 4 to 8 px away is the ring's.
    bool ring = false;
    for (const ImDrawVert& vert : dl.VtxBuffer) {
      const float dist = (Eigen::Vector2f(vert.pos.x, vert.pos.y) - b).norm();
      ring = ring || (dist >= 4.0f && dist <= 8.0f);
    }
    ringed += ring;
  }
  CHECK(short_lines > 0);
  CHECK(ringed == short_lines);
}

TEST_CASE("a gedi-dev problem verified on its clouds equals the CLI, and the session keeps it") {
  TempDir tmp;
  UiDriver d(empty_files_state(tmp), 1280, 800);
  d.frames(2);
  // Dropped together: the correspondences, both clouds and the ground truth.
  d.studio().open_files({gedi("03.txt"), semreg("03/source.pcd"), semreg("03/target.pcd"),
                         semreg("03/T_target_source.txt")});
  CHECK(d.state().data.correspondences == gedi("03.txt"));
  CHECK(d.state().data.source == semreg("03/source.pcd"));
  d.settle();
  auto snap = d.studio().worker().snapshot();
  REQUIRE(snap);
  REQUIRE(snap->source);
  CHECK(snap->verification_points > 0);
  CHECK(snap->acceptance.verified);
  check_same(*snap, cli_run(gedi("03.txt"), semreg("03/T_target_source.txt"), true));
  // Saved and restored: the correspondences come back with the clouds.
  d.studio().save_session_now();
  studio::AppState restored;
  studio::load_session(d.state().session_path, restored);
  CHECK(restored.data.correspondences == gedi("03.txt"));
  CHECK(restored.data.source == semreg("03/source.pcd"));
  // Another mode drops nothing of files mode, but does not register the correspondences.
  d.state().data.kind = PairSource::Kind::synthetic;
  CHECK(studio::resolved_data(d.state()).correspondences.empty());
}

TEST_CASE("a correspondences file from the recent list and after clouds: a fresh pipeline") {
  TempDir tmp;
  UiDriver d(files_state(tmp), 1024, 700);
  d.settle();
  REQUIRE(d.studio().worker().snapshot()->source);
  // Files mode with clouds, then correspondences alone: no cloud of the old pair verifies them.
  d.state().data.source.clear();
  d.studio().open_file(gedi("04.txt"), studio::FilePurpose::any);
  d.settle();
  auto snap = d.studio().worker().snapshot();
  CHECK_FALSE(snap->source);
  CHECK_FALSE(snap->acceptance.verified);
  CHECK(snap->verification_points == 0);
  // A cloud pair again (the correspondences verified on it), then 04 from the recent list.
  d.studio().open_file(semreg("03/source.pcd"), studio::FilePurpose::source_cloud);
  d.settle();
  CHECK(d.studio().worker().snapshot()->source);
  d.studio().open_file(gedi("03.txt"), studio::FilePurpose::any);
  d.settle();
  CHECK(d.studio().worker().snapshot()->description.find("03.txt") != std::string::npos);
  const auto& recent = d.state().recent;  // newest first: 03.txt, source.pcd, 04.txt, ...
  const auto at = std::find(recent.begin(), recent.end(), gedi("04.txt"));
  REQUIRE(at != recent.end());
  const std::string item = gedi("04.txt") + "##recent" + std::to_string(at - recent.begin());
  REQUIRE(d.click_widget("recent files", "Pagor Studio"));
  REQUIRE(d.click_widget(item));
  CHECK(d.state().data.correspondences == gedi("04.txt"));
  d.settle();
  snap = d.studio().worker().snapshot();
  CHECK(snap->description.find("04.txt") != std::string::npos);
  CHECK(snap->correspondences.size() == read_correspondence_file(gedi("04.txt")).items.size());
}

TEST_CASE("an epsilon or mu change on gedi-dev 03 re-runs on the worker (latency in the log)") {
  const bool truth = GENERATE(false, true);  // with a ground truth the diagnosis runs too
  std::printf("gedi-dev 03 %s ground truth:\n", truth ? "with" : "without");
  TempDir tmp;
  studio::AppState s = gedi_state(tmp, truth);
  UiDriver d(std::move(s), 1024, 700);
  d.settle();
  REQUIRE(d.studio().worker().snapshot());
  const auto change = [&](const char* what, auto&& edit) {
    edit(d.state().config);
    const auto t0 = std::chrono::steady_clock::now();
    d.studio().submit_config();
    const std::uint64_t id = d.studio().worker().status().submitted;
    while (d.studio().worker().snapshot()->request != id) {
      REQUIRE(d.studio().worker().status().error.empty());
      d.studio().worker().wait_idle(0.001);
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const auto& t = d.studio().worker().snapshot()->stage_ms;
    const auto at = [&](Stage st) { return t[static_cast<std::size_t>(st)]; };
    std::printf(
        "gedi-dev 03, %s: new snapshot after %.1f ms (graph %.1f, clique %.1f, gnc %.1f "
        "ms)\n",
        what, ms, at(Stage::graph), at(Stage::clique), at(Stage::gnc));
    d.frames(1);
  };
  const auto before = d.studio().worker().snapshot();
  change("epsilon of level 3 x1.1", [](Config& c) { c.graph.thresholds[3] *= 1.1; });
  auto after = d.studio().worker().snapshot();
  CHECK(after->config.graph.thresholds[3] == Approx(before->config.graph.thresholds[3] * 1.1));
  CHECK(after->stage_ran[static_cast<int>(Stage::graph)]);
  change("mu x2", [](Config& c) { c.verification.mu *= 2; });
  after = d.studio().worker().snapshot();
  CHECK(after->config.verification.mu == Approx(before->config.verification.mu * 2));
  CHECK_FALSE(after->stage_ran[static_cast<int>(Stage::graph)]);  // mu re-runs no graph
  // A newer change cancels an older run: two at once end in the second's result.
  d.state().config.graph.thresholds[3] = before->config.graph.thresholds[3];
  d.studio().submit_config();
  d.state().config.graph.thresholds[2] *= 1.05;
  d.studio().submit_config();
  d.settle();
  after = d.studio().worker().snapshot();
  CHECK(after->request == d.studio().worker().status().submitted);
  CHECK(after->config.graph.thresholds[2] == Approx(before->config.graph.thresholds[2] * 1.05));
  CHECK(after->config.graph.thresholds[3] == Approx(before->config.graph.thresholds[3]));
  // The same with the levels solved independently (issue 22: the cascade is the slow part).
  d.state().config.clique.solver = CliqueSolver::independent;
  d.studio().submit_config();
  d.settle();
  change("epsilon of level 3 x1.1, independent levels",
         [](Config& c) { c.graph.thresholds[3] *= 1.1; });
  CHECK(d.studio().worker().snapshot()->stage_ran[static_cast<int>(Stage::clique)]);
}

TEST_CASE("diagnosis of a correspondences file without clouds: no D, the rule named, as the CLI") {
  TempDir tmp;
  studio::AppState s = gedi_state(tmp);
  s.view.diagnosis.panel = true;
  UiDriver d(std::move(s), 1400, 900);
  d.settle();
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(snap);
  REQUIRE_FALSE(snap->source);
  REQUIRE(snap->diagnosis);
  // The CLI's figures: pagor register --correspondences 03.txt --ground-truth 03.T.txt --json.
  const Pipeline p = cli_run(gedi("03.txt"), gedi("03.T.txt"), false);
  const auto cli = diagnose(p);
  REQUIRE(cli);
  const CorrespondenceFile file = read_correspondence_file(gedi("03.txt"));
  std::size_t flagged = 0;
  for (char f : file.inlier) flagged += f != 0;
  REQUIRE(flagged > 0);
  const auto report = nlohmann::json::parse(snap->report_json);
  CHECK(report["correspondences"]["flagged_inliers"] == flagged);
  CHECK(report["diagnosis"]["true_correspondences"] == cli->true_correspondences);
  CHECK(snap->diagnosis->true_correspondences == cli->true_correspondences);
  d.frames(2);
  const std::string win = "Diagnosis";
  // The selection rule the core used (S, not D), no "lowest D", no D of anything.
  CHECK_FALSE(d.texts("* selected (lowest S = sum of min(residual, noise bound)", win).empty());
  CHECK(d.texts("lowest D", win).empty());
  CHECK_FALSE(d.texts("n/a without clouds", win).empty());
  CHECK(d.texts("D of the truth", win).empty());
  CHECK(d.texts("inf", win).empty());
  // One n/a in the D column per level, and the truth's row.
  CHECK(d.texts("n/a", win).size() >= snap->levels.size() + 1);
  for (const std::string& t : d.texts("invalid", win)) FAIL_CHECK("an invalid D: " << t);
  // The file's own inlier count beside the diagnosis' rule, both as the CLI reports them.
  const std::string line = "the file flags " + std::to_string(flagged) + " of " +
                           std::to_string(file.items.size()) + " as inliers (its own rule); " +
                           std::to_string(cli->true_correspondences) + " are within 2 m";
  CHECK_FALSE(d.texts(line, win).empty());
  CHECK_FALSE(d.texts("Front end (true: residual <= 2 m)", win).empty());
  // The pyramid names the same rule.
  d.state().view.diagnosis.panel = false;
  d.frames(2);
  CHECK_FALSE(
      d.texts("* selected: lowest S = sum of min(residual, noise bound)", "Pyramid").empty());
  // The status bar lists what ran; the stages with nothing to do without clouds apart.
  const std::string stages = studio::run_stages_text(*snap);
  const std::string ran = stages.substr(0, stages.find(';'));
  CHECK(ran.find("graph") != std::string::npos);
  CHECK(ran.find("selection by S (no clouds)") != std::string::npos);
  for (const char* skipped : {"landmarks", "verification_prep", "refinement", "acceptance"}) {
    INFO(stages);
    CHECK(ran.find(skipped) == std::string::npos);
    CHECK(stages.find(skipped, ran.size()) != std::string::npos);
  }
  CHECK(stages.find("; skipped without clouds: ") != std::string::npos);
  CHECK_FALSE(d.texts("ready | " + stages, "##status").empty());
}
