// The user's own files in the studio: the file browser, drops on the window, the recent list and
// what each kind of file opens as; copying and exporting results; picking points; colouring by
// height, intensity and residual.

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "pagor/errors.hpp"
#include "panels/exports.hpp"
#include "scene/cloud_colors.hpp"
#include "scene/picking.hpp"
#include "scene/scene_view.hpp"
#include "state/open_file.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"
#include "widgets/plot.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

std::string semreg(const std::string& file) {
  return studio::absolute_path(shared_data() + "/semreg-dev/" + file);
}

}  // namespace

TEST_CASE("the file browser opens a cloud for the field it was opened from, and remembers it") {
  TempDir tmp;
  UiDriver d(files_state(tmp), 1280, 800);
  d.settle();
  const auto* field = d.find("source cloud", "Pagor Studio");
  REQUIRE(field);
  // The "..." beside the field (same line).
  ImGuiID browse = 0;
  for (const auto& w : d.widgets())
    if (w.label == "..." && std::abs(w.min.y - field->min.y) < 3) browse = w.id;
  REQUIRE(browse);
  REQUIRE(d.click_id(browse));
  CHECK(d.state().dialog.open);
  CHECK(d.state().dialog.purpose == studio::FilePurpose::source_cloud);
  CHECK(d.state().dialog.name == "source.pcd");  // the current file, in its directory
  d.state().dialog.directory = semreg("05");
  d.frames(2);
  CHECK(d.find("T_target_source.txt##dialog") == nullptr);  // not a cloud: not listed
  REQUIRE(d.click_widget("source.pcd##dialog"));
  REQUIRE(d.click_widget("open##dialog"));
  CHECK_FALSE(d.state().dialog.open);
  CHECK(d.state().data.source == semreg("05/source.pcd"));
  REQUIRE_FALSE(d.state().recent.empty());
  CHECK(d.state().recent.front() == semreg("05/source.pcd"));
  d.settle();
  CHECK(d.studio().worker().snapshot()->description.find("05/source.pcd") != std::string::npos);
}

TEST_CASE("files dropped on the window open by their kind: clouds, truth, configuration") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 1024, 700);
  d.settle();
  d.studio().open_files({semreg("04/source.pcd"), semreg("04/target.pcd"),
                         semreg("04/T_target_source.txt"),
                         PAGOR_SOURCE_DIR "/bench/manifests/semreg-dev.json"});
  CHECK(d.state().data.kind == PairSource::Kind::files);
  CHECK(d.state().data.source == semreg("04/source.pcd"));
  CHECK(d.state().data.target == semreg("04/target.pcd"));
  CHECK(d.state().data.ground_truth == semreg("04/T_target_source.txt"));
  CHECK(d.state().config.label_scheme.name == "semantickitti-learning");
  CHECK(d.state().recent.size() == 4);
  d.settle();
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(snap->ground_truth);
  CHECK(*snap->ground_truth == read_transform_file(semreg("04/T_target_source.txt")));
  // A file that cannot be opened is said, the others still open.
  d.studio().open_files({tmp.file("nothere.pcd"), semreg("05/T_target_source.txt")});
  CHECK(d.state().message.level == studio::MessageLevel::error);
  CHECK(d.state().message.text.find("nothere.pcd") != std::string::npos);
  CHECK(d.state().data.ground_truth == semreg("05/T_target_source.txt"));
}

