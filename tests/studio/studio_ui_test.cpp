// Driven-UI tests: the real studio, headless, driven through ImGui's input like a user would.

#include <imgui_internal.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "panels/panels.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"

using namespace pagor;
using namespace pagor::test;
using studio::ui::WidgetKind;

namespace {

// Exercises every widget while staying in `mode` (a radio of another mode is clicked too; the
// driver then goes back) and reports the coverage.
void exercise_mode(UiDriver& d, PairSource::Kind mode, const char* radio,
                   bool every_parameter = false) {
  d.settle();
  // Open the closed sections first so their widgets are part of the walk.
  for (const char* header : {"History", "Session"}) REQUIRE(d.click_widget(header));
  const int acted = exercise_every_widget(
      d,
      [&] {
        if (d.state().data.kind != mode) d.click_widget(radio);
        hide_clouds(d.state());
        d.state().dialog.open = false;  // the file browser has a test of its own
        if (d.state().show_help) d.click_widget("close##help");
      },
      900, "",
      every_parameter ? std::function<bool(const studio::ui::WidgetRecord&)>()
                      : skip_parameter_sections);
  d.settle();
  // Every kind of widget was met, and the walk stayed in the mode under test.
  std::set<WidgetKind> kinds;
  for (const auto& w : d.widgets()) kinds.insert(w.kind);
  CHECK(d.state().data.kind == mode);
  CHECK(acted >= 60);
  CHECK(d.touched().size() >= 60);
  WARN("widgets acted on: " << acted << ", distinct widgets touched: " << d.touched().size()
                            << ", events: " << d.events() << ", frames: " << d.frame_count());
}

}  // namespace

TEST_CASE("files mode: typing a path and toggling the same-named layer works (was an abort)") {
  TempDir tmp;
  UiDriver d(files_state(tmp));
  d.settle();
  const auto* field = d.find("source cloud", "Pagor Studio");
  REQUIRE(field);
  const ImGuiID field_id = field->id;
  REQUIRE(d.type_into(field_id, U"/tmp/nope.pcd"));
  CHECK(d.state().data.source == "/tmp/nope.pcd");
  const bool before = d.state().view.layers.source;
  REQUIRE(d.click_widget("source", "Pagor Studio"));
  CHECK(d.state().view.layers.source == !before);
  // The field keeps working after the checkbox.
  REQUIRE(d.type_into(field_id, U"/tmp/again.pcd"));
  CHECK(d.state().data.source == "/tmp/again.pcd");
  // Opening a missing file is an error in the status bar, not a crash.
  REQUIRE(d.click_widget("Open", "Pagor Studio"));
  d.settle();
  CHECK(d.studio().worker().status().error.find("/tmp/again.pcd") != std::string::npos);
}

TEST_CASE("every widget of every panel in synthetic mode and every parameter of the catalog") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp));
  // The synthetic scene runs fastest: the walk goes through every parameter of the catalog here.
  exercise_mode(d, PairSource::Kind::synthetic, "synthetic", true);
  CHECK(d.touched().size() >= 200);
}

TEST_CASE("every widget of every panel in files mode (semreg-dev pair 03)") {
  TempDir tmp;
  UiDriver d(files_state(tmp));
  exercise_mode(d, PairSource::Kind::files, "files");
}

#ifdef PAGOR_HAVE_KITTI
TEST_CASE("every widget of every panel in KITTI mode") {
  TempDir tmp;
  UiDriver d(kitti_state(tmp));
  exercise_mode(d, PairSource::Kind::kitti, "KITTI");
}

TEST_CASE("stepping through pairs while a run is in progress") {
  TempDir tmp;
  UiDriver d(kitti_state(tmp));
  d.settle();
  REQUIRE(d.state().pairs.pairs.size() == 3);
  // A parameter change starts a run; step while it computes, with keys and the arrow buttons.
  d.state().config.verification.mu = 1.5;
  d.studio().submit_config();
  REQUIRE(d.state().pair_index == 1);
  d.press_key(keys::Right);
  CHECK(d.state().pair_index == 2);
  d.press_key(keys::Right);  // past the end: stays at the last pair
  CHECK(d.state().pair_index == 2);
  d.press_key(keys::Left);
  CHECK(d.state().pair_index == 1);
  REQUIRE(d.click_widget("##next", "Pagor Studio"));
  REQUIRE(d.click_widget("##next", "Pagor Studio"));  // past the end: stays at the last pair
  d.settle();
  const PairSource& last = d.state().pairs.pairs.back().source;
  CHECK(d.state().pair_index == 2);
  CHECK(d.state().data.source_frame == last.source_frame);
  CHECK(d.state().data.target_frame == last.target_frame);
  REQUIRE(d.studio().worker().snapshot());
  CHECK(d.studio().worker().snapshot()->description.find(
            std::to_string(last.source_frame) + " -> " + std::to_string(last.target_frame)) !=
        std::string::npos);
  CHECK(d.studio().worker().status().error.empty());
  d.press_key(keys::Left);
  d.settle();
  CHECK(d.state().pair_index == 1);
}
#endif

