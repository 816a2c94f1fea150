// The studio and the user's files: opening them (the file browser, a drop on the window, the
// recent list, a pair of a set) and the clipboard.

#include <imgui.h>

#include "pagor/errors.hpp"
#include "panels/panels.hpp"
#include "state/open_file.hpp"
#include "studio.hpp"

namespace pagor::studio {

namespace {

// Re-runs what opening files changed.
void apply_opened(Studio& studio, const Opened& o) {
  AppState& s = studio.state();
  if (o.session) {
    studio.load_session_now();
    return;
  }
  if (o.config) studio.submit_config();
  if (o.data) {
    s.have_data = true;
    s.camera_fitted = false;
    s.view.level = -1;
    s.picks.clear();
    studio.submit_data();
  }
  if (o.bench) studio.open_benchmark_now();
}

}  // namespace

void Studio::open_file(const std::string& path, FilePurpose purpose) {
  std::vector<std::string> errors;
  Opened o;
  try {
    o = open_file_into(state_, path, purpose);
    remember_file(state_, path);
  } catch (const Error& e) {
    // A file that does not open leaves the recent list (picked from it, it would fail again).
    const bool dropped = forget_file(state_, path);
    notify(Message::error(std::string(e.what()) +
                          (dropped ? " (dropped from the recent files)" : "")));
    return;
  }
  if (o.config) params_.commit(state_.config);  // loading parameters is one undo step
  apply_opened(*this, o);
  if (o.data) opened_paths_ = {path}, opened_request_ = worker_.status().submitted;
  if (!o.session) notify(Message::info(o.what));
}

void Studio::open_files(const std::vector<std::string>& paths) {
  std::vector<std::string> errors;
  const Opened o = open_files_into(state_, paths, errors);
  if (o.config) params_.commit(state_.config);
  apply_opened(*this, o);
  if (o.data) opened_paths_ = paths, opened_request_ = worker_.status().submitted;
  if (!errors.empty()) {
    std::string detail;
    for (const std::string& e : errors) detail += e + "\n";
    notify(
        Message::error(errors.front() + (errors.size() > 1 ? " (and more: hover)" : ""), detail));
  } else if (!o.session) {
    notify(Message::info(o.what));
  }
}

void Studio::forget_unreadable(const WorkerStatus& status) {
  if (!opened_request_ || status.finished < opened_request_) return;
  const bool failed = !status.error.empty() && (!snapshot_ || snapshot_->request < opened_request_);
  if (failed)  // the error names the file it could not read
    for (const std::string& p : opened_paths_)
      if (status.error.find(p) != std::string::npos ||
          status.error.find(absolute_path(p)) != std::string::npos)
        forget_file(state_, p);
  opened_paths_.clear();
  opened_request_ = 0;
}

void Studio::browse(FilePurpose purpose, const std::string& current) {
  open_file_dialog(state_, purpose, current);
}

void Studio::open_pair(const PairEntry& entry, const std::optional<Transform>& truth) {
  show_pair(state_, entry);
  if (truth) state_.inline_truth = truth;
  submit_data();
}

void Studio::copy_text(const std::string& text, const std::string& what) {
  ImGui::SetClipboardText(text.c_str());
  notify(Message::info("copied " + what + " to the clipboard", text));
}

}  // namespace pagor::studio
