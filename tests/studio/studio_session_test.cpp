// The session reader and writer, and the widget registry's duplicate-ID check (no GL needed).

#include <imgui.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "state/app_state.hpp"
#include "state/camera_views.hpp"
#include "state/history.hpp"
#include "studio_test_util.hpp"
#include "widgets/number_format.hpp"
#include "widgets/widgets.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

std::string bad(const std::string& name) {
  return shared_data() + "/bad-inputs/" + name;
}

// The message of the InputError that loading `path` throws ("" when it loads).
std::string load_error(const std::string& path) {
  studio::AppState s;
  try {
    studio::load_session(path, s);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string write(const TempDir& tmp, const std::string& text) {
  const std::string path = tmp.file("s.json");
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("session reader rejects the bad inputs, naming the file and the key") {
  const std::string p32 = bad("session_pair_2p32_plus_20_silent.json");
  const std::string e32 = load_error(p32);
  CHECK_THAT(e32, Catch::Contains(p32) && Catch::Contains("data.pair[0]") &&
                      Catch::Contains("4294967316") && Catch::Contains("outside"));
  const std::string p30 = bad("session_pair_1e30_ub.json");
  CHECK_THAT(load_error(p30), Catch::Contains(p30) && Catch::Contains("data.pair[0]") &&
                                  Catch::Contains("expected an integer"));
  const std::string pw = bad("session_window_40000_segv.json");
  CHECK_THAT(load_error(pw), Catch::Contains(pw) && Catch::Contains("window.width") &&
                                 Catch::Contains("40000") && Catch::Contains("8192"));
  // Missing data files are legal in a session (they may appear later); opening them fails in
  // the worker and the headless run exits non-zero (tested through the executable).
  CHECK(load_error(bad("session_missing_files_exit0.json")).empty());
}

TEST_CASE("session reader rejects wrong values at their key") {
  TempDir tmp;
  const auto err = [&](const std::string& text) { return load_error(write(tmp, text)); };
  CHECK_THAT(err(R"({"window": {"width": 100, "height": 600}})"),
             Catch::Contains("window.width") && Catch::Contains("outside [320, 8192]"));
  CHECK_THAT(err(R"({"window": {"width": 800.5, "height": 600}})"),
             Catch::Contains("window.width: expected an integer"));
  CHECK_THAT(err(R"({"view": {"point_size": 1e30}})"), Catch::Contains("view.point_size"));
  CHECK_THAT(err(R"({"view": {"point_size": -1}})"), Catch::Contains("view.point_size"));
  CHECK_THAT(err(R"({"view": {"level": 99}})"), Catch::Contains("view.level"));
  CHECK_THAT(err(R"({"view": {"color": "purple"}})"), Catch::Contains("view.color"));
  CHECK_THAT(err(R"({"view": {"diagnosis": {"truth": "maybe"}}})"),
             Catch::Contains("view.diagnosis.truth") && Catch::Contains("\"outliers\""));
  CHECK_THAT(err(R"({"view": {"diagnosis": {"panel": 1}}})"),
             Catch::Contains("view.diagnosis.panel"));
  CHECK_THAT(err(R"({"camera": {"distance": 0}})"), Catch::Contains("camera.distance"));
  CHECK_THAT(err(R"({"camera": {"target": [1, 2, 1e300]}})"), Catch::Contains("camera.target[2]"));
  CHECK_THAT(err(R"({"data": {"kind": "synthetic", "seed": -3}})"), Catch::Contains("data.seed"));
  CHECK_THAT(err(R"({"data": {"kind": "kitti", "pair": [0, -1]}})"),
             Catch::Contains("data.pair[1]"));
  CHECK_THAT(err(R"({"layout": {"left_width": 5}})"), Catch::Contains("layout.left_width"));
  CHECK_THAT(err(R"({"bogus": 1})"), Catch::Contains("bogus: unknown key"));
  CHECK_THAT(err(R"({"data": {"kind": "files", "source": 3}})"),
             Catch::Contains("data.source: expected a string"));
  CHECK_THAT(err("[1, 2]"), Catch::Contains("expected a JSON object"));
  CHECK_THAT(err("{\"view\": "), Catch::Contains("not valid JSON"));
}

TEST_CASE("a session round-trips and writes numbers in their shortest exact form") {
  TempDir tmp;
  studio::AppState s;
  s.have_data = true;
  s.data.kind = PairSource::Kind::synthetic;
  s.data.synthetic_seed = 11;
  s.config.graph.thresholds = {studio::shortest(0.3f), studio::shortest(0.55f)};
  s.view.point_size = 2.7f;
  s.view.line_width = 3.3f;
  s.camera.distance = 41.7f;
  s.layout.left_width = 287.3f;
  s.layout.scene_share = 0.55f;
  s.view.layers.plan = false;  // the floor plan overlay of indoor pairs, hidden
  s.view.diagnosis = {
      true, true, "pole", studio::TruthFilter::outliers, false, studio::Contribution::ground_truth};
  s.width = 1000;
  s.height = 700;
  const std::string path = tmp.file("round.json");
  studio::save_session(s, path);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(text, Catch::Contains("0.3,") || Catch::Contains("0.3\n"));
  CHECK_THAT(text, Catch::Contains("2.7"));
  CHECK_THAT(text, Catch::Contains("41.7"));
  CHECK_THAT(text, !Catch::Contains("0.30000001") && !Catch::Contains("2.700000"));
  studio::AppState r;
  studio::load_session(path, r);
  CHECK(r.config.graph.thresholds == s.config.graph.thresholds);
  CHECK(r.data.synthetic_seed == 11);
  CHECK(r.view.point_size == s.view.point_size);
  CHECK(r.view.line_width == s.view.line_width);
  CHECK(r.camera.distance == s.camera.distance);
  CHECK(r.layout.left_width == s.layout.left_width);
  CHECK(r.layout.scene_share == s.layout.scene_share);
  CHECK_FALSE(r.view.layers.plan);
  CHECK(studio::AppState{}.view.layers.plan);  // shown unless a session hides it
  CHECK(r.view.diagnosis.panel);
  CHECK(r.view.diagnosis.color_by_residual);
  CHECK(r.view.diagnosis.class_name == "pole");
  CHECK(r.view.diagnosis.truth == studio::TruthFilter::outliers);
  CHECK_FALSE(r.view.diagnosis.edges_on_hover);
  CHECK(r.view.diagnosis.contribution == studio::Contribution::ground_truth);
  CHECK(r.width == 1000);
  CHECK(r.height == 700);
}

TEST_CASE("camera views round-trip in the session and through the clipboard's JSON") {
  TempDir tmp;
  studio::AppState s;
  studio::Camera a;
  a.target = Eigen::Vector3f(1.5f, -2.25f, 0.5f);
  a.distance = 33.3f;
  a.yaw_deg = 12.5f;
  a.pitch_deg = 20.0f;
  studio::Camera b = a;
  b.top_down = true;
  s.camera_views = {{"street", a}, {studio::next_view_name({{"street", a}}), b}};
  CHECK(s.camera_views[1].name == "view 1");
  CHECK(studio::next_view_name(s.camera_views) == "view 2");
  const std::string path = tmp.file("views.json");
  studio::save_session(s, path);
  studio::AppState r;
  studio::load_session(path, r);
  REQUIRE(r.camera_views.size() == 2);
  CHECK(r.camera_views[0].name == "street");
  CHECK(r.camera_views[0].camera.target == a.target);
  CHECK(r.camera_views[0].camera.distance == a.distance);
  CHECK(r.camera_views[0].camera.yaw_deg == a.yaw_deg);
  CHECK_FALSE(r.camera_views[0].camera.top_down);
  CHECK(r.camera_views[1].camera.top_down);

  // "copy view" writes one line of JSON that "paste view" reads back exactly; a session's
  // member pasted with its key is read too; anything else is an error naming the clipboard.
  const std::string text = studio::camera_text(a);
  CHECK(text.find('\n') == std::string::npos);
  const studio::Camera back = studio::camera_from_text(text, studio::Camera{}, "the clipboard");
  CHECK(back.target == a.target);
  CHECK(back.distance == a.distance);
  CHECK(back.pitch_deg == a.pitch_deg);
  const studio::Camera keyed = studio::camera_from_text(
      R"({"camera": {"distance": 7, "top_down": true}})", a, "the clipboard");
  CHECK(keyed.distance == 7.0f);
  CHECK(keyed.top_down);
  CHECK(keyed.yaw_deg == a.yaw_deg);  // absent keys keep the camera's
  const auto paste_error = [&](const std::string& t) {
    try {
      studio::camera_from_text(t, a, "the clipboard: camera");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(paste_error("/home/me/scan.pcd"),
             Catch::Contains("the clipboard") && Catch::Contains("not a camera view"));
  CHECK_THAT(paste_error(R"({"distance": -4})"), Catch::Contains("the clipboard: camera.distance"));
  CHECK_THAT(paste_error(R"({"zoom": 2})"), Catch::Contains("zoom: unknown key"));
  CHECK_THAT(paste_error(std::string(5000, ' ')), Catch::Contains("not a camera view"));
  CHECK(paste_error("") == "the clipboard: camera: empty, not a camera view (copy one with \"copy "
                           "view\")");
  CHECK(paste_error("hello") ==
        "the clipboard: camera: not a camera view (copy one with \"copy view\"): \"hello\" is "
        "not JSON");
}

TEST_CASE("session reader rejects wrong camera views at their index and key") {
  TempDir tmp;
  const auto err = [&](const std::string& text) { return load_error(write(tmp, text)); };
  CHECK_THAT(err(R"({"camera_views": {"name": "a"}})"), Catch::Contains("camera_views: expected a list"));
  CHECK_THAT(err(R"({"camera_views": [{"name": "", "camera": {}}]})"),
             Catch::Contains("camera_views[0].name"));
  CHECK_THAT(err(R"({"camera_views": [{"name": "a", "camera": {}}, {"name": "b"}]})"),
             Catch::Contains("camera_views[1]: no \"camera\""));
  CHECK_THAT(err(R"({"camera_views": [{"name": "a", "camera": {"pitch_deg": 95}}]})"),
             Catch::Contains("camera_views[0].camera.pitch_deg"));
  std::string many = R"({"camera_views": [)";
  for (int i = 0; i < 33; ++i) many += std::string(i ? "," : "") + R"({"name": "v", "camera": {}})";
  CHECK_THAT(err(many + "]}"), Catch::Contains("33 views, at most 32"));
}

TEST_CASE("fit frames the whole box, top-down at any yaw and aspect, and in perspective") {
  // A street 300 m long and 12 m wide, turned, and a tower 100 m tall: every corner must land
  // inside the viewport, in front of the camera.
  for (const auto& [lo, hi] : {std::pair{Eigen::Vector3f(-150.0f, 20.0f, -2.0f),
                                         Eigen::Vector3f(150.0f, 32.0f, 6.0f)},
                               std::pair{Eigen::Vector3f(-2.0f, -2.0f, -50.0f),
                                         Eigen::Vector3f(2.0f, 2.0f, 50.0f)}})
  for (const bool top_down : {true, false})
    for (const float yaw : {-90.0f, -60.0f, 0.0f, 30.0f, 90.0f})
      for (const float aspect : {0.5f, 1.0f, 1.6f, 3.0f}) {
        studio::Camera c;
        c.top_down = top_down;
        c.yaw_deg = yaw;
        c.fit(lo, hi, aspect);
        const float h = 600.0f, w = h * aspect;
        const Eigen::Matrix4f vp = c.projection(aspect) * c.view();
        float reach = 0;  // the farthest corner from the centre, as a share of the half viewport
        for (int k = 0; k < 8; ++k) {
          const Eigen::Vector3f p((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                  (k & 4) ? hi.z() : lo.z());
          Eigen::Vector2f px;
          REQUIRE(studio::project_to_screen(vp, p, w, h, px));
          INFO("top_down " << top_down << ", yaw " << yaw << ", aspect " << aspect << ", corner "
                           << k << " at " << px.transpose());
          CHECK(px.x() >= 0.0f);
          CHECK(px.x() <= w);
          CHECK(px.y() >= 0.0f);
          CHECK(px.y() <= h);
          // Between the near and the far plane (top-down too: the eye above the highest corner).
          const Eigen::Vector4f clip = vp * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
          CHECK(std::abs(clip.z() / clip.w()) <= 1.0f);
          reach = std::max({reach, std::abs(px.x() - w / 2) / (w / 2),
                            std::abs(px.y() - h / 2) / (h / 2)});
        }
        // Top-down the street fills the view (not a speck in the middle): its margin is 12 %.
        if (top_down && hi.z() - lo.z() < 20.0f) CHECK(reach > 0.85f);
      }
}

TEST_CASE("shortest: a float's shortest decimal as a double") {
  CHECK(studio::shortest(0.3f) == 0.3);
  CHECK(studio::shortest(0.02f) == 0.02);
  CHECK(studio::shortest(1.0f) == 1.0);
  CHECK(studio::shortest(1e-3f) == 0.001);
  CHECK(nlohmann::json(studio::shortest(0.1f)).dump() == "0.1");
}

TEST_CASE("numbers as the studio prints them: no negative zero, a unit on every figure") {
  CHECK(studio::fixed(-0.0, 2) == "0.00");
  CHECK(studio::fixed(-0.004, 2) == "0.00");  // pitch -0.004 deg reads 0.00, not -0.00
  CHECK(studio::fixed(-0.005001, 2) == "-0.01");
  CHECK(studio::fixed(12.346, 2) == "12.35");
  CHECK(studio::fixed(-3.0, 0) == "-3");
  CHECK(studio::with_unit(1.0, "m") == "1 m");  // a legend's tick: "1 m", not "1.0"
  CHECK(studio::with_unit(0.25, "m") == "0.25 m");
  CHECK(studio::with_unit(-0.0, "m") == "0 m");
  CHECK(studio::with_unit(-12.5, "m") == "-12.5 m");
  CHECK(studio::with_unit(0.5, "") == "0.5");
  CHECK(studio::with_unit(3052.4, "m") == "3052 m");  // a D gap: not "3.05e+03 m"
  CHECK(studio::with_unit(-999.94, "m") == "-1000 m");
}

TEST_CASE("the widget registry reports two widgets of one frame with the same ID") {
  ImGuiContext* ctx = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(800, 600);
  io.DeltaTime = 1.0f / 60.0f;
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  const auto frame = [](bool scoped) {
    studio::ui::registry().begin_frame();
    ImGui::NewFrame();
    ImGui::Begin("panel");
    std::string path;
    bool layer = true;
    if (scoped) ImGui::PushID("data");
    studio::ui::input_text("source", &path);  // the Data panel's field ...
    if (scoped) ImGui::PopID();
    if (scoped) ImGui::PushID("view");
    studio::ui::checkbox("source", &layer);  // ... and the View panel's layer box
    if (scoped) ImGui::PopID();
    ImGui::End();
    ImGui::Render();
    return studio::ui::registry().duplicates();
  };
  const auto dups = frame(false);
  REQUIRE(dups.size() == 1);
  CHECK(dups[0].first == "source");
  CHECK(dups[0].second == "source");
  CHECK(dups[0].window == "panel");
  CHECK_THAT(dups[0].describe(), Catch::Contains("duplicate ImGui ID"));
  CHECK(frame(true).empty());  // each panel in its own ID scope: two widgets
  CHECK(studio::ui::registry().items().size() == 2);
  ImGui::DestroyContext(ctx);
}

TEST_CASE("runs during a drag are compared with the run shown before the drag") {
  // Dragging a threshold re-runs at every step: the line "last run changed the selection" must
  // compare the run after the drag with the one before it, not with a run in between.
  const auto run = [](int selected) {
    auto s = std::make_shared<studio::Snapshot>();
    s->data_generation = 1;
    for (double eps : {0.02, 0.04, 0.08, 0.16}) {
      studio::LevelView l;
      l.epsilon = eps;
      s->levels.push_back(l);
    }
    s->selected = selected;
    return std::shared_ptr<const studio::Snapshot>(s);
  };
  studio::RunHistory h;
  const auto before = run(3), during = run(0), after = run(3);
  h.observe(before);
  h.observe(before, true);  // the drag begins
  CHECK(h.observe(during, true).selected_changed());  // 3 -> 0 while dragging
  const studio::RunChanges& c = h.observe(after, false);  // the drag's result
  CHECK(c.selected_before == 3);
  CHECK(c.selected_after == 3);
  CHECK_FALSE(c.selected_changed());
  // Without a drag, each run is compared with the one before it.
  CHECK(h.observe(run(0)).selected_changed());
}
