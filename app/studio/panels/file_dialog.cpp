// The studio's own file browser: a window listing a directory's subdirectories and the files of
// the purpose it was opened for; a double click (or "open") hands the file to the studio.

#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "panels/panels.hpp"
#include "state/open_file.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxEntries = 2000;  // a directory of more lists its first ones

bool shown_file(const std::string& name, const std::vector<std::string>& extensions) {
  if (extensions.empty()) return true;
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::any_of(extensions.begin(), extensions.end(), [&](const std::string& e) {
    return lower.size() >= e.size() && lower.compare(lower.size() - e.size(), e.size(), e) == 0;
  });
}

// Reads the directory's entries when the directory, filter or purpose changed: subdirectories
// first, then the files of the purpose, by name.
void refresh(FileDialogState& f) {
  const std::string key =
      f.directory + "\n" + f.filter + "\n" + std::to_string(static_cast<int>(f.purpose));
  if (key == f.listed) return;
  f.listed = key;
  f.listing.clear();
  f.truncated = false;
  f.listing_error.clear();
  const auto extensions = purpose_extensions(f.purpose);
  std::error_code ec;
  fs::directory_iterator it(f.directory, ec);
  if (ec) {  // said, not shown as an empty directory
    f.listing_error = f.directory + ": " +
                      (fs::exists(f.directory) ? "cannot be listed (" + ec.message() + ")"
                                               : std::string("no such directory"));
    return;
  }
  for (fs::directory_iterator end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    const bool directory = it->is_directory(ec);
    if (name.empty() || name[0] == '.') continue;  // hidden
    if (!f.filter.empty() && name.find(f.filter) == std::string::npos) continue;
    if (!directory && !shown_file(name, extensions)) continue;
    if (f.listing.size() >= kMaxEntries) {
      f.truncated = true;
      break;
    }
    f.listing.emplace_back(std::move(name), directory);
  }
  std::sort(f.listing.begin(), f.listing.end(), [](const auto& a, const auto& b) {
    return a.second != b.second ? a.second : a.first < b.first;
  });
}

void choose(FileDialogState& f, StudioActions& actions, const std::string& path) {
  f.open = false;
  actions.open_file(path, f.purpose);
}

// The list of entries; a click selects a file or enters a directory, a double click opens.
void entries(FileDialogState& f, StudioActions& actions) {
  refresh(f);
  const auto found = f.listing;  // a click may change the directory
  const float h =
      std::max(80.0f, ImGui::GetContentRegionAvail().y - 2.6f * ImGui::GetFrameHeight());
  ImGui::BeginChild("##entries", ImVec2(0, h), true);
  if (ui::selectable(".. (up)##dialog", false)) {
    f.directory = fs::path(f.directory).parent_path().string();
    f.name.clear();
  }
  for (const auto& [name, directory] : found) {
    const std::string label = (directory ? "[dir] " : "") + name + "##dialog";
    const bool selected = !directory && name == f.name;
    if (ui::selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
      const std::string path = (fs::path(f.directory) / name).string();
      if (directory) {
        f.directory = path;
        f.name.clear();
      } else {
        f.name = name;
        if (ImGui::IsMouseDoubleClicked(0)) choose(f, actions, path);
      }
      break;  // the listing changed under the loop
    }
  }
  if (f.truncated) ui::figure_dim("(more entries not listed: type a filter)");
  if (!f.listing_error.empty()) ui::figure_dim(f.listing_error);
  ImGui::EndChild();
}

}  // namespace

void file_dialog(FileDialogState& f, StudioActions& actions) {
  if (!f.open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(
      ImVec2(std::min(720.0f, display.x - 20), std::min(520.0f, display.y - 40)),
      ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);  // what is behind must not show through the listing
  const std::string title = std::string("Open ") + purpose_name(f.purpose) + "###file_dialog";
  if (ImGui::Begin(title.c_str(), nullptr,
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::PushItemWidth(-110);
    ui::input_path("directory##dialog", &f.directory, "The directory listed.");
    ui::input_text("filter##dialog", &f.filter, "Only names containing this.");
    ImGui::PopItemWidth();
    entries(f, actions);
    ImGui::PushItemWidth(-180);
    ui::input_text("file##dialog", &f.name,
                   "The file to open (a name in the directory above, or a whole path).");
    ImGui::PopItemWidth();
    ImGui::SameLine();
    ImGui::BeginDisabled(f.name.empty() && f.purpose != FilePurpose::kitti_root);
    if (ui::button("open##dialog", ImVec2(0, 0), "Open the file (or a double click)."))
      choose(f, actions,
             f.name.empty()                   ? f.directory
             : fs::path(f.name).is_absolute() ? f.name
                                              : (fs::path(f.directory) / f.name).string());
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ui::button("cancel##dialog", ImVec2(0, 0), "Close the browser.")) f.open = false;
  }
  ImGui::End();
}

}  // namespace pagor::studio