TEST_CASE("window sizes from 320x240 to 2560x1440 keep the layout inside the window") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 800, 600);
  d.settle();
  for (auto [w, h] : {std::pair{640, 480},
                      {2560, 1440},
                      {800, 600},
                      {1920, 1080},
                      {320, 240},
                      {1280, 720},
                      {1024, 768}}) {
    d.resize(w, h);
    d.frames(3);
    const float left = d.state().layout.left_width;
    INFO("window " << w << "x" << h);
    // The left panel leaves room for the view; the view and the pyramid panel exist.
    ImVec2 a, b;
    REQUIRE(d.scene_rect(a, b));
    CHECK(b.x <= w + 0.5f);
    CHECK(b.y <= h + 0.5f);
    CHECK(a.x >= std::min(left, std::max(180.0f, 0.45f * w)) - 0.5f);
    CHECK(b.x - a.x >= std::min(0.5f * w, w - 186.0f) - 1.0f);
    const auto* split = d.find("##left_splitter");
    REQUIRE(split);
    CHECK(split->max.x <= w);
    // Splitters still move at this size, and the layout stays in range.
    d.drag(ImVec2((split->min.x + split->max.x) / 2, h / 2.0f),
           ImVec2((split->min.x + split->max.x) / 2 + 50, h / 2.0f));
    d.frames(1);
    for (const auto& wd : d.widgets())
      if (wd.window == "Pagor Studio" && wd.visible) CHECK(wd.min.x >= 0);
  }
}

TEST_CASE("the left panel gets its width back after the window was shrunk") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 1280, 720);
  d.settle();
  d.state().layout.left_width = 400.0f;
  d.frames(2);
  const auto* split = d.find("##left_splitter");
  REQUIRE(split);
  CHECK(split->min.x == Approx(400.0f).margin(1.0f));
  d.resize(320, 240);
  d.frames(3);
  split = d.find("##left_splitter");
  REQUIRE(split);
  CHECK(split->min.x < 200.0f);  // narrower while the window is small (at most 180 px)
  d.resize(1280, 720);
  d.frames(3);
  CHECK(d.state().layout.left_width == 400.0f);
  split = d.find("##left_splitter");
  REQUIRE(split);
  CHECK(split->min.x == Approx(400.0f).margin(1.0f));
}

TEST_CASE("shortcuts") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 800, 600);
  d.settle();
  studio::AppState& s = d.state();
  d.press_key(keys::F1);
  CHECK(s.show_help);
  CHECK(d.find("close##help"));
  d.press_key('H');
  CHECK_FALSE(s.show_help);
  d.press_key('H');
  d.press_key(keys::Escape);
  CHECK_FALSE(s.show_help);

  const bool top = s.camera.top_down;
  d.press_key('T');
  CHECK(s.camera.top_down == !top);
  d.press_key('T');
  CHECK(s.camera.top_down == top);

  const float size = s.view.point_size;
  d.chars(U"+");
  d.frame();
  CHECK(s.view.point_size == Approx(size + 0.5f));
  d.chars(U"--");
  d.frame();
  CHECK(s.view.point_size == Approx(size - 0.5f));
  for (int i = 0; i < 40; ++i) d.chars(U"+");
  d.frame();
  CHECK(s.view.point_size == studio::ViewLimits::max_point_size);

  s.camera.yaw_deg = 10.0f;
  s.camera.distance = 3.0f;
  d.press_key('R');
  CHECK(s.camera.yaw_deg == studio::Camera{}.yaw_deg);
  CHECK(s.camera.distance > 3.0f);  // reset, then fitted to the data
  s.camera.distance = 3.0f;
  d.press_key('F');
  CHECK(s.camera.distance > 3.0f);

  d.press_key('S');
  CHECK(std::filesystem::file_size(s.screenshot_path) > 1000);
  CHECK(s.message.level == studio::MessageLevel::info);
  CHECK(s.message.text == "wrote " + s.screenshot_path);

  // Ctrl+S saves, a change, Ctrl+O loads it back; each says so in the status bar.
  const double eps0 = s.config.graph.thresholds[0];
  d.press_key('S', true);
  CHECK(std::filesystem::exists(s.session_path));
  CHECK(s.message.text == "saved " + s.session_path);
  const std::string session = s.session_path;
  s.session_path = tmp.file("no/such/dir/session.json");
  d.press_key('S', true);
  CHECK(s.message.level == studio::MessageLevel::error);
  CHECK(s.message.text.find("no/such/dir") != std::string::npos);
  s.session_path = session;
  s.config.graph.thresholds[0] = eps0 / 2;
  d.frame();
  d.press_key('O', true);
  CHECK(s.config.graph.thresholds[0] == eps0);

  // Keys typed into a field go to the field, not to the shortcuts.
  const bool top_before = s.camera.top_down;
  const auto* png = d.find("PNG");
  if (!png) REQUIRE(d.click_widget("Session"));
  png = d.find("PNG");
  REQUIRE(png);
  REQUIRE(d.type_into(png->id, U"TTT.png"));
  CHECK(s.camera.top_down == top_before);
  CHECK(s.screenshot_path == "TTT.png");
}

