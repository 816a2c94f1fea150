#include "runners/worker.hpp"

#include <chrono>
#include <filesystem>
#include <new>
#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/registration.hpp"

namespace pagor::studio {

Worker::Worker() : thread_([this] { loop(); }) {}

Worker::~Worker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    cancel_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

std::uint64_t Worker::submit(std::optional<PairSource> data, const Config& config,
                             std::optional<Transform> truth) {
  std::lock_guard<std::mutex> lock(mutex_);
  Request r;
  r.id = ++status_.submitted;
  // A queued data change must survive a newer configuration-only request.
  if (data) {
    r.data = std::move(data);
    r.truth = truth;
  } else if (pending_) {
    r.data = pending_->data;
    r.truth = pending_->truth;
  }
  r.config = config;
  pending_ = std::move(r);
  cancel_ = true;  // the running request, if any, is now outdated
  changed_.notify_all();
  return status_.submitted;
}

std::shared_ptr<const Snapshot> Worker::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return snapshot_;
}

WorkerStatus Worker::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

bool Worker::wait_idle(double timeout_s) const {
  std::unique_lock<std::mutex> lock(mutex_);
  return changed_.wait_for(lock, std::chrono::duration<double>(timeout_s), [this] {
    return status_.finished == status_.submitted && !status_.busy;
  });
}

void Worker::loop() {
  for (;;) {
    Request request;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return stop_ || pending_.has_value(); });
      if (stop_) return;
      request = std::move(*pending_);
      pending_.reset();
      cancel_ = false;
      status_.busy = true;
      status_.error.clear();
    }
    try {
      handle(request);
    } catch (const std::bad_alloc&) {  // the studio keeps running and says so
      std::lock_guard<std::mutex> lock(mutex_);
      status_.error = "out of memory while computing " + describe_request(request) +
                      "; the last result is kept";
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      status_.error = std::string("internal error: ") + e.what();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      status_.busy = pending_.has_value();
      status_.finished = std::max(status_.finished, request.id);
      status_.activity.clear();
    }
    changed_.notify_all();
  }
}

std::string Worker::describe_request(const Request& request) const {
  return request.data ? describe_data(*request.data) : "the current data";
}

bool matches_only(const PairSource& data) {
  return data.kind == PairSource::Kind::files && !data.correspondences.empty() &&
         (data.source.empty() || data.target.empty());
}

std::string describe_data(const PairSource& data) {
  if (data.kind != PairSource::Kind::files || data.correspondences.empty()) return describe(data);
  const std::string name = std::filesystem::path(data.correspondences).filename().string();
  return matches_only(data) ? "correspondences " + name
                            : "correspondences " + name + " on " + describe(data);
}

void Worker::load(const Request& request) {
  const PairSource& data = *request.data;
  // Everything that can fail is read first: a file that cannot be read keeps the current data.
  std::optional<LoadedPair> pair;
  std::optional<Transform> truth = request.truth;
  if (!matches_only(data)) {
    // Unlabelled clouds are fine: the pipeline falls back to class-agnostic landmarks.
    pair = load_pair(data, request.config.indoor);
    if (!truth) truth = pair->T_target_source_gt;
  } else if (!truth && !data.ground_truth.empty()) {
    truth = read_transform_file(data.ground_truth);
  }
  std::optional<CorrespondenceFile> matches;
  if (data.kind == PairSource::Kind::files && !data.correspondences.empty())
    matches = read_correspondence_file(data.correspondences);
  Pipeline next(request.config);  // clouds of an earlier pair must not verify the matches

  source_.reset(), target_.reset(), target_index_.reset(), plan_.reset(), scan_columns_.reset();
  if (pair) {
    source_ = std::make_shared<const PointCloud>(std::move(pair->source.cloud));
    target_ = std::make_shared<const PointCloud>(std::move(pair->target.cloud));
    source_name_ = pair->source_name;
    target_name_ = pair->target_name;
    target_index_ = std::make_shared<const KdTree3f>(target_->points);
    if (pair->plan) {  // a scan against a floor plan
      plan_ = std::make_shared<const FloorPlan>(std::move(*pair->plan));
      scan_columns_ =
          std::make_shared<const std::vector<DetectedColumn>>(std::move(pair->scan_columns));
    }
    next.set_input(*source_, *target_, pair_label_scheme(data));  // a manifest's scheme=
  } else {
    source_name_ = target_name_ = data.correspondences;  // as pagor register names them
  }
  matches_file_.clear();
  inlier_flags_.clear();
  matches_weighted_ = false;
  if (matches) {
    matches_file_ = data.correspondences;
    inlier_flags_ = std::move(matches->inlier);
    matches_weighted_ = !matches->weights.empty();
    next.set_matches(std::move(matches->items));
  }
  ground_truth_ = truth;
  next.set_ground_truth(ground_truth_);
  pipeline_ = std::move(next);
  description_ = describe_data(data);
  ++data_generation_;
}

