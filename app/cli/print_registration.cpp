// What `pagor register` prints, from the one result type (registration.hpp): the labels and
// landmarks, the pyramid table, the selected pose, refinement, the verdict with each of its tests,
// the ground truth and the diagnosis, the stage times.

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <unistd.h>

#include "command.hpp"

namespace pagor::cli {
namespace {

std::string pose_text(const Transform& T) {
  const Eigen::Vector3d a = yaw_pitch_roll_deg(T.block<3, 3>(0, 0));
  char buf[160];
  std::snprintf(buf, sizeof(buf), "t = (%.2f, %.2f, %.2f) m, yaw %.2f, pitch %.2f, roll %.2f deg",
                T(0, 3), T(1, 3), T(2, 3), a[0], a[1], a[2]);
  return buf;
}

// Red on a terminal: the one outcome a loop-closing user cannot afford must not pass unseen.
std::string alarm(const std::string& text) {
  return isatty(fileno(stdout)) ? "\033[1;31m" + text + "\033[0m" : text;
}

void print_front_end(const Registration& r) {
  if (r.selected_by == SelectedBy::score_D || r.origin_all.landmark > 0) {
    std::printf("labels: source %s, target %s\n", labels_text(r.source_labels).c_str(),
                labels_text(r.target_labels).c_str());
    std::printf("landmarks:");
    for (const ClassCount& c : r.classes)
      std::printf(" %s %zu/%zu", c.name.c_str(), c.source, c.target);
    std::printf("  (source/target)\n");
  }
  std::printf(
      "correspondences: %zu%s\n", r.correspondences,
      r.correspondences_capped
          ? (" (capped from " + std::to_string(r.correspondence_candidates) + ")").c_str()
          : "");
}

void print_level_row(const Registration& r, std::size_t l, bool flags, bool gt) {
  const LevelSummary& s = r.levels[l];
  std::printf("%s %-5zu %-8.3f %8zu %9zu %7zu %8zu ",
              static_cast<int>(l) == r.selected_level ? "*" : " ", l, s.epsilon, s.vertices,
              s.edges, s.clique.size(), s.pose.inliers.size());
  if (flags) {
    if (s.file_inliers)
      std::printf(" %10.3f %9.3f", s.file_inliers->precision, s.file_inliers->recall);
    else
      std::printf(" %10s %9s", "-", "-");
  }
  if (r.selected_by == SelectedBy::score_D) {
    if (std::isfinite(s.score_D))
      std::printf(" %13.1f", s.score_D);
    else
      std::printf(" %13s", "invalid");
  } else if (s.support && std::isfinite(s.support_score)) {
    std::printf(" %8d %10.1f", *s.support, s.support_score);
  } else {
    std::printf(" %8s %10s", "-", "invalid");
  }
  if (gt && s.error)
    std::printf(" %10.2f %11.2f %4s", s.error->translation, s.error->rotation_deg,
                s.error->success ? "yes" : "no");
  std::printf("\n");
}

// One line per level whose clique search says more than its size: a proof of maximality (exact
// solver), or a budget that cut the search short, with the bound it reached.
void print_clique_search(const Registration& r) {
  const bool exact = r.config.clique.solver == CliqueSolver::exact;
  for (std::size_t l = 0; l < r.levels.size(); ++l) {
    const LevelSummary& s = r.levels[l];
    const char* budget = s.clique_budget == CliqueBudget::nodes ? "node" : "time";
    if (s.clique_budget == CliqueBudget::probe)  // not settled: no full search, no fallback
      std::printf(
          "  level %zu: not settled (search of clique.probe_nodes, no fallback): %zu members%s\n",
          l,
          s.clique.size(),
          s.clique_number_bound > static_cast<int>(s.clique.size())
              ? (", at most " + std::to_string(s.clique_number_bound)).c_str()
              : "");
    else if (s.clique_budget != CliqueBudget::none &&
             s.clique_number_bound > static_cast<int>(s.clique.size()))
      std::printf("  level %zu: clique search stopped by its %s budget: %zu members, at most %d\n",
                  l, budget, s.clique.size(), s.clique_number_bound);
    else if (s.clique_budget != CliqueBudget::none)  // stopped before any bound was reached
      std::printf("  level %zu: clique search stopped by its %s budget: %zu members, no bound\n",
                  l, budget, s.clique.size());
    else if (exact && s.clique_proven)
      std::printf("  level %zu: clique of %zu proven maximum\n", l, s.clique.size());
    if (s.clique_start == CliqueStart::fallback)
      std::printf("  level %zu: the warm start lost to a cold one and was dropped\n", l);
  }
}

void print_levels(const Registration& r) {
  const bool flags = r.matches_file && !r.matches_file->inliers.empty();
  const bool gt = r.T_target_source_gt.has_value();
  const bool scored = r.selected_by == SelectedBy::score_D;
  std::printf("\n  %-5s %-8s %8s %9s %7s %8s", "level", "epsilon", "vertices", "edges", "clique",
              "inliers");
  if (flags) std::printf(" %10s %9s", "flag prec.", "flag rec.");
  if (scored)
    std::printf(" %13s", "score D [m]");
  else
    std::printf(" %8s %10s", "support", "S [m]");
  if (gt) std::printf(" %10s %11s %4s", "t err [m]", "r err [deg]", "ok");
  std::printf("\n");
  for (std::size_t l = 0; l < r.levels.size(); ++l) print_level_row(r, l, flags, gt);
  print_clique_search(r);
  if (scored)
    std::printf(
        "  (* selected: lowest D; D = sum of min(distance, %.2f m) over %zu source points)\n",
        r.config.verification.mu, r.verification_points);
  else
    std::printf(
        "  (* selected: lowest S = sum of min(residual, noise bound) over all correspondences; "
        "support: those within the bound (no clouds to verify on))\n");
  if (flags)
    std::printf(
        "  (flag prec., flag rec.: each clique's precision and recall against the file's inlier "
        "flags, not against the ground truth the diagnosis uses)\n");
}

void print_pose_and_refinement(const Registration& r) {
  const AcceptanceAdoption& adopted = r.acceptance.adopted;
  if (r.T_target_source && adopted.applied)
    std::printf(
        "\nselected level %d (lowest D), replaced by the verdict's alternative: %s\n"
        "  adopted: %s fitted %.2f times as well where both poses are seen; refitted by GNC on %zu "
        "inliers; the selected pose was not accepted (%s)\n",
        r.selected_level, pose_text(*r.T_target_source).c_str(), adopted.from.c_str(),
        adopted.ratio, adopted.inliers.size(), adopted.selected_reason.c_str());
  else if (r.T_target_source)
    std::printf("\nselected level %d: %s\n", r.selected_level,
                pose_text(*r.T_target_source).c_str());
  else
    std::printf("\nno valid candidate on any level\n");
  const RefinementResult& f = r.refinement;
  if (f.ran && f.applied)
    std::printf("refinement: applied, D %.1f -> %.1f m, moved %.2f m / %.2f deg in %d iterations\n",
                f.score_before, f.score_after, f.correction_translation, f.correction_rotation,
                f.iterations);
  else if (f.ran)
    std::printf("refinement: not applied (%s)\n", f.reason.c_str());
}

void print_verdict(const Registration& r) {
  const Acceptance& a = r.acceptance;
  if (!a.verified) {
    std::printf("verdict: not verified (%s)\n", a.reason.c_str());
    return;
  }
  if (r.selected_level < 0) return;
  std::printf("verdict: %s%s%s\n", a.accepted ? "ACCEPTED" : "REJECTED", a.accepted ? "" : ": ",
              a.reason.c_str());
  std::printf("  tests: %s (aligned: within %.2f m)\n", acceptance_tests_text(r).c_str(),
              r.config.acceptance.inlier_distance);
  if (!a.alternative.description.empty())
    std::printf(
        "  best distinct alternative: %s, %.2f times as well supported (%zu points only it "
        "aligns, %zu only the selected pose)\n",
        a.alternative.description.c_str(), a.alternative.ratio, a.alternative.only_alternative,
        a.alternative.only_selected);
}

void print_ground_truth(const Registration& r) {
  if (!r.T_target_source_gt) return;
  const char* bound = r.any_level_succeeds ? "yes" : "no";
  if (r.unrefined_error && r.refinement.applied)
    std::printf(
        "ground truth before refinement: translation error %.2f m, rotation error %.2f deg\n",
        r.unrefined_error->translation, r.unrefined_error->rotation_deg);
  if (const auto& e = r.error) {
    std::printf(
        "ground truth: translation error %.2f m, rotation error %.2f deg -> %s "
        "(criterion %g m / %g deg); any level right: %s\n",
        e->translation, e->rotation_deg, e->success ? "SUCCESS" : "FAILURE",
        r.config.evaluation.max_translation_error, r.config.evaluation.max_rotation_error, bound);
  } else {
    std::printf("ground truth: FAILURE (no pose); any level right: %s\n", bound);
  }
  if (r.accepted_wrong())
    std::printf("%s\n", alarm("WRONG POSE ACCEPTED: the verdict trusted a pose the ground truth "
                              "calls wrong").c_str());
}

// Per origin, when a matcher's correspondences took part: the correspondences, and of the selected
// clique how many (and, with a diagnosis, how many true ones) come from each.
void print_origins(const Registration& r) {
  if (r.origin_all.matcher == 0) return;
  std::printf("\ncorrespondences by origin: landmark %zu, matcher %zu\n", r.origin_all.landmark,
              r.origin_all.matcher);
  if (r.selected_level < 0) return;
  std::printf("selected clique by origin: landmark %zu, matcher %zu", r.origin_clique.landmark,
              r.origin_clique.matcher);
  const auto sel = static_cast<std::size_t>(r.selected_level);
  if (r.diagnosis && sel < r.diagnosis->levels.size()) {
    const OriginCounts& t = r.diagnosis->levels[sel].clique_true_origin;
    std::printf(" (true: landmark %zu, matcher %zu)", t.landmark, t.matcher);
  }
  std::printf("\n");
}

void print_times(const Registration& r) {
  std::printf("times [ms]:");
  double total = 0;
  for (Stage s : {Stage::landmarks, Stage::correspondences, Stage::graph, Stage::clique,
                  Stage::gnc, Stage::verification_prep, Stage::verification, Stage::refinement,
                  Stage::acceptance}) {
    const double ms = r.stage_ms[static_cast<std::size_t>(s)];
    std::printf(" %s %.1f", stage_name(s), ms);
    total += ms;
  }
  std::printf(" | total %.1f\n", total);
}

}  // namespace

std::string acceptance_tests_text(const Registration& r) {
  std::string text;
  for (const AcceptanceTest& t : r.acceptance.tests) {
    if (!t.applies) continue;
    text += (text.empty() ? "" : ", ") + test_text(t);
  }
  return text;
}

void report_registration(const Args& args, const Pipeline& pipeline,
                         const RegistrationContext& context) {
  const Registration result = make_registration(pipeline, context);
  print_registration(result);
  if (args.has("json")) {
    write_text_file(args.get("json"), to_json(result) + "\n");
    std::printf("wrote %s\n", args.get("json").c_str());
  }
}

void print_registration(const Registration& r) {
  print_front_end(r);
  print_levels(r);
  print_pose_and_refinement(r);
  print_verdict(r);
  print_ground_truth(r);
  print_origins(r);
  if (r.diagnosis)
    std::printf("diagnosis: %s: %s\n", verdict_sentence(r.diagnosis->verdict),
                r.diagnosis->explanation.c_str());
  print_times(r);
}

}  // namespace pagor::cli