TEST_CASE("camera views: saved and restored, copied and pasted as JSON; the help lists picking") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 1100, 800);
  d.settle();
  studio::AppState& s = d.state();
  // Picking and measuring are in the help overlay and named under the View panel.
  d.press_key(keys::F1);
  CHECK_FALSE(d.texts("Shift+click", "Shortcuts").empty());
  CHECK_FALSE(d.texts("distance between the two", "Shortcuts").empty());
  CHECK_FALSE(d.texts("copy view / paste view", "Shortcuts").empty());
  d.press_key(keys::Escape);
  CHECK_FALSE(d.texts("Shift+click a second to measure", "Pagor Studio").empty());

  s.camera.yaw_deg = 33.0f;
  s.camera.distance = 61.0f;
  s.camera.target = Eigen::Vector3f(4.0f, -3.0f, 1.0f);
  const studio::Camera saved = s.camera;
  REQUIRE(d.click_widget("save view", "Pagor Studio"));
  REQUIRE(s.camera_views.size() == 1);
  CHECK(s.camera_views[0].name == "view 1");
  REQUIRE(d.click_widget("copy view", "Pagor Studio"));
  CHECK(std::string(ImGui::GetClipboardText()) == studio::camera_text(saved));
  // Moved away, then back with a click on the view's name.
  s.camera.yaw_deg = -120.0f;
  s.camera.distance = 9.0f;
  d.frame();
  REQUIRE(d.click_widget("view 1", "Pagor Studio"));
  CHECK(s.camera.yaw_deg == saved.yaw_deg);
  CHECK(s.camera.distance == saved.distance);
  CHECK(s.camera.target == saved.target);
  // Pasted JSON sets the camera; text that is not a camera is an error naming the clipboard, and
  // the camera stays.
  ImGui::SetClipboardText(R"({"distance": 25, "yaw_deg": 5, "top_down": true})");
  s.camera_fitted = false;  // a fit pending (as after new data): the pasted view must stay
  REQUIRE(d.click_widget("paste view", "Pagor Studio"));
  CHECK(s.camera.distance == 25.0f);
  CHECK(s.camera.top_down);
  d.frames(2);
  CHECK(s.camera.distance == 25.0f);  // not fitted again over the pasted view
  ImGui::SetClipboardText("/data/scan.pcd");
  REQUIRE(d.click_widget("paste view", "Pagor Studio"));
  CHECK(s.message.level == studio::MessageLevel::error);
  CHECK(s.message.text.find("the clipboard") != std::string::npos);
  CHECK(s.camera.distance == 25.0f);
  // Kept in the session, and forgotten with its x.
  d.press_key('S', true);
  studio::AppState loaded;
  studio::load_session(s.session_path, loaded);
  REQUIRE(loaded.camera_views.size() == 1);
  CHECK(loaded.camera_views[0].camera.yaw_deg == saved.yaw_deg);
  REQUIRE(d.click_widget("x##view", "Pagor Studio"));
  CHECK(s.camera_views.empty());
}