TEST_CASE("what a file opens as: told by its extension and first lines") {
  TempDir tmp;
  using P = studio::FilePurpose;
  CHECK(studio::classify_file(semreg("03/source.pcd")) == P::source_cloud);
  CHECK(studio::classify_file(semreg("03/T_target_source.txt")) == P::ground_truth);
  CHECK(studio::classify_file(PAGOR_SOURCE_DIR "/tests/studio/bench_pairs.txt") == P::pairs);
  CHECK(studio::classify_file(PAGOR_KITTI_DIR "/pairs_00_dev.txt") == P::pairs);
  CHECK(studio::classify_file(PAGOR_SOURCE_DIR "/tests/studio/kitti_20_30.json") == P::session);
  CHECK(studio::classify_file(PAGOR_SOURCE_DIR "/bench/manifests/semreg-dev.json") == P::config);
  CHECK(studio::classify_file(PAGOR_SOURCE_DIR "/tests/data/indoor/plan.json") == P::target_cloud);
  std::ofstream(tmp.file("r.jsonl")) << "{}\n";
  CHECK(studio::classify_file(tmp.file("r.jsonl")) == P::bench);
  std::ofstream(tmp.file("corr.txt")) << "1 2 3 4 5 6\n";
  CHECK(studio::classify_file(tmp.file("corr.txt")) == P::correspondences);  // a matcher's
  CHECK_THROWS_WITH(studio::classify_file(tmp.file("none.pcd")), Catch::Contains("no such file"));
#ifdef PAGOR_HAVE_KITTI
  CHECK(studio::classify_file(PAGOR_KITTI_DIR) == P::kitti_root);
#endif
  // Every purpose has its own name in the file browser (a purpose missing from the table would
  // read "a file", as `any` does).
  std::set<std::string> names;
  for (int i = 0; i <= static_cast<int>(P::kitti_root); ++i)
    names.insert(studio::purpose_name(static_cast<P>(i)));
  CHECK(names.size() == static_cast<std::size_t>(P::kitti_root) + 1);
  CHECK(studio::purpose_extensions(P::source_cloud) ==
        std::vector<std::string>{".pcd", ".ply", ".bin"});
  // A pairs file of nothing but comments, and one that is not there: said as such.
  std::ofstream(tmp.file("comments.txt")) << "# source target\n\n  # none yet\n";
  CHECK_THROWS_WITH(studio::read_step_pairs(tmp.file("comments.txt"), "", "00"),
                    Catch::Contains("the pairs file has nothing but blank lines and comments"));
  CHECK_THROWS_WITH(studio::read_step_pairs(tmp.file("absent.txt"), "", "00"),
                    Catch::Contains("cannot open the pairs file"));
  // A KITTI pairs file read without a root (the current directory's sequences/ is not there).
  std::ofstream(tmp.file("kitti_pairs.txt")) << "0 20\n";
  CHECK_THROWS_WITH(studio::read_step_pairs(tmp.file("kitti_pairs.txt"), "", "00"),
                    Catch::Contains("is a KITTI pairs file: it needs the KITTI root"));
}

#ifdef PAGOR_HAVE_KITTI
TEST_CASE("copy and export: the pose, the result JSON, the levels table") {
  TempDir tmp;
  studio::AppState s = kitti_state(tmp);
  s.export_path = tmp.file("out");  // the pair view's (the benchmark view has its own)
  UiDriver d(s, 1400, 900);
  d.settle();
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(snap->selected >= 0);
  const nlohmann::json report = nlohmann::json::parse(snap->report_json);
  Transform T;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) T(r, c) = report["T_target_source"][r][c].get<double>();
  REQUIRE(d.click_widget("copy pose 4x4", "Pyramid"));
  std::istringstream text(ImGui::GetClipboardText());
  Transform copied;
  for (int i = 0; i < 16; ++i) text >> copied(i / 4, i % 4);
  CHECK(copied == T);  // exact: every digit of the double
  REQUIRE(d.click_widget("copy pose JSON", "Pyramid"));
  const auto pose = nlohmann::json::parse(ImGui::GetClipboardText());
  CHECK(pose["T_target_source"] == report["T_target_source"]);
  CHECK(pose["level"] == snap->selected);
  REQUIRE(d.click_widget("copy result JSON", "Pyramid"));
  CHECK(std::string(ImGui::GetClipboardText()) == snap->report_json);
  REQUIRE(d.click_widget("save result JSON", "Pyramid"));
  std::ifstream saved(tmp.file("out-result.json"));
  CHECK(nlohmann::json::parse(saved) == report);
  REQUIRE(d.click_widget("levels CSV", "Pyramid"));
  std::ifstream csv(tmp.file("out-levels.csv"));
  std::string line;
  int lines = 0;
  while (std::getline(csv, line)) ++lines;
  CHECK(lines == 1 + static_cast<int>(snap->levels.size()));
  // A plot as SVG: the same drawing, its title and tick labels as text.
  studio::Plot p;
  p.title = "Rates & more";
  p.categories = {"success"};
  p.value_unit = "%";
  p.series = {{"this run", {}, {75.0}}};
  const std::string svg = studio::plot_svg(p, 480, 300, 15.0f);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"480\"") != std::string::npos);
  CHECK(svg.find(">Rates &amp; more</text>") != std::string::npos);
  CHECK(svg.find(">success</text>") != std::string::npos);
  CHECK(svg.find("</svg>") != std::string::npos);
}

