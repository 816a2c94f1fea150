#include "state/camera_views.hpp"

#include <cmath>

#include "pagor/errors.hpp"
#include "pagor/io/json_input.hpp"
#include "state/session_json.hpp"

namespace pagor::studio {
namespace {

using json = nlohmann::json;
using namespace session_json;

constexpr double kMaxCoordinate = 1e7;                        // [m]
constexpr float kMinDistance = 0.5f, kMaxDistance = 5000.0f;  // as Camera::zoom clamps [m]
constexpr std::size_t kMaxCameraText = 4096;                  // a pasted view [bytes]

}  // namespace

json camera_json(const Camera& c) {
  return {{"target", {number(c.target.x()), number(c.target.y()), number(c.target.z())}},
          {"distance", number(c.distance)},
          {"yaw_deg", number(c.yaw_deg)},
          {"pitch_deg", number(c.pitch_deg)},
          {"top_down", c.top_down}};
}

void read_camera(const json& c, const std::string& where, Camera& cam) {
  if (!c.is_object()) throw InputError(where + ": expected an object");
  reject_unknown(c, where, {"target", "distance", "yaw_deg", "pitch_deg", "top_down"});
  if (const json* t = find(c, "target")) {
    if (!t->is_array() || t->size() != 3) throw InputError(where + ".target: expected [x, y, z]");
    for (int i = 0; i < 3; ++i) {
      const json& x = (*t)[static_cast<std::size_t>(i)];
      if (!x.is_number() || !(std::abs(x.get<double>()) <= kMaxCoordinate))
        throw InputError(where + ".target[" + std::to_string(i) + "]: expected a number within " +
                         "+-1e7 m, got " + x.dump());
      cam.target[i] = static_cast<float>(x.get<double>());
    }
  }
  cam.distance = get_float(c, "distance", where, cam.distance, kMinDistance, kMaxDistance);
  cam.yaw_deg = get_float(c, "yaw_deg", where, cam.yaw_deg, -3600.0f, 3600.0f);
  cam.pitch_deg = get_float(c, "pitch_deg", where, cam.pitch_deg, -89.9f, 89.9f);
  cam.top_down = get_bool(c, "top_down", where, cam.top_down);
}

std::string camera_text(const Camera& camera) {
  return camera_json(camera).dump();
}

Camera camera_from_text(const std::string& text, const Camera& current, const std::string& where) {
  if (text.size() > kMaxCameraText)
    throw InputError(where + ": " + std::to_string(text.size()) +
                     " bytes, not a camera view (at most " + std::to_string(kMaxCameraText) + ")");
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(where + ": empty, not a camera view (copy one with \"copy view\")");
  json j;
  try {
    j = parse_json_limited(text, where);
  } catch (const ConfigError&) {
    const std::string start = text.substr(0, 40);
    throw InputError(where + ": not a camera view (copy one with \"copy view\"): \"" + start +
                     (text.size() > start.size() ? "...\"" : "\"") + " is not JSON");
  }
  // A session's member pasted with its key: {"camera": {...}}.
  if (j.is_object() && j.size() == 1 && j.contains("camera")) j = j.at("camera");
  Camera camera = current;
  read_camera(j, where, camera);
  return camera;
}

json camera_views_json(const std::vector<CameraView>& views) {
  json out = json::array();
  for (const CameraView& v : views) out.push_back({{"name", v.name}, {"camera", camera_json(v.camera)}});
  return out;
}

std::vector<CameraView> read_camera_views(const json& j, const std::string& where) {
  if (!j.is_array()) throw InputError(where + ": expected a list of {\"name\", \"camera\"}");
  if (j.size() > kMaxCameraViews)
    throw InputError(where + ": " + std::to_string(j.size()) + " views, at most " +
                     std::to_string(kMaxCameraViews));
  std::vector<CameraView> views;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const json& v = j[i];
    if (!v.is_object()) throw InputError(at + ": expected {\"name\", \"camera\"}");
    reject_unknown(v, at, {"name", "camera"});
    CameraView view;
    view.name = get_string(v, "name", at, "");
    if (view.name.empty() || view.name.size() > kMaxCameraViewName)
      throw InputError(at + ".name: expected 1 to " + std::to_string(kMaxCameraViewName) +
                       " characters, got \"" + view.name.substr(0, kMaxCameraViewName) + "\"");
    const json* c = find(v, "camera");
    if (!c) throw InputError(at + ": no \"camera\"");
    read_camera(*c, at + ".camera", view.camera);
    views.push_back(std::move(view));
  }
  return views;
}

std::string next_view_name(const std::vector<CameraView>& views) {
  for (std::size_t n = 1;; ++n) {
    const std::string name = "view " + std::to_string(n);
    bool taken = false;
    for (const CameraView& v : views) taken = taken || v.name == name;
    if (!taken) return name;
  }
}

}  // namespace pagor::studio