TEST_CASE("epsilon editing: clamped at the widget - insert and delete anywhere - sorted - undo") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 900, 1000);
  d.settle();
  auto& th = d.state().config.graph.thresholds;
  const auto [lo, hi] = studio::epsilon_range(d.state().config.graph.trim);
  const std::vector<double> start = th;
  REQUIRE(start.size() == 4);

  // Typed values out of range are clamped to the fixed range, never kept.
  const auto* e1 = d.find(
      "\xce\xb5"
      "1",
      "Pagor Studio");
  REQUIRE(e1);
  const ImGuiID e1_id = e1->id;
  REQUIRE(d.type_into_slider(e1_id, U"0"));
  d.frames(2);
  CHECK(th.front() == lo);  // eps1 became the smallest, and the levels were sorted again
  CHECK(std::is_sorted(th.begin(), th.end()));
  REQUIRE(d.type_into_slider(e1_id, U"1000"));
  d.frames(2);
  CHECK(th.back() == hi);
  CHECK(std::adjacent_find(th.begin(), th.end()) == th.end());
  // The range is fixed: it does not follow the neighbours.
  REQUIRE(
      d.find("\xce\xb5"
             "2",
             "Pagor Studio"));
  const studio::ui::WidgetRecord e2v = *d.find(
      "\xce\xb5"
      "2",
      "Pagor Studio");
  const auto* e2 = &e2v;
  CHECK(e2->lo == Approx(lo));
  CHECK(e2->hi == Approx(hi));

  // Ctrl+Z twice brings the start back; Ctrl+Y redoes.
  d.press_key('Z', true);
  d.press_key('Z', true);
  CHECK(th == start);
  d.press_key('Y', true);
  CHECK(th != start);
  d.press_key('Z', true);
  CHECK(th == start);

  // Insert below level 2: the geometric mean of levels 1 and 2, in place.
  ImGuiID insert_id = 0, delete_id = 0;
  for (const auto& w : d.widgets()) {
    if (w.label == "+" && w.min.y > e2->min.y - 2 && w.min.y < e2->max.y) insert_id = w.id;
    if (w.label == "x" && w.min.y > e2->min.y - 2 && w.min.y < e2->max.y) delete_id = w.id;
  }
  REQUIRE(insert_id);
  REQUIRE(delete_id);
  REQUIRE(d.click_id(insert_id));
  REQUIRE(th.size() == 5);
  CHECK(th[2] == Approx(std::sqrt(start[1] * start[2])).epsilon(1e-6));
  CHECK(std::is_sorted(th.begin(), th.end()));
  // Delete level 2 (the one just inserted): back to the start.
  REQUIRE(d.click_id(delete_id));
  CHECK(th == start);
  // Shortest decimals: what the UI wrote is what a session says.
  for (double e : th) CHECK(std::to_string(e).size() < 12);
  d.settle();
  CHECK(d.studio().run_history().runs().size() >= 2);
}

TEST_CASE("results are marked stale while a run is pending, and changes are shown after it") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 900, 700);
  d.settle();
  CHECK(d.studio().stale_reason().empty());
  const auto before = d.studio().worker().snapshot();
  REQUIRE(before);
  d.state().config.verification.mu = 3.0;
  d.studio().submit_config();
  d.frame();
  CHECK_FALSE(d.studio().stale_reason().empty());
  d.settle();
  CHECK(d.studio().stale_reason().empty());
  const auto& changes = d.studio().run_history().changes();
  CHECK(changes.comparable);
  REQUIRE(changes.levels.size() == before->levels.size());
  bool some_delta = false;
  for (const auto& l : changes.levels) some_delta = some_delta || (l.d_delta && *l.d_delta != 0);
  CHECK(some_delta);  // mu changes every D
  CHECK(d.studio().run_history().runs().front().change != "new data");
}

TEST_CASE("an ImGui assertion fails the test with its message", "[.assert-demo]") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 640, 480);
  d.set_action("calling ImGui::End() once too often on purpose");
  ImGui::NewFrame();
  ImGui::End();  // IM_ASSERT inside ImGui: the handler prints it and exits non-zero
}

