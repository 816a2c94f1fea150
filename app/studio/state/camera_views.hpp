#pragma once
/// \file camera_views.hpp
/// Camera views as JSON: the session's "camera" object, the named views a session keeps
/// ("camera_views"), and one view as text for the clipboard, read back with the session's checks.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "state/camera.hpp"

namespace pagor::studio {

/// A camera saved under a name (the View panel's "save view"), kept in the session.
struct CameraView {
  std::string name;
  Camera camera;
};

/// Most views a session keeps, and the longest name [characters].
constexpr std::size_t kMaxCameraViews = 32, kMaxCameraViewName = 64;

/// {"target": [x, y, z], "distance", "yaw_deg", "pitch_deg", "top_down"}: a camera as the
/// session writes it.
nlohmann::json camera_json(const Camera& camera);
/// Reads a camera written by camera_json into `camera` (absent keys keep their value). Throws
/// InputError naming `where` and the key of a wrong or out-of-range value.
void read_camera(const nlohmann::json& j, const std::string& where, Camera& camera);

/// One camera as one line of JSON (what "copy view" puts on the clipboard).
std::string camera_text(const Camera& camera);
/// The camera a text holds: camera_text's JSON, or a session's whole "camera" member pasted with
/// its key. Absent keys keep `current`'s values. Throws InputError naming `where`.
Camera camera_from_text(const std::string& text, const Camera& current, const std::string& where);

/// [{"name", "camera"}, ...] for the session.
nlohmann::json camera_views_json(const std::vector<CameraView>& views);
/// Reads the session's "camera_views". Throws InputError naming `where`, the index and the key.
std::vector<CameraView> read_camera_views(const nlohmann::json& j, const std::string& where);

/// "view N": the first such name not yet taken.
std::string next_view_name(const std::vector<CameraView>& views);

}  // namespace pagor::studio
