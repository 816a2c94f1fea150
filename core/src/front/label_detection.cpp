#include "pagor/front/label_detection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pagor {
namespace {

// Share of a class among the points of a typical scan: SemanticKITTI's label frequencies for the
// driving classes (its `content` table, unlabeled and outliers together), a car park's for the
// indoor ones. Only the ratios matter: a numbering is judged by how likely the cloud's labels are
// when its ids are read as these classes.
const std::unordered_map<std::string, double>& class_frequencies() {
  static const std::unordered_map<std::string, double> table = {{"car", 0.041},
                                                                {"bicycle", 1.7e-4},
                                                                {"motorcycle", 4.0e-4},
                                                                {"truck", 2.1e-3},
                                                                {"other-vehicle", 1.7e-3},
                                                                {"person", 1.8e-4},
                                                                {"bicyclist", 2e-5},
                                                                {"motorcyclist", 1e-5},
                                                                {"road", 0.199},
                                                                {"parking", 0.0147},
                                                                {"sidewalk", 0.144},
                                                                {"other-ground", 3.9e-3},
                                                                {"building", 0.133},
                                                                {"fence", 0.072},
                                                                {"vegetation", 0.267},
                                                                {"trunk", 6.0e-3},
                                                                {"terrain", 0.078},
                                                                {"pole", 2.9e-3},
                                                                {"traffic-sign", 6e-4},
                                                                {"wall", 0.5},
                                                                {"column", 0.1},
                                                                {"door", 0.05},
                                                                {"furniture", 0.3}};
  return table;
}
constexpr double kUnlabeledShare = 0.032;  // unlabeled and outlier points of a scan
constexpr double kMovingShare = 2e-3;      // SemanticKITTI's moving objects together
constexpr double kRareShare = 1e-5;        // floor: the rarest classes, and unknown class names
constexpr double kUnknownIdShare = 1e-6;   // an id the numbering does not have

// Ids a numbering uses for points of no class: unlabeled, outliers, moving objects.
std::vector<std::pair<std::uint32_t, double>> classless_ids(const std::string& scheme) {
  if (scheme == "semantickitti") {
    std::vector<std::pair<std::uint32_t, double>> ids = {
        {0, kUnlabeledShare}, {1, kUnlabeledShare}, {52, kUnlabeledShare}, {99, kUnlabeledShare}};
    for (std::uint32_t id = 252; id <= 259; ++id) ids.push_back({id, kMovingShare});
    return ids;
  }
  if (scheme == "semantickitti-learning" || scheme == "indoor") return {{0, kUnlabeledShare}};
  if (scheme == "semantickitti-train") return {{255, kUnlabeledShare}, {0xFFFF, kUnlabeledShare}};
  return {};
}

using Histogram = std::vector<std::pair<std::uint32_t, std::size_t>>;  // (semantic id, points)

Histogram histogram_of(const PointCloud& cloud, std::size_t& instances) {
  std::vector<std::size_t> small(1024, 0);
  std::map<std::uint32_t, std::size_t> large;
  instances = 0;
  for (std::uint32_t l : cloud.labels) {
    const std::uint32_t id = semantic_id(l);
    instances += (l >> 16) != 0;
    if (id < small.size())
      ++small[id];
    else
      ++large[id];
  }
  Histogram h;
  for (std::uint32_t id = 0; id < small.size(); ++id)
    if (small[id]) h.push_back({id, small[id]});
  h.insert(h.end(), large.begin(), large.end());
  return h;
}

std::pair<double, double> fit_of(const Histogram& h, std::size_t total, const LabelScheme& s) {
  if (total == 0) return {0.0, 0.0};
  std::unordered_map<std::uint32_t, double> share;
  for (const auto& [id, p] : classless_ids(s.name)) share[id] = p;
  const auto& freq = class_frequencies();
  for (const auto& c : s.classes) {
    const auto f = freq.find(c.name);
    const double p = f == freq.end() ? kRareShare : std::max(f->second, kRareShare);
    for (std::uint32_t id : c.ids) share[id] = p;
  }
  double log_likelihood = 0.0, known = 0.0;
  for (const auto& [id, n] : h) {
    const auto it = share.find(id);
    log_likelihood +=
        static_cast<double>(n) * std::log(it == share.end() ? kUnknownIdShare : it->second);
    known += it == share.end() ? 0.0 : static_cast<double>(n);
  }
  return {log_likelihood / static_cast<double>(total), known / static_cast<double>(total)};
}

// A built-in numbering explaining the labels better than the configured scheme by more than this
// [nats per point] makes them not fit it. Shifted numberings differ by 1.9-4.5 nats a point on the
// shared KITTI and semreg-dev clouds, raw ids read as a 0-based numbering by 7 and more.
constexpr double kMismatchMargin = 1.0;
// A numbering that knows fewer of the points than this does not fit them.
constexpr double kLeastKnown = 0.5;

std::string percent(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.0f %%", 100.0 * x);
  return buf;
}

}  // namespace