#ifdef PAGOR_HAVE_KITTI
TEST_CASE("every parameter and view widget explains itself in a tooltip") {
  TempDir tmp;
  UiDriver d(kitti_state(tmp), 900, 700);
  d.settle();
  for (const char* header : {"History", "Session"}) REQUIRE(d.click_widget(header));
  // Open every section and class of the parameter editor.
  d.open_all_nodes();
  int explained = 0, parameters = 0;
  for (const auto& w : d.widgets()) {
    if (w.window != "Pagor Studio" || w.kind == WidgetKind::header ||
        w.kind == WidgetKind::tree_node || w.kind == WidgetKind::text)
      continue;
    parameters += w.label.find("###") != std::string::npos;
    INFO(to_string(w.kind) << " '" << w.label << "'");
    CHECK(w.has_tooltip);
    explained += w.has_tooltip;
  }
  CHECK(explained >= 50);
  // Every parameter of the catalog has its widget (the pyramid's TRIM and thresholds and the
  // label scheme have theirs above the generated sections).
  CHECK(parameters == static_cast<int>(config_fields(d.state().config).size()) - 3);
  // Hovering shows it.
  const auto* mu = d.find_param("verification.mu");
  REQUIRE(mu);
  REQUIRE(d.reveal(mu->id));
  const auto m = *d.find_id(mu->id);
  d.move(ImVec2((m.min.x + m.max.x) / 2, (m.min.y + m.max.y) / 2));
  d.frames(2);
  bool tooltip_window = false;
  for (ImGuiWindow* w : GImGui->Windows)
    tooltip_window =
        tooltip_window || (w->Active && std::string(w->Name).rfind("##Tooltip", 0) == 0);
  CHECK(tooltip_window);
}
#endif

#ifdef PAGOR_HAVE_KITTI
// Pictures of the changed views for a human to look at (not run by ctest):
//   PAGOR_SHOTS_DIR=/tmp/studio-shots build/tests/studio_ui_test "[.shots]"
TEST_CASE("screenshots of the changed views", "[.shots]") {
  const char* dir = std::getenv("PAGOR_SHOTS_DIR");
  REQUIRE(dir);
  TempDir tmp;
  studio::AppState s = kitti_state(tmp);
  s.view.layers.source = s.view.layers.target = true;
  UiDriver d(s, 1280, 720);
  d.settle();
  std::string error;
  const auto shot = [&](const std::string& name, int frames = 2) {
    d.frames(frames);
    REQUIRE(d.studio().screenshot(std::string(dir) + "/" + name, d.width(), d.height(), error));
  };
  // A clustering change re-runs everything: meanwhile the results are marked stale.
  d.state().config.landmarks.classes[0].cluster_tolerance = 0.6;
  d.studio().submit_config();
  shot("driven_stale_pending.png", 1);
  d.settle();
  // Without the selected level (0.08) the selection moves, and the changes are highlighted.
  d.state().config.graph.thresholds = {0.01, 0.02, 0.04, 0.16, 0.32};
  d.studio().submit_config();
  d.settle();
  shot("driven_after_rerun_changes.png");
  // The source where its sensor saw it, with every correspondence in class colours.
  d.state().view.layers.all_correspondences = true;
  d.state().view.pose = studio::PoseShown::identity;
  d.state().camera_fitted = false;
  d.frames(2);
  shot("driven_identity_all_corr.png");
  d.state().view.pose = studio::PoseShown::selected;
  d.state().view.layers.all_correspondences = false;
  d.resize(640, 480);
  d.frames(3);
  shot("driven_640x480.png");
  d.resize(320, 240);
  d.frames(3);
  shot("driven_320x240.png");
  d.resize(1280, 720);
  d.press_key('H');
  shot("driven_help.png");
}
#endif

TEST_CASE("a long error in the status bar is cut at the window's edge, and shown whole on hover") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 800, 600);
  d.settle();
  std::string text = "/a/very/long/path/";
  while (text.size() < 400) text += "that-goes-on-and-on/";
  text += "file.pcd: scan does not exist";
  d.studio().notify(studio::Message::error(text));
  d.frames(2);
  const studio::ui::WidgetRecord* line = nullptr;
  for (const auto& w : d.widgets())
    if (w.kind == studio::ui::WidgetKind::text && w.window == "##status" &&
        w.text == "| error: " + text)
      line = &w;
  REQUIRE(line);
  CHECK(line->max.x > line->clip_max.x);  // cut: the window is narrower than the line
  CHECK(line->has_tooltip);
  d.move(ImVec2(std::min(line->min.x + 40, line->clip_max.x - 4), (line->min.y + line->max.y) / 2));
  d.frames(2);
  bool shown = false;
  for (ImGuiWindow* w : GImGui->Windows)
    shown = shown || (std::string(w->Name).rfind("##Tooltip", 0) == 0 && w->Active);
  CHECK(shown);
}