TEST_CASE("picking: the point drawn nearest the click, its facts, and the distance of two") {
  TempDir tmp;
  studio::AppState s = kitti_state(tmp);
  s.view.layers.source = s.view.layers.target = true;
  s.view.layers.landmarks = s.view.layers.correspondences = false;
  UiDriver d(s, 1200, 800);
  d.settle();
  d.frames(2);
  const auto snap = d.studio().worker().snapshot();
  ImVec2 a, b;
  REQUIRE(d.scene_rect(a, b));
  const float w = std::floor(b.x - a.x), h = std::floor(b.y - a.y);  // as the view sizes itself
  const studio::Camera& cam = d.state().camera;
  const Eigen::Matrix4f vp = cam.projection(w / h) * cam.view();
  const Transform pose = studio::shown_source_pose(d.state().view, *snap);
  // Click the screen position of a target point near the view's centre.
  const auto screen = [&](const Eigen::Vector3f& p, Eigen::Vector2f& px) {
    return studio::project_to_screen(vp, p, w, h, px) && px.x() > 20 && px.y() > 20 &&
           px.x() < w - 20 && px.y() < h - 20;
  };
  Eigen::Vector2f at;
  std::size_t k = 0;
  for (; k < snap->target->size(); k += 97)
    if (screen(snap->target->points[k], at)) break;
  REQUIRE(k < snap->target->size());
  // ImGui floors the mouse position: the click is at whole pixels.
  const auto floored = [&](Eigen::Vector2f& p) {
    p = Eigen::Vector2f(std::floor(a.x + p.x()) - a.x, std::floor(a.y + p.y()) - a.y);
  };
  floored(at);
  d.click(ImVec2(a.x + at.x(), a.y + at.y()));
  REQUIRE(d.state().picks.size() == 1);
  const studio::Pick p1 = d.state().picks[0];
  // Brute force: no drawn point is nearer the click on screen.
  const auto check_nearest = [&](const studio::Pick& p, const Eigen::Vector2f& click) {
    const PointCloud& c = p.source ? *snap->source : *snap->target;
    Eigen::Vector2f px;
    const Eigen::Matrix4f m = p.source ? Eigen::Matrix4f(vp * pose.cast<float>()) : vp;
    REQUIRE(studio::project_to_screen(m, c.points[p.index], w, h, px));
    const float mine = (px - click).norm();
    CHECK(mine <= 8.0f);  // within the pick radius
    CHECK(p.raw == c.points[p.index]);
    int nearer = 0;
    float closest = HUGE_VALF;
    for (const bool src : {false, true}) {
      const PointCloud& o = src ? *snap->source : *snap->target;
      const Eigen::Matrix4f mo = src ? Eigen::Matrix4f(vp * pose.cast<float>()) : vp;
      for (std::size_t i = 0; i < o.size(); ++i)
        if (studio::project_to_screen(mo, o.points[i], w, h, px)) {
          closest = std::min(closest, (px - click).norm());
          nearer += (px - click).norm() < mine - 1e-3f;
        }
    }
    INFO("picked at " << mine << " px from the click, the nearest at " << closest);
    CHECK(nearer == 0);
  };
  check_nearest(p1, at);
  if (!p1.source) CHECK(p1.at == p1.raw);
  // In the scheme the picked cloud's labels were read with (`auto`: the one detected for it).
  CHECK(p1.class_name ==
        studio::class_of_label(p1.source ? snap->source_landmarks.labels.scheme
                                         : snap->target_landmarks.labels.scheme,
                               (p1.source ? *snap->source : *snap->target).labels[p1.index]));
  CHECK_FALSE(p1.class_name.empty());
  // Shift+click a source point: its distance to the nearest target point, and the pair's.
  std::size_t j = 0;
  for (; j < snap->source->size(); j += 89)
    if (screen(studio::transform_point(pose, snap->source->points[j].cast<double>()), at)) break;
  REQUIRE(j < snap->source->size());
  floored(at);
  d.set_modifiers(false, true);
  d.click(ImVec2(a.x + at.x(), a.y + at.y()));
  d.set_modifiers(false, false);
  REQUIRE(d.state().picks.size() == 2);
  const studio::Pick p2 = d.state().picks[1];
  check_nearest(p2, at);
  if (p2.source) {
    float nearest = HUGE_VALF;
    for (const Eigen::Vector3f& q : snap->target->points)
      nearest = std::min(nearest, (q - p2.at).norm());
    CHECK(p2.nearest_target == Approx(nearest).margin(1e-4));
  }
  CHECK(studio::pick_distance(p1, p2) == Approx((p1.at - p2.at).norm()));
  // A click on nothing clears the picks.
  d.click(ImVec2(a.x + 3, a.y + 3));
  CHECK(d.state().picks.empty());
}