std::pair<double, double> label_fit(const PointCloud& cloud, const LabelScheme& scheme) {
  std::size_t instances = 0;
  return fit_of(histogram_of(cloud, instances), cloud.labels.size(), scheme);
}

LabelDetection detect_label_scheme(const PointCloud& cloud) {
  LabelDetection d;
  if (!cloud.has_labels()) {
    d.reason = "no labels";
    return d;
  }
  const Histogram h = histogram_of(cloud, d.instances);
  if (h.size() == 1) {
    d.reason = "every point carries label " + std::to_string(h.front().first);
    return d;
  }
  std::vector<std::pair<std::pair<double, double>, std::string>> fits;
  for (const auto& name : label_numbering_names())
    fits.push_back({fit_of(h, cloud.labels.size(), builtin_label_scheme(name)), name});
  std::stable_sort(fits.begin(), fits.end(),
                   [](const auto& a, const auto& b) { return a.first.first > b.first.first; });
  const auto& best = fits.front();
  d.fit = best.first.first;
  d.known = best.first.second;
  d.runner_up = fits.size() > 1 ? fits[1].second : std::string();
  d.margin = fits.size() > 1 ? best.first.first - fits[1].first.first : 0.0;
  if (d.known < kLeastKnown) {
    d.reason = "ids of no known numbering (the closest, " + best.second + ", knows " +
               percent(d.known) + " of the points)";
    return d;
  }
  d.scheme = best.second;
  return d;
}

LabelReading read_labels(const PointCloud& cloud, const LabelScheme& configured) {
  LabelReading r;
  r.detection = detect_label_scheme(cloud);
  r.automatic = configured.automatic();
  if (!cloud.has_labels() || configured.ignores_labels()) {
    r.scheme = builtin_label_scheme("none");
    return r;
  }
  if (configured.automatic()) {
    r.scheme = builtin_label_scheme(r.detection.scheme);
    return r;
  }
  r.scheme = configured;
  const auto [fit, known] = label_fit(cloud, configured);
  const bool better = r.detection.scheme != "none" && r.detection.scheme != configured.name &&
                      r.detection.fit - fit > kMismatchMargin;
  if (known >= kLeastKnown && !better) return r;
  r.mismatch = "labels do not fit scheme '" + configured.name + "': " + percent(known) +
               " of points carry its ids";
  if (r.detection.scheme != "none" && r.detection.scheme != configured.name)
    r.mismatch += "; they look like '" + r.detection.scheme + "' (set label_scheme, or auto)";
  return r;
}

std::string numbering_doubt(const LabelReading& r) {
  const LabelDetection& d = r.detection;
  if (!r.automatic || r.scheme.ignores_labels() || d.runner_up.empty() ||
      d.margin >= kMismatchMargin)
    return {};
  char margin[32];
  std::snprintf(margin, sizeof(margin), "%.2f", d.margin);
  return "labels read in numbering '" + d.scheme + "', but '" + d.runner_up +
         "' fits them almost as well (" + margin +
         " nats a point apart): set label_scheme if they are in that one";
}

}  // namespace pagor
