#include "state/history.hpp"

#include <cmath>
#include <cstdio>

namespace pagor::studio {

void ParamHistory::reset(const Config& current) {
  past_.clear();
  future_.clear();
  current_ = config_to_json(current, -1);
}

bool ParamHistory::commit(const Config& now) {
  std::string j = config_to_json(now, -1);
  if (j == current_) return false;
  past_.push_back(std::move(current_));
  if (past_.size() > kMaxSteps) past_.pop_front();
  current_ = std::move(j);
  future_.clear();
  return true;
}

std::optional<Config> ParamHistory::undo() {
  if (past_.empty()) return std::nullopt;
  future_.push_back(std::move(current_));
  current_ = std::move(past_.back());
  past_.pop_back();
  return parse_config(current_, "undo");
}

std::optional<Config> ParamHistory::redo() {
  if (future_.empty()) return std::nullopt;
  past_.push_back(std::move(current_));
  current_ = std::move(future_.back());
  future_.pop_back();
  return parse_config(current_, "redo");
}

bool RunChanges::any() const {
  if (!comparable) return false;
  if (selected_changed()) return true;
  for (const LevelChange& l : levels)
    if (l.added || l.validity_flipped || l.success_flipped || (l.d_delta && *l.d_delta != 0))
      return true;
  return false;
}

namespace {

bool has_epsilon(const Snapshot& s, double epsilon) {
  for (const LevelView& l : s.levels)
    if (l.epsilon == epsilon) return true;
  return false;
}

// The level at `i` before, when the runs have as many levels and its ε is gone from the new run
// while the new level's ε is new: the user edited that level's ε (not inserted one).
const LevelView* edited_level(const Snapshot& before, const Snapshot& after, std::size_t i) {
  if (before.levels.size() != after.levels.size() || i >= before.levels.size()) return nullptr;
  const LevelView& b = before.levels[i];
  return has_epsilon(after, b.epsilon) ? nullptr : &b;
}

}  // namespace

RunChanges compare_runs(const Snapshot& before, const Snapshot& after) {
  RunChanges c;
  c.comparable = before.data_generation == after.data_generation;
  if (!c.comparable) return c;  // other data: nothing to compare level by level
  c.selected_before = before.selected;
  c.selected_after = after.selected;
  if (before.selected >= 0 && before.selected < static_cast<int>(before.levels.size()))
    c.selected_eps_before = before.levels[static_cast<std::size_t>(before.selected)].epsilon;
  c.trim_before = before.config.graph.trim;
  c.trim_after = after.config.graph.trim;
  if (after.selected >= 0 && after.selected < static_cast<int>(after.levels.size()))
    c.selected_eps_after = after.levels[static_cast<std::size_t>(after.selected)].epsilon;
  for (std::size_t i = 0; i < after.levels.size(); ++i) {
    LevelChange l;
    const LevelView& a = after.levels[i];
    const LevelView* match = nullptr;
    for (const LevelView& b : before.levels)
      if (b.epsilon == a.epsilon) match = &b;
    if (!match) match = edited_level(before, after, i);
    if (match && match->epsilon != a.epsilon) l.epsilon_before = match->epsilon;
    if (!match) {
      l.added = true;
    } else {
      const LevelView& b = *match;
      if (b.pose.valid && a.pose.valid && std::isfinite(a.score_D) && std::isfinite(b.score_D))
        l.d_delta = a.score_D - b.score_D;
      l.validity_flipped = b.pose.valid != a.pose.valid;
      l.success_flipped =
          b.error.has_value() && a.error.has_value() && b.error->success != a.error->success;
    }
    c.levels.push_back(l);
  }
  return c;
}

std::optional<DGap> d_gap(const Snapshot& s) {
  DGap m{HUGE_VAL, HUGE_VAL, -1, -1};
  for (std::size_t i = 0; i < s.levels.size(); ++i) {
    const LevelView& l = s.levels[i];
    if (!l.pose.valid || !std::isfinite(l.score_D)) continue;
    if (l.score_D < m.best) {
      m.second = m.best;
      m.second_level = m.best_level;
      m.best = l.score_D;
      m.best_level = static_cast<int>(i);
    } else if (l.score_D < m.second) {
      m.second = l.score_D;
      m.second_level = static_cast<int>(i);
    }
  }
  if (m.second_level < 0) return std::nullopt;
  return m;
}

RunRecord summarize(const Snapshot& s, const RunChanges& changes) {
  RunRecord r;
  r.request = s.request;
  r.data = s.description;
  r.levels = static_cast<int>(s.levels.size());
  r.selected = s.selected;
  if (s.selected >= 0 && s.selected < r.levels)
    r.best_d = s.levels[static_cast<std::size_t>(s.selected)].score_D;
  if (s.selected_error) r.success = s.selected_error->success;
  for (std::size_t i = 0; i < s.stage_ms.size(); ++i)
    if (s.stage_ran[i]) r.total_ms += s.stage_ms[i];
  if (!changes.comparable) {
    r.change = "new data";
  } else if (changes.selected_changed()) {
    char text[96];
    std::snprintf(text, sizeof(text), "selected \xce\xb5 %.3g -> %.3g", changes.selected_eps_before,
                  changes.selected_eps_after);
    r.change = text;
  } else {
    int flips = 0, moved = 0;
    for (const LevelChange& l : changes.levels) {
      flips += l.success_flipped || l.validity_flipped;
      moved += l.d_delta && std::abs(*l.d_delta) > 1e-9;
    }
    r.change = flips   ? std::to_string(flips) + " level(s) flipped"
               : moved ? "D changed on " + std::to_string(moved) + " level(s)"
                       : "same result";
  }
  return r;
}

const RunChanges& RunHistory::observe(const std::shared_ptr<const Snapshot>& s, bool dragging) {
  if (dragging && !before_drag_) before_drag_ = last_;
  if (!s || s == last_) return changes_;
  const std::shared_ptr<const Snapshot>& before = before_drag_ ? before_drag_ : last_;
  changes_ = before ? compare_runs(*before, *s) : RunChanges{};
  runs_.push_front(summarize(*s, changes_));
  if (runs_.size() > kMaxRuns) runs_.pop_back();
  last_ = s;
  if (!dragging) before_drag_.reset();  // the first run after the drag: compared, done
  return changes_;
}

}  // namespace pagor::studio