TEST_CASE("colour by height, intensity and residual: the legend's scale is the one drawn") {
  TempDir tmp;
  studio::AppState s = kitti_state(tmp);
  s.view.layers.source = s.view.layers.target = true;
  UiDriver d(s, 1000, 700);
  d.settle();
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(d.click_widget("height", "Pagor Studio"));
  d.frames(2);
  const studio::ColorScale hs = studio::height_scale(*snap);
  CHECK(d.studio().scene().color_scale().title == "height z [m]");
  CHECK(d.studio().scene().color_scale().lo == hs.lo);
  CHECK(d.studio().scene().color_scale().hi == hs.hi);
  CHECK(hs.lo < hs.hi);
  REQUIRE(d.click_widget("intensity", "Pagor Studio"));
  d.frames(2);
  CHECK(d.studio().scene().color_scale().valid);  // KITTI scans carry their reflectance
  CHECK(d.studio().scene().color_scale().hi > 0);
  REQUIRE(d.click_widget("residual", "Pagor Studio"));
  d.frames(2);
  CHECK(studio::shown_contribution(d.state().view) == studio::Contribution::candidate);
}
#endif

namespace {

// Whether ImGui shows a tooltip this frame.
bool tooltip_shown() {
  for (ImGuiWindow* w : GImGui->Windows)
    if (std::string(w->Name).rfind("##Tooltip", 0) == 0 && w->Active) return true;
  return false;
}

}  // namespace

