// pagor bench --compare-thresholds: the pyramid against each of its thresholds alone and against
// the TEASER++-like baseline (one threshold, exact maximum clique, no verification).

#include <unistd.h>

#include <cstdio>

#include "command.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/threshold_comparison.hpp"

namespace pagor::cli {

int run_threshold_comparison(const Args& args, const Config& config, const PairSet& set) {
  const std::vector<Variant> variants = threshold_variants(config);
  const bool tty = isatty(STDERR_FILENO);
  std::vector<VariantResult> results;
  with_config_origin(args, [&] {
    results = compare_variants(set, variants, args.get_int("threads", 1),
                               [tty](std::size_t done, std::size_t total) {
                                 if (!tty) return;
                                 std::fprintf(stderr, "[%zu/%zu] pairs ...\r", done, total);
                                 std::fflush(stderr);
                               });
  });
  if (tty) std::fprintf(stderr, "%40s\r", "");
  if (results.empty() || results.front().with_truth == 0)
    throw InputError(set.origin + ": no pair with ground truth could be loaded");
  std::printf("%-22s %-10s %-13s %9s %10s %14s\n", "variant", "solver", "verification", "success",
              "rate", "mean [ms]");
  for (std::size_t i = 0; i < results.size(); ++i) {
    const VariantResult& r = results[i];
    const Config& c = variants[i].config;
    std::printf("%-22s %-10s %-13s %4d/%-4d %10s %14.2f\n", r.name.c_str(),
                to_string(c.clique.solver),
                c.graph.thresholds.size() > 1 ? "lowest D" : "none (1 lvl)", r.successes,
                r.with_truth, rate_text(r.success_rate()).c_str(), r.mean_ms);
  }
  std::printf(
      "\nsuccess: %.1f m / %.1f deg; thresholds in %s TRIM units; time: graph, clique, "
      "pose and verification per pair\n",
      config.evaluation.max_translation_error, config.evaluation.max_rotation_error,
      to_string(config.graph.trim));
  return 0;
}

}  // namespace pagor::cli