void Worker::handle(const Request& request) {
  const auto fail = [this](const std::string& message) {
    std::lock_guard<std::mutex> lock(mutex_);
    status_.error = message;
  };
  if (request.data) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      status_.activity = "loading " + describe_request(request);
    }
    try {
      load(request);
    } catch (const Error& e) {
      fail(e.what());
      return;
    }
  }
  try {
    pipeline_.set_config(request.config);
  } catch (const ConfigError& e) {
    fail(e.what());
    return;
  }
  if (!pipeline_.has_input()) return;
  std::array<int, kStageCount> runs_before{};
  for (int s = 0; s < kStageCount; ++s)
    runs_before[static_cast<std::size_t>(s)] = pipeline_.runs(static_cast<Stage>(s));
  try {
    pipeline_.run(
        [this](Stage stage, double fraction) {
          std::lock_guard<std::mutex> lock(mutex_);
          status_.stage = stage;
          status_.fraction = fraction;
          status_.activity = std::string("computing ") + stage_name(stage);
        },
        &cancel_);
  } catch (const Cancelled&) {
    return;  // a newer request is queued
  } catch (const Error& e) {
    fail(e.what());
    return;
  }
  auto snap = make_snapshot(request.id);
  for (int s = 0; s < kStageCount; ++s)
    snap->stage_ran[static_cast<std::size_t>(s)] =
        pipeline_.runs(static_cast<Stage>(s)) != runs_before[static_cast<std::size_t>(s)];
  std::lock_guard<std::mutex> lock(mutex_);
  snapshot_ = std::move(snap);
}

namespace {

// The graph and each verification point's contribution to D, for the diagnosis panel and
// the 3D view; computed here, on the worker thread, never in the UI.
void add_diagnosis(const Pipeline& p, Snapshot& s) {
  s.graph = std::make_shared<const PyramidGraph>(p.graph());
  const Verifier* v = p.verifier();
  if (!v) return;
  s.verification_source = std::make_shared<const std::vector<Eigen::Vector3f>>(v->source_points());
  const double mu = p.config().verification.mu;
  for (const PoseEstimate& e : p.poses())
    s.contributions.push_back(e.valid ? point_contributions(*v, e.T_target_source, mu)
                                      : std::vector<float>());
  if (p.ground_truth()) s.gt_contribution = point_contributions(*v, *p.ground_truth(), mu);
}

}  // namespace

std::shared_ptr<Snapshot> Worker::make_snapshot(std::uint64_t request) const {
  const Pipeline& p = pipeline_;
  RegistrationContext context;
  context.source_name = source_name_;
  context.target_name = target_name_;
  if (!matches_file_.empty())
    context.matches_file = MatchesFileInfo{matches_file_, matches_weighted_, inlier_flags_};
  const Registration r = make_registration(p, context);
  auto s = std::make_shared<Snapshot>();
  s->request = request;
  s->data_generation = data_generation_;
  s->description = description_;
  s->source = source_;
  s->target = target_;
  s->ground_truth = ground_truth_;
  s->plan = plan_;
  s->scan_columns = scan_columns_;
  s->config = r.config;
  s->source_landmarks = p.source_landmarks();
  s->target_landmarks = p.target_landmarks();
  s->correspondences = p.correspondences().items;
  s->correspondences_capped = r.correspondences_capped;
  s->levels = r.levels;
  for (LevelView& l : s->levels)  // the studio draws the clouds in their own frames
    if (l.pose.valid)
      l.pose.T_target_source =
          to_cloud_frames(l.pose.T_target_source, p.source().origin, p.target().origin);
  s->selected = r.selected_level;
  s->acceptance = r.acceptance;
  if (s->acceptance.adopted.applied)  // drawn with the clouds, in their own frames
    s->acceptance.adopted.T_target_source = to_cloud_frames(s->acceptance.adopted.T_target_source,
                                                            p.source().origin, p.target().origin);
  s->refinement = r.refinement;
  s->unrefined_error = r.unrefined_error;
  s->upper_bound = r.any_level_succeeds;
  s->selected_error = r.error;
  s->stage_ms = r.stage_ms;
  s->verification_points = r.verification_points;
  s->warnings = r.warnings;
  add_diagnosis(p, *s);
  s->diagnosis = r.diagnosis;
  s->target_index = target_index_;
  s->matches_file = matches_file_;
  s->inlier_flags = inlier_flags_;
  s->report_json = to_json(r) + "\n";  // as pagor register --json writes it
  return s;
}

}  // namespace pagor::studio
