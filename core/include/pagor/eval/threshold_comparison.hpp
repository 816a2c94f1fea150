#pragma once
/// \file threshold_comparison.hpp
/// The pyramid against its own levels, on a set of pairs: the configured k-threshold pyramid
/// (cascaded CLIPPER, verification picks the lowest D), each threshold alone (one level, so
/// verification has nothing to choose), and each threshold alone with the exact maximum clique,
/// the TEASER++-like baseline on the same semantic correspondences (max clique, no
/// verification). Each pair is loaded and its landmarks and correspondences computed once; the
/// variants differ from the graph on.

#include <functional>
#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/pair_set.hpp"

namespace pagor {

/// A configuration to compare.
struct Variant {
  std::string name;  ///< e.g. "pyramid (5 levels)", "single 0.10", "max clique 0.10"
  Config config;     ///< differs from the base in graph and clique only
};

/// The pyramid of `base`, then each of its thresholds alone with `base`'s solver, then each alone
/// with the exact maximum clique.
std::vector<Variant> threshold_variants(const Config& base);

/// What a variant achieved.
struct VariantResult {
  std::string name;
  int with_truth = 0;    ///< pairs with ground truth that loaded
  int successes = 0;     ///< selected pose within the criterion
  double mean_ms = 0.0;  ///< mean time of the stages from the graph on [ms]
  std::optional<double> success_rate() const { return ratio(successes, with_truth); }
};

/// Runs every variant on every positive pair with ground truth (others are skipped).
/// `progress(done, total)` is called after each pair. Throws ConfigError for an invalid variant.
std::vector<VariantResult> compare_variants(
    const PairSet& set, const std::vector<Variant>& variants, int threads = 1,
    const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace pagor
