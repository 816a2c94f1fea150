// pagor bench: every pair of a pairs file, one JSON line per pair, and a summary table.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "bench_journal.hpp"
#include "command.hpp"
#include "pagor/errors.hpp"
#include "pagor/kitti.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/report.hpp"

namespace pagor::cli {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// What the summary needs of a pair taken from an earlier run's line.
struct ResumedPair {
  bool success = false, upper_bound = false;
  double total_ms = 0;
};
ResumedPair resumed_pair(const nlohmann::json& line) {
  ResumedPair r;
  const auto gt = line.find("ground_truth");
  if (gt != line.end() && gt->is_object()) {
    r.success = gt->value("success", false);
    r.upper_bound = gt->value("upper_bound", false);
  }
  const auto t = line.find("timings_ms");
  if (t != line.end() && t->is_object() && t->contains("total") && (*t)["total"].is_number())
    r.total_ms = (*t)["total"].get<double>();
  return r;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

}  // namespace

std::vector<Option> bench_options() {
  return {{"kitti-root", 1, "DIR", "KITTI root holding sequences/"},
          {"sequence", 1, "SEQ", "KITTI sequence (default 00)"},
          {"pairs", 1, "FILE", "pairs file: 'source target' frame numbers per line"},
          {"config", 1, "FILE", "configuration JSON (default: built-in outdoor defaults)"},
          {"out", 1, "FILE", "write one JSON line per pair (pagor.register/1 without config)"},
          {"resume", 0, "", "with --out: continue a killed run, skipping pairs already written"},
          {"threads", 1, "N", "threads for graph construction and verification (default 1)"}};
}

int run_bench(const Args& args) {
  if (!args.has("kitti-root") || !args.has("pairs"))
    throw UsageError("bench needs --kitti-root DIR and --pairs FILE");
  const Config config = config_from_args(args);
  const KittiSequence seq(args.get("kitti-root"), args.get("sequence", "00"));
  const auto pairs = read_pairs_file(args.get("pairs"));
  if (args.has("resume") && !args.has("out")) throw UsageError("--resume goes with --out FILE");
  std::optional<BenchJournal> journal;
  if (args.has("out"))
    journal.emplace(args.get("out"), args.has("resume"),
                    fingerprint(args.get("sequence", "00") + "\n" + config_to_json(config, -1)));

  const Stage stages[] = {
      Stage::landmarks, Stage::correspondences,   Stage::graph,       Stage::clique,
      Stage::pose,      Stage::verification_prep, Stage::verification};
  std::vector<std::vector<double>> times(std::size(stages));
  std::vector<double> totals;
  int successes = 0, upper = 0, failed_to_load = 0, resumed = 0;
  Pipeline pipeline(config, args.get_int("threads", 1));

  const bool progress = isatty(STDERR_FILENO);
  std::printf("%-12s %6s %10s %11s %8s %8s %10s\n", "pair", "level", "t err [m]", "r err [deg]",
              "success", "bound", "time [ms]");
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [s, t] = pairs[k];
    // Progress only on a terminal: in a log it would run into the next line (an error, say).
    if (progress) std::fprintf(stderr, "[%zu/%zu] %d -> %d ...\r", k + 1, pairs.size(), s, t);
    std::fflush(stderr);
    if (const nlohmann::json* done = journal ? journal->find(s, t) : nullptr) {
      const ResumedPair r = resumed_pair(*done);
      successes += r.success;
      upper += r.upper_bound;
      totals.push_back(r.total_ms);
      ++resumed;
      continue;
    }
    LoadedCloud source, target;
    try {
      source = seq.load_frame(s);
      target = seq.load_frame(t);
    } catch (const InputError& e) {
      warn(std::string("pair ") + std::to_string(s) + " -> " + std::to_string(t) +
           " skipped: " + e.what());
      ++failed_to_load;
      continue;
    }
    pipeline.set_input(std::move(source.cloud), std::move(target.cloud));
    pipeline.set_ground_truth(seq.ground_truth(s, t));
    with_config_origin(args, [&] { pipeline.run(); });

    double total = 0;
    for (std::size_t i = 0; i < std::size(stages); ++i) {
      times[i].push_back(pipeline.time_ms(stages[i]));
      total += pipeline.time_ms(stages[i]);
    }
    totals.push_back(total);
    const auto err = pipeline.selected_error();
    const bool ok = err && err->success;
    successes += ok;
    upper += pipeline.upper_bound_success();
    const std::string name = std::to_string(s) + " -> " + std::to_string(t);
    if (err)
      std::printf("%-12s %6d %10.2f %11.2f %8s %8s %10.1f\n", name.c_str(),
                  pipeline.selected_level(), err->translation, err->rotation_deg, ok ? "yes" : "no",
                  pipeline.upper_bound_success() ? "yes" : "no", total);
    else
      std::printf("%-12s %6s %10s %11s %8s %8s %10.1f\n", name.c_str(), "-", "-", "-", "no",
                  pipeline.upper_bound_success() ? "yes" : "no", total);
    std::fflush(stdout);
    if (journal) {
      auto j = nlohmann::json::parse(
          registration_report_json(pipeline, seq.scan_path(s), seq.scan_path(t), -1));
      j.erase("config");
      journal->append(std::move(j), s, t);
    }
  }
  if (progress) std::fprintf(stderr, "%40s\r", "");

  const std::size_t n = totals.size();
  if (n == 0) throw InputError(args.get("pairs") + ": no pair could be loaded");
  std::printf("\npairs run: %zu%s\n", n,
              failed_to_load ? (" (" + std::to_string(failed_to_load) + " skipped)").c_str() : "");
  if (resumed)
    std::printf("of which %d taken from %s.partial (--resume); stage times cover the others\n",
                resumed, args.get("out").c_str());
  std::printf("success (selected pose, %.1f m / %.1f deg): %d/%zu = %.1f %%\n",
              config.evaluation.max_translation_error, config.evaluation.max_rotation_error,
              successes, n, 100.0 * successes / static_cast<double>(n));
  std::printf("upper bound (any level succeeds):       %d/%zu = %.1f %%\n", upper, n,
              100.0 * upper / static_cast<double>(n));
  std::printf("\n%-18s %10s %12s\n", "stage", "mean [ms]", "median [ms]");
  for (std::size_t i = 0; i < std::size(stages); ++i)
    std::printf("%-18s %10.2f %12.2f\n", stage_name(stages[i]), mean(times[i]), median(times[i]));
  std::printf("%-18s %10.2f %12.2f\n", "total", mean(totals), median(totals));
  if (journal) {
    journal->finish();
    std::printf("\nwrote %s\n", args.get("out").c_str());
  }
  return 0;
}

}  // namespace pagor::cli
