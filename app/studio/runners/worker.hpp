#pragma once
/// \file worker.hpp
/// Runs the core's pipeline on a background thread so that the UI stays responsive: the UI
/// submits requests (new data and/or a new configuration); a newer request cancels the running
/// one; each finished run is published as an immutable snapshot the UI draws from.

#include <array>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "pagor/eval/dataset.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/registration.hpp"
#include "pagor/util/kdtree.hpp"
#include "pagor/verify/diagnosis.hpp"

namespace pagor::studio {

/// One pyramid level as the UI shows it: the registration's summary of it, its candidate pose in
/// the clouds' own frames (the studio draws them there; Registration's are the frames of the
/// points as given).
using LevelView = LevelSummary;

/// Everything a finished run shows; immutable once published.
struct Snapshot {
  std::uint64_t request = 0;          ///< request it answers
  std::uint64_t data_generation = 0;  ///< changes whenever the clouds change
  std::string description;            ///< the data, in words
  std::shared_ptr<const PointCloud> source, target;
  std::optional<Transform> ground_truth;
  /// Indoor pair (target a floor plan): the plan's walls and columns [m]; null otherwise.
  std::shared_ptr<const FloorPlan> plan;
  /// Indoor pair: the columns found in the scan, in the scan (source) frame [m].
  std::shared_ptr<const std::vector<DetectedColumn>> scan_columns;
  Config config;
  LandmarkSet source_landmarks, target_landmarks;
  std::vector<Correspondence> correspondences;
  bool correspondences_capped = false;
  std::vector<LevelView> levels;
  int selected = -1;
  Acceptance acceptance;                     ///< the verdict on the selected pose
  RefinementResult refinement;               ///< what refinement did to the selected pose
  std::optional<PoseError> unrefined_error;  ///< the selected candidate's errors before refinement
  bool upper_bound = false;
  std::optional<PoseError> selected_error;
  std::array<double, kStageCount> stage_ms{};  ///< last wall time per stage [ms]
  std::array<bool, kStageCount> stage_ran{};   ///< which stages this run recomputed
  std::size_t verification_points = 0;
  std::vector<std::string> warnings;
  // Diagnosis (computed by the worker after the run; see diagnosis.hpp).
  std::optional<Diagnosis> diagnosis;         ///< with ground truth
  std::shared_ptr<const PyramidGraph> graph;  ///< edges around a hovered correspondence
  std::shared_ptr<const std::vector<Eigen::Vector3f>> verification_source;  ///< D's points
  /// Per level, each verification point's min(d, mu) under its candidate [m] (empty: invalid).
  std::vector<std::vector<float>> contributions;
  std::vector<float> gt_contribution;  ///< the same under the ground truth (empty without)
  /// The result as `pagor register --json` writes it (schema pagor.register/1, with the
  /// diagnosis), for the same inputs the same figures.
  std::string report_json;
  /// The target cloud's points indexed, for picking (distance to the nearest target point).
  std::shared_ptr<const KdTree3f> target_index;
  /// A matcher's correspondences file registered (PairSource::correspondences): its name, and its
  /// ground-truth inlier flags (empty without) for each level's precision and recall.
  std::string matches_file;
  std::vector<char> inlier_flags;
};

/// What the worker is doing.
struct WorkerStatus {
  bool busy = false;
  Stage stage = Stage::landmarks;  ///< stage running (when busy)
  double fraction = 0;             ///< overall progress of the run, 0..1
  std::string activity;            ///< e.g. "loading data"
  std::string error;               ///< last error (data or configuration); empty when fine
  std::uint64_t submitted = 0, finished = 0;
};

/// Whether `data` is a matcher's correspondences alone (files mode without both clouds): the back
/// end runs without verification, as pagor register --correspondences FILE does.
bool matches_only(const PairSource& data);
/// describe(data), naming the correspondences file when there is one.
std::string describe_data(const PairSource& data);

class Worker {
 public:
  Worker();
  ~Worker();
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  /// Queues new data (nullopt keeps the current data) and a configuration; returns the request id.
  /// `truth` replaces the data's ground truth (a row of benchmark results carries its own).
  std::uint64_t submit(std::optional<PairSource> data, const Config& config,
                       std::optional<Transform> truth = std::nullopt);
  /// The latest finished snapshot (null before the first).
  std::shared_ptr<const Snapshot> snapshot() const;
  WorkerStatus status() const;
  /// Blocks until every submitted request is handled or `timeout_s` passes; true when idle.
  bool wait_idle(double timeout_s) const;

 private:
  struct Request {
    std::uint64_t id = 0;
    std::optional<PairSource> data;
    std::optional<Transform> truth;
    Config config;
  };
  void loop();
  /// Runs one request. Throws only what the pipeline cannot recover from (std::bad_alloc, ...),
  /// which the loop turns into the status's error: the worker never ends the studio.
  void handle(const Request& request);
  std::string describe_request(const Request& request) const;
  /// Loads new data into the pipeline: clouds, a matcher's correspondences, or both. Throws Error.
  void load(const Request& request);
  std::shared_ptr<Snapshot> make_snapshot(std::uint64_t request) const;

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::optional<Request> pending_;
  std::shared_ptr<const Snapshot> snapshot_;
  WorkerStatus status_;
  std::atomic<bool> cancel_{false};
  bool stop_ = false;

  // Owned by the worker thread.
  Pipeline pipeline_;
  std::shared_ptr<const PointCloud> source_, target_;
  std::optional<Transform> ground_truth_;
  std::shared_ptr<const FloorPlan> plan_;
  std::shared_ptr<const std::vector<DetectedColumn>> scan_columns_;
  std::string description_, source_name_, target_name_;
  std::shared_ptr<const KdTree3f> target_index_;
  std::string matches_file_;        ///< the correspondences file registered (empty: none)
  std::vector<char> inlier_flags_;  ///< its ground-truth flags (empty without)
  bool matches_weighted_ = false;   ///< it has a weight column
  std::uint64_t data_generation_ = 0;
  std::thread thread_;
};

}  // namespace pagor::studio
