#include "pagor/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "pagor/errors.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "pagor/verify/level_selection.hpp"
#include "util/parallel.hpp"

namespace pagor {
namespace {

// Direct dependents of each stage.
const std::vector<Stage>& dependents(Stage s) {
  static const std::array<std::vector<Stage>, kStageCount> table = {{
      {Stage::correspondences},  // landmarks
      {Stage::graph},            // correspondences
      {Stage::clique},           // graph
      {Stage::gnc},              // clique
      {Stage::verification},     // pose
      {Stage::verification},     // verification_prep
      {Stage::refinement},       // verification
      {Stage::acceptance},       // refinement
      {Stage::evaluation},       // acceptance
      {},                        // evaluation
  }};
  return table[static_cast<std::size_t>(s)];
}

}  // namespace

const char* stage_name(Stage stage) {
  static const char* const names[kStageCount] = {
      "landmarks",         "correspondences", "graph",      "clique",     "gnc",
      "verification_prep", "verification",    "refinement", "acceptance", "evaluation"};
  return names[static_cast<int>(stage)];
}

Pipeline::Pipeline(Config config, int threads) : threads_(threads < 1 ? 1 : threads) {
  validate(config);
  config_ = std::move(config);
  stale_.fill(true);
}

void Pipeline::mark_stale(Stage s) {
  stale_[static_cast<std::size_t>(s)] = true;
  for (Stage d : dependents(s)) mark_stale(d);
}

bool Pipeline::up_to_date() const {
  for (bool s : stale_)
    if (s) return false;
  return true;
}

void Pipeline::set_input(PointCloud source, PointCloud target,
                         std::optional<LabelScheme> label_scheme) {
  source_ = std::move(source);
  target_ = std::move(target);
  input_scheme_ = std::move(label_scheme);
  has_clouds_ = true;
  ground_.reset();
  mark_stale(Stage::landmarks);
  mark_stale(Stage::verification_prep);
}

void Pipeline::set_matches(std::vector<Correspondence> matches) {
  const bool mode_changes = matches.empty() != matches_.empty();
  matches_ = std::move(matches);
  mark_stale(mode_changes ? Stage::landmarks : Stage::correspondences);
}

bool Pipeline::uses_landmarks() const {
  return has_clouds_ && (matches_.empty() || config_.correspondences.fuse_matches);
}

void Pipeline::set_ground_truth(std::optional<Transform> T) {
  ground_truth_ = std::move(T);
  mark_stale(Stage::evaluation);
}

namespace {

// The first stage each section's parameters feed (the later ones follow by `dependents`); a new
// section without an entry here does not compile.
std::optional<Stage> first_stage(const LabelScheme&) {
  return Stage::landmarks;
}
std::optional<Stage> first_stage(const LandmarkParams&) {
  return Stage::landmarks;
}
std::optional<Stage> first_stage(const CorrespondenceParams&) {
  return Stage::correspondences;
}
std::optional<Stage> first_stage(const GraphParams&) {
  return Stage::graph;
}
std::optional<Stage> first_stage(const CliqueParams&) {
  return Stage::clique;
}
std::optional<Stage> first_stage(const GncParams&) {
  return Stage::gnc;
}
std::optional<Stage> first_stage(const VerificationParams&) {
  return Stage::verification;
}
std::optional<Stage> first_stage(const RefinementParams&) {
  return Stage::refinement;
}
std::optional<Stage> first_stage(const AcceptanceParams&) {
  return Stage::acceptance;
}
// The criterion also decides which candidates count as distinct for the D margin.
std::optional<Stage> first_stage(const EvaluationParams&) {
  return Stage::acceptance;
}
// Indoor parameters act when a pair is loaded (load_pair: the plan's sampling, the scan's
// projection), before the pipeline.
std::optional<Stage> first_stage(const IndoorParams&) {
  return std::nullopt;
}

}  // namespace

void Pipeline::set_config(const Config& config) {
  validate(config);
  Config::sections([&](auto member, const FieldInfo& f) {
    const std::optional<Stage> stage = first_stage(config.*member);
    if (stage && section_json(config, f.key) != section_json(config_, f.key)) mark_stale(*stage);
  });
  // The fields that feed a stage outside their section's chain.
  if (config.verification.voxel_size != config_.verification.voxel_size)
    mark_stale(Stage::verification_prep);
  if (config.correspondences.fuse_matches != config_.correspondences.fuse_matches &&
      !matches_.empty())
    mark_stale(Stage::landmarks);  // whether they take part
  // What counts as the same answer decides whether the selected level is settled.
  if (config.acceptance.distinct_translation != config_.acceptance.distinct_translation ||
      config.acceptance.distinct_rotation != config_.acceptance.distinct_rotation)
    mark_stale(Stage::verification);
  config_ = config;
}

void Pipeline::run(const ProgressFn& progress, const std::atomic<bool>* cancel) {
  if (!has_input())
    throw InputError("the pipeline has no input: neither clouds nor a matcher's correspondences");
  run_started_ = std::chrono::steady_clock::now();
  const int clique_runs = runs_[static_cast<std::size_t>(Stage::clique)];
  for (int i = 0; i < kStageCount; ++i) {
    if (!stale_[static_cast<std::size_t>(i)]) continue;
    if (cancel && cancel->load()) throw Cancelled();
    const Stage s = static_cast<Stage>(i);
    if (progress) progress(s, static_cast<double>(i) / kStageCount);
    const auto t0 = std::chrono::steady_clock::now();
    run_stage(s);
    times_[static_cast<std::size_t>(i)] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    // Settling the selected level (select_and_settle) is clique work: in a run that ran the
    // clique stage, its time is that stage's (a re-run of the selection alone keeps it).
    if (s == Stage::verification && runs_[static_cast<std::size_t>(Stage::clique)] > clique_runs) {
      times_[static_cast<std::size_t>(Stage::verification)] -= settle_ms_;
      times_[static_cast<std::size_t>(Stage::clique)] += settle_ms_;
    }
    ++runs_[static_cast<std::size_t>(i)];
    stale_[static_cast<std::size_t>(i)] = false;
  }
  if (progress) progress(Stage::evaluation, 1.0);
}

template <class F>
void Pipeline::both_clouds(const F& f) {
  // The two clouds are independent; of two failures, the source's is reported.
  parallel_pair(
      threads_now(), [&] { f(source_, source_landmarks_); },
      [&] { f(target_, target_landmarks_); });
}

void Pipeline::run_stage(Stage stage) {
  switch (stage) {
    case Stage::landmarks: {
      source_landmarks_ = LandmarkSet{};
      target_landmarks_ = LandmarkSet{};
      if (!uses_landmarks()) {
        // No landmarks, but the clouds' labels are still read as the landmarks would read them:
        // the report, the diagnosis and a viewer colour each cloud in that scheme.
        if (has_clouds_) {
          source_landmarks_.labels = read_labels(source_, label_scheme());
          target_landmarks_.labels = read_labels(target_, label_scheme());
        }
        break;
      }
      const auto extract = [this](const PointCloud& cloud, LandmarkSet& out) {
        out = extract_landmarks(cloud, label_scheme(), config_.landmarks);
      };
      const auto fallback = [this](const PointCloud& cloud, LandmarkSet& out) {
        add_fallback_landmarks(cloud, label_scheme(), config_.landmarks, out);
      };
      both_clouds(extract);
      warn_if_numberings_differ();
      warn_if_numbering_unsure();
      // Class-agnostic landmarks when the pair is unlabelled or class-poor; both clouds get
      // them, so the class lists stay aligned for matching.
      if (needs_fallback(source_, target_, source_landmarks_, target_landmarks_,
                         config_.landmarks.fallback))
        both_clouds(fallback);
      break;
    }
    case Stage::correspondences:
      run_correspondences();
      break;
    case Stage::graph:
      graph_.build(correspondences_.items, config_.graph, threads_now());
      break;
    case Stage::clique: {
      const Deadline deadline = clique_deadline();
      first_cliques_ = solve_pyramid(graph_.graph(), config_.clique, deadline, threads_now());
      // A level cut short by time after the pair's deadline (not by the exact solver's own share).
      pass_budget_hit_ = false;
      if (deadline != kNoDeadline && std::chrono::steady_clock::now() > deadline)
        for (const CliqueResult& c : first_cliques_)
          pass_budget_hit_ |= c.budget == CliqueBudget::time;
      cliques_ = first_cliques_;  // until the selection settles one
      pair_budget_hit_ = pass_budget_hit_;
      // What the pair's budget leaves for settling the selected level (select_and_settle).
      clique_left_ = deadline == kNoDeadline ? std::chrono::steady_clock::duration::max()
                                             : deadline - std::chrono::steady_clock::now();
      break;
    }
    case Stage::gnc:
      run_gnc();
      break;
    case Stage::verification_prep:
      refiner_.reset();  // it refers to the verifier
      verifier_.reset();
      if (has_clouds_)
        verifier_.emplace(source_, target_, config_.verification.voxel_size, threads_now());
      break;
    case Stage::verification:
      select_and_settle();
      break;
    case Stage::refinement:
      run_refinement();
      break;
    case Stage::acceptance:
      judge_acceptance();
      break;
    case Stage::evaluation:
      level_errors_.clear();
      if (ground_truth_)
        for (const PoseEstimate& e : poses_)
          level_errors_.push_back(e.valid
                                      ? std::optional<PoseError>(pose_error(
                                            e.T_target_source, *ground_truth_, config_.evaluation))
                                      : std::nullopt);
      break;
  }
}

void Pipeline::run_correspondences() {
  if (matches_.empty()) {
    correspondences_ = match_landmarks(source_landmarks_, target_landmarks_,
                                       config_.correspondences, threads_now());
    return;
  }
  CorrespondenceSet landmark_ones;
  if (uses_landmarks())
    landmark_ones = match_landmarks(source_landmarks_, target_landmarks_, config_.correspondences,
                                    threads_now());
  correspondences_ = with_matches(matches_, std::move(landmark_ones),
                                  static_cast<int>(source_landmarks_.landmarks.size()),
                                  static_cast<int>(target_landmarks_.landmarks.size()));
}

// Clouds of one pair read in two numberings (each detected on its own) are worth a word: each is
// read in its own, but the user's data may be mixed up.
void Pipeline::warn_if_numberings_differ() {
  const LabelReading& s = source_landmarks_.labels;
  const LabelReading& t = target_landmarks_.labels;
  if (s.scheme.ignores_labels() || t.scheme.ignores_labels() || s.scheme.name == t.scheme.name)
    return;
  target_landmarks_.warnings.push_back("labels in numbering '" + t.scheme.name +
                                       "', the source's in '" + s.scheme.name +
                                       "' (each cloud is read in its own)");
}

// A detected numbering that another explains almost as well is a guess the user should settle.
void Pipeline::warn_if_numbering_unsure() {
  for (LandmarkSet* set : {&source_landmarks_, &target_landmarks_}) {
    const std::string doubt = numbering_doubt(set->labels);
    if (!doubt.empty()) set->warnings.push_back(doubt);
  }
}

GncParams Pipeline::gnc_params() const {
  GncParams p = config_.gnc;
  if (p.model == PoseModel::automatic && ground_ &&
      gravity_aligned(ground_->first, ground_->second, p.level_tolerance))
    p.model = PoseModel::four_dof;
  return p;
}

void Pipeline::run_gnc() {
  if (config_.gnc.model == PoseModel::automatic && has_clouds_ && !ground_)
    ground_.emplace(ground_plane(source_), ground_plane(target_));
  const GncParams params = gnc_params();
  first_poses_.clear();
  for (const CliqueResult& c : first_cliques_)
    first_poses_.push_back(estimate_pose_gnc(correspondences_.items, c.vertices, params));
  poses_ = first_poses_;  // until the selection settles a level
}

// The selection, with clique.settle_selected the selected level settled (settle_selection): it
// starts from the clique and GNC stages' results each time, so that a re-run of this stage alone
// (a verification setting changed) gives what a full run gives. Settling has what the pair's
// budget left at the end of the clique stage (clique_left_). Its time, refits included and
// selections not, is clique work (settle_ms_).
void Pipeline::select_and_settle() {
  using Clock = std::chrono::steady_clock;
  cliques_ = first_cliques_;
  poses_ = first_poses_;
  const auto t0 = Clock::now();
  Clock::duration selecting{0};
  const auto select = [&] {
    const auto ts = Clock::now();
    verification_ =
        verifier_ ? verify_candidates(*verifier_, poses_, config_.verification, threads_now())
                  : select_without_clouds(poses_, correspondences_.items, config_.gnc.noise_bound);
    selecting += Clock::now() - ts;
    return verification_.selected;
  };
  const GncParams params = gnc_params();
  const auto refit = [&](int level) {
    const auto l = static_cast<std::size_t>(level);
    poses_[l] = estimate_pose_gnc(correspondences_.items, cliques_[l].vertices, params);
  };
  // The same answer as a settled level's candidate (within the acceptance's distinct_*):
  // settling the selected level then cannot change which answer the pair gets.
  const auto same_answer = [&](int level) {
    std::vector<char> settled;
    for (const CliqueResult& c : cliques_) settled.push_back(c.settled);
    return same_answer_as(poses_, level, settled, config_.acceptance.distinct()) >= 0;
  };
  const Deadline deadline =
      clique_left_ == Clock::duration::max() ? kNoDeadline : t0 + clique_left_;
  settle_selection(graph_.graph(), cliques_, config_.clique, deadline, select, refit, same_answer,
                   threads_now());
  const auto t1 = Clock::now();
  settle_ms_ = std::chrono::duration<double, std::milli>(t1 - t0 - selecting).count();
  pair_budget_hit_ = pass_budget_hit_;
  if (deadline != kNoDeadline && t1 > deadline)
    for (const CliqueResult& c : cliques_) pair_budget_hit_ |= c.budget == CliqueBudget::time;
}

void Pipeline::run_refinement() {
  refinement_ = RefinementResult{};
  const RefinementParams& params = config_.refinement;
  if (!params.enabled || verification_.selected < 0 || !verifier_) return;
  if (!refiner_ || refiner_->normal_radius() != params.normal_radius)
    refiner_.emplace(*verifier_, params.normal_radius);
  const auto sel = static_cast<std::size_t>(verification_.selected);
  // The model the selected pose was fitted in (with `automatic`, the one GNC kept).
  refinement_ = refiner_->refine(poses_[sel].T_target_source, verification_.scores[sel],
                                 poses_[sel].model, params, config_.verification, threads_now());
}

void Pipeline::judge_acceptance() {
  if (!verifier_) {
    acceptance_ = Acceptance{};
    acceptance_.verified = false;
    if (verification_.selected >= 0)
      acceptance_.inliers =
          static_cast<int>(poses_[static_cast<std::size_t>(verification_.selected)].inliers.size());
    acceptance_.reason = verification_.selected < 0 ? "no valid candidate"
                                                    : "nothing to verify on: no clouds were given";
    return;
  }
  // The verifier's source points on furniture: a floor scan's cells that its higher beams passed
  // over (prepare_floor_scan, IndoorParams::furniture_gap), whatever scheme the labels are read in.
  std::vector<char> furniture;
  const std::vector<std::uint32_t>& labels = verifier_->source_labels();
  if (std::find(labels.begin(), labels.end(), kFurnitureLabel) != labels.end()) {
    furniture.resize(labels.size());
    for (std::size_t i = 0; i < labels.size(); ++i) furniture[i] = labels[i] == kFurnitureLabel;
  }
  const std::vector<char>* on_furniture = furniture.empty() ? nullptr : &furniture;
  const PoseModel model = verification_.selected >= 0
                              ? poses_[static_cast<std::size_t>(verification_.selected)].model
                              : config_.gnc.model;
  // Judge the pose the user gets: the refined one, with its own D.
  std::vector<PoseEstimate> candidates = poses_;
  VerificationResult verification = verification_;
  if (refinement_.applied) {
    const auto sel = static_cast<std::size_t>(verification_.selected);
    candidates[sel].T_target_source = refinement_.T_after;
    verification.scores[sel] = refinement_.score_after;
    verification.selected_distances = refinement_.distances_after;
  }
  // The unique landmarks' poses, searched once and only if an ambiguity test asks for them.
  std::optional<std::vector<NamedPose>> found;
  const std::function<std::vector<NamedPose>()> anchored = [&] {
    if (!found) found = anchored_alternatives();
    return *found;
  };
  acceptance_ =
      judge_selection(*verifier_, candidates, verification, config_.verification,
                      config_.acceptance, model, threads_now(), on_furniture, false, anchored);
  adopt_alternative(std::move(candidates), std::move(verification), on_furniture, anchored);
}

std::vector<NamedPose> Pipeline::anchored_alternatives() const {
  std::vector<NamedPose> out;
  const PyramidGraph& g = graph_.graph();
  const std::vector<Correspondence>& items = correspondences_.items;
  if (!uses_landmarks() || g.vertices != static_cast<int>(items.size())) return out;
  // The anchors: the one correspondence of a clustered class with one landmark on each side.
  const auto& sc = source_landmarks_.classes;
  const auto& tc = target_landmarks_.classes;
  std::vector<int> anchors;
  for (std::size_t k = 0; k < sc.size() && k < tc.size(); ++k) {
    if (sc[k].method != LandmarkMethod::cluster || sc[k].landmarks != 1 || tc[k].landmarks != 1)
      continue;
    int found = -1, seen = 0;
    for (std::size_t i = 0; i < items.size(); ++i)
      if (items[i].origin == CorrespondenceOrigin::landmark &&
          items[i].class_index == static_cast<int>(k))
        found = static_cast<int>(i), ++seen;
    if (seen != 1) continue;
    anchors.push_back(found);
  }
  if (anchors.empty()) return out;
  const GncParams gnc = gnc_params();
  const EvaluationParams distinct = config_.acceptance.distinct();
  std::vector<Transform> kept;
  for (int l = 0; l < g.levels(); ++l) {
    const std::vector<int> members = clique_through(g, l, anchors, config_.clique.probe_nodes);
    const PoseEstimate pose = estimate_pose_gnc(items, members, gnc);
    if (!pose.valid) continue;
    const bool again = std::any_of(kept.begin(), kept.end(), [&](const Transform& T) {
      return pose_error(pose.T_target_source, T, distinct).success;
    });
    if (again) continue;
    kept.push_back(pose.T_target_source);
    // The classes of the anchors the clique holds (a subset when they disagree), three named.
    std::string names;
    int named = 0, more = 0;
    for (int a : anchors) {
      if (!std::binary_search(members.begin(), members.end(), a)) continue;
      if (named == 3) {
        ++more;
        continue;
      }
      names += (named++ ? ", " : "") +
               correspondence_class_name(items[static_cast<std::size_t>(a)], source_landmarks_);
    }
    if (more) names += " and " + std::to_string(more) + " more";
    out.push_back({pose.T_target_source, "the pose its unique landmarks fix",
                   names + "; " + std::to_string(members.size()) + " correspondences at level " +
                       std::to_string(l)});
  }
  return out;
}

void Pipeline::adopt_alternative(std::vector<PoseEstimate> candidates,
                                 VerificationResult verification,
                                 const std::vector<char>* furniture,
                                 const std::function<std::vector<NamedPose>()>& anchored) {
  const AcceptanceParams& params = config_.acceptance;
  const AcceptanceAlternative& alt = acceptance_.alternative;
  // Overturning the selection asks the evidence to be decisive twice over: the alternative must
  // out-fit it by the square of what the ambiguity test asks of a pose against its rival, at
  // adopt_max_ambiguity (3.3 at 0.55), and the refitted pose must meet that test's threshold. Car
  // parks 1-14: a right pose rivalled by its half turn, 19 points against 0 (ratio 2.9: the
  // as-built walls are not the plan's), was replaced by the turn at the former bar, 1 /
  // max_ambiguity (1.8); the right adoptions have ratios 3.2-46, the self-similar scenes' 5.3-8.6.
  if (!params.adopt_alternative || acceptance_.accepted || alt.description.empty() ||
      !(alt.ratio > params.adoption_bar()))
    return;
  // The correspondences the alternative explains (within the TLS bound, measured as GNC measures
  // them), and the pose they give.
  const GncParams gnc = gnc_params();
  std::vector<int> members;
  for (std::size_t i = 0; i < correspondences_.items.size(); ++i) {
    const Correspondence& c = correspondences_.items[i];
    if (std::sqrt(squared_residual(alt.T_target_source, c.p, c.q, gnc.model)) <= gnc.noise_bound)
      members.push_back(static_cast<int>(i));
  }
  PoseEstimate refit = estimate_pose_gnc(correspondences_.items, members, gnc);
  const auto sel = static_cast<std::size_t>(verification.selected);
  const char* failed = nullptr;
  if (!refit.valid)
    failed = "no pose";
  else if (!pose_error(refit.T_target_source, alt.T_target_source, params.distinct()).success)
    failed = "it moved away from the alternative";
  else if (pose_error(refit.T_target_source, candidates[sel].T_target_source, params.distinct())
               .success)
    failed = "it fell back to the selected pose's answer";
  Acceptance adopted;
  if (!failed) {
    candidates.push_back(refit);
    std::vector<float> distances;
    verification.scores.push_back(verifier_->score(refit.T_target_source, config_.verification.mu,
                                                   config_.verification.score, threads_now(),
                                                   &distances));
    verification.selected = static_cast<int>(candidates.size()) - 1;
    verification.selected_distances = std::move(distances);
    verification.distance_bound = static_cast<float>(config_.verification.mu);
    AcceptanceParams strict = params;
    strict.max_ambiguity = params.adopted_max_ambiguity();
    adopted = judge_selection(*verifier_, candidates, verification, config_.verification, strict,
                              refit.model, threads_now(), furniture, true, anchored);
    if (strict.max_ambiguity < params.max_ambiguity) {
      // Say which threshold judged it: not the max_ambiguity the configuration shows. (The
      // ambiguity is judged only where every other test passed, so where it failed the reason is
      // its own.)
      char note[160];
      std::snprintf(note, sizeof(note),
                    " (an adopted alternative is judged at acceptance.adopt_max_ambiguity, %.3g, "
                    "below max_ambiguity)",
                    strict.max_ambiguity);
      for (AcceptanceTest& t : adopted.tests) {
        if (t.name != "ambiguity") continue;
        t.description += note;
        if (t.applies && !t.passed) adopted.reason += note;
      }
    }
  }
  if (failed || !adopted.accepted) {
    char buf[96];
    std::snprintf(buf, sizeof(buf), "; refitted on the %zu correspondences it explains, ",
                  members.size());
    acceptance_.reason +=
        buf + std::string(failed ? failed : "it was not trusted either: " + adopted.reason);
    return;
  }
  adopted.adopted = {true,      refit.T_target_source,      refit.inliers,     alt.description,
                     alt.ratio, verification.scores.back(), acceptance_.reason};
  acceptance_ = std::move(adopted);
}

std::optional<Transform> Pipeline::selected_transform() const {
  if (verification_.selected < 0 ||
      static_cast<std::size_t>(verification_.selected) >= poses_.size())
    return std::nullopt;
  if (acceptance_.adopted.applied) return acceptance_.adopted.T_target_source;
  if (refinement_.applied) return refinement_.T_after;
  return poses_[static_cast<std::size_t>(verification_.selected)].T_target_source;
}

std::optional<PoseError> Pipeline::selected_error() const {
  const auto T = selected_transform();
  if (!T || !ground_truth_) return std::nullopt;
  return pose_error(*T, *ground_truth_, config_.evaluation);
}

std::optional<PoseError> Pipeline::unrefined_error() const {
  if (verification_.selected < 0 || !ground_truth_) return std::nullopt;
  return pose_error(poses_[static_cast<std::size_t>(verification_.selected)].T_target_source,
                    *ground_truth_, config_.evaluation);
}

bool Pipeline::upper_bound_success() const {
  // Any pose the pipeline made: each level's candidate, and the selection after refinement (so
  // the bound is never below the success of the selected pose).
  if (const auto e = selected_error(); e && e->success) return true;
  for (const auto& e : level_errors_)
    if (e && e->success) return true;
  return false;
}

bool Pipeline::pair_time_budget_hit() const {
  return pair_budget_hit_;
}

Deadline Pipeline::clique_deadline() const {
  if (config_.clique.pair_time_budget_ms <= 0) return kNoDeadline;
  return run_started_ + std::chrono::microseconds(
                            static_cast<long long>(1000.0 * config_.clique.pair_time_budget_ms));
}

std::vector<std::string> Pipeline::warnings() const {
  std::vector<std::string> out;
  for (const auto& w : source_landmarks_.warnings) out.push_back("source: " + w);
  for (const auto& w : target_landmarks_.warnings) out.push_back("target: " + w);
  for (const auto& w : correspondences_.warnings) out.push_back(w);
  for (std::size_t l = 0; l < poses_.size(); ++l)
    if (!poses_[l].valid)
      out.push_back("level " + std::to_string(l) + ": no pose (" + poses_[l].failure + ")");
  if (!poses_.empty() && verification_.selected < 0)
    out.push_back("no valid candidate on any level");
  if (pair_time_budget_hit()) {
    std::string cut;
    for (const CliqueResult& c : cliques_)
      if (c.budget == CliqueBudget::time)
        cut += (cut.empty() ? "" : ", ") + std::to_string(c.level);
    out.push_back("the pair's time budget (clique.pair_time_budget_ms = " +
                  number_text(config_.clique.pair_time_budget_ms) +
                  " ms) ran out in the clique search: level(s) " + cut +
                  " kept the best clique found so far, not proven maximum");
  }
  return out;
}

}  // namespace pagor