TEST_CASE("exports of a stale result are disabled, saying why; the pair view has its own path") {
  TempDir tmp;
  studio::AppState s = synthetic_state(tmp);
  s.export_path = tmp.file("pair");
  s.bench.plot_path = tmp.file("bench");
  UiDriver d(s, 1400, 900);
  d.settle();
  const char* const buttons[] = {"copy pose 4x4", "copy pose JSON", "copy result JSON",
                                 "save result JSON", "levels CSV"};
  const auto check_buttons = [&](bool enabled) {
    for (const char* b : buttons) {
      INFO(b);
      const auto* w = d.find(b, "Pyramid");
      REQUIRE(w);
      CHECK(w->enabled == enabled);
      CHECK(w->has_tooltip);
    }
  };
  check_buttons(true);
  // The parameters change; the result shown is of the run before.
  d.state().config.verification.mu = 3.0;
  d.frame();
  REQUIRE_FALSE(d.studio().stale_reason().empty());
  check_buttons(false);
  ImGui::SetClipboardText("untouched");
  for (const char* b : buttons) REQUIRE(d.click_widget(b, "Pyramid"));
  CHECK(std::string(ImGui::GetClipboardText()) == "untouched");
  CHECK_FALSE(std::filesystem::exists(tmp.file("pair-result.json")));
  CHECK_FALSE(std::filesystem::exists(tmp.file("pair-levels.csv")));
  // Hovered, the disabled button says why.
  const auto* copy = d.find("copy pose 4x4", "Pyramid");
  d.move(ImVec2((copy->min.x + copy->max.x) * 0.5f, (copy->min.y + copy->max.y) * 0.5f));
  d.frames(2);
  CHECK(tooltip_shown());
  // While the new run is pending, still disabled; once it is in, the new pose is copied.
  d.studio().submit_config();
  d.frame();
  if (!d.studio().stale_reason().empty()) check_buttons(false);
  d.settle();
  CHECK(d.studio().stale_reason().empty());
  check_buttons(true);
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(snap->config.verification.mu == 3.0);
  REQUIRE(d.click_widget("copy result JSON", "Pyramid"));
  CHECK(std::string(ImGui::GetClipboardText()) == snap->report_json);
  // The pair view writes to its own export path, not the benchmark view's.
  REQUIRE(d.click_widget("save result JSON", "Pyramid"));
  CHECK(std::filesystem::exists(tmp.file("pair-result.json")));
  CHECK_FALSE(std::filesystem::exists(tmp.file("bench-result.json")));
  // The same for the diagnosis table (the synthetic scene has a ground truth).
  d.state().view.diagnosis.panel = true;
  d.frames(2);
  const auto* csv = d.find("diagnosis CSV", "Diagnosis");
  REQUIRE(csv);
  CHECK(csv->enabled);
  d.state().config.verification.mu = 2.0;
  d.frame();
  csv = d.find("diagnosis CSV", "Diagnosis");
  REQUIRE(csv);
  CHECK_FALSE(csv->enabled);
  // The export path is kept in the session.
  d.studio().save_session_now();
  studio::AppState loaded;
  studio::load_session(d.state().session_path, loaded);
  CHECK(loaded.export_path == tmp.file("pair"));
}

TEST_CASE("a file that fails to open leaves the recent list; the list's label is not cut") {
  TempDir tmp;
  studio::AppState s = synthetic_state(tmp);
  s.recent_file = tmp.file("recent.txt");
  UiDriver d(s, 1024, 700);
  d.settle();
  // Opened once, then gone: picked again, it fails and is dropped.
  std::filesystem::copy_file(semreg("03/T_target_source.txt"), tmp.file("gt.txt"));
  d.studio().open_file(tmp.file("gt.txt"), studio::FilePurpose::any);
  REQUIRE(d.state().recent.size() == 1);
  std::filesystem::remove(tmp.file("gt.txt"));
  d.studio().open_file(tmp.file("gt.txt"), studio::FilePurpose::any);
  CHECK(d.state().message.level == studio::MessageLevel::error);
  CHECK(d.state().message.text.find("dropped from the recent files") != std::string::npos);
  CHECK(d.state().recent.empty());
  studio::AppState reread;
  reread.recent_file = s.recent_file;
  studio::load_recent_files(reread);
  CHECK(reread.recent.empty());  // and from the list kept between runs
  // A cloud that exists but cannot be read: the worker fails on it, and it is dropped too.
  std::ofstream(tmp.file("broken.pcd")) << "not a point cloud\n";
  d.studio().open_file(semreg("03/target.pcd"), studio::FilePurpose::target_cloud);
  d.studio().open_file(tmp.file("broken.pcd"), studio::FilePurpose::source_cloud);
  d.settle();
  CHECK_FALSE(d.studio().worker().status().error.empty());
  const auto& recent = d.state().recent;
  CHECK(std::find(recent.begin(), recent.end(), tmp.file("broken.pcd")) == recent.end());
  CHECK(std::find(recent.begin(), recent.end(), semreg("03/target.pcd")) != recent.end());
  // The combo's preview fits its frame (it was cut beside the "open a file..." button).
  d.frames(2);
  const auto* combo = d.find("recent files", "Pagor Studio");
  REQUIRE(combo);
  const ImGuiStyle& style = ImGui::GetStyle();
  CHECK(ImGui::CalcTextSize(combo->text.c_str()).x + ImGui::GetFrameHeight() +
            2 * style.FramePadding.x <=
        combo->frame_w);
  CHECK(combo->max.x <= combo->clip_max.x + 0.5f);
}
