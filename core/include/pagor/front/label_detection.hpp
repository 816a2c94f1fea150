#pragma once
/// \file label_detection.hpp
/// Which numbering a cloud's labels are in, read from the label values themselves: raw
/// SemanticKITTI ids (instance ids in the upper 16 bits), the 0-based training numbering, the
/// learning map, the indoor scheme, or none that fits. Each scheme is scored by how likely the
/// cloud's label histogram is when its ids are read as that scheme's classes, with class
/// frequencies typical of the data (SemanticKITTI's for driving scenes): a numbering shifted by
/// one reads the bulk of a scan (road, vegetation) as rare classes (parking, trunk) and scores
/// several nats per point lower.

#include <string>

#include "pagor/front/label_scheme.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// What a cloud's label values say about their numbering.
struct LabelDetection {
  /// The built-in scheme that explains the labels best, or `none`: no labels, a single label
  /// value for every point, or ids that no built-in scheme knows for most points.
  std::string scheme = "none";
  std::string runner_up;      ///< the next best built-in scheme (empty when none)
  double fit = 0.0;           ///< mean log-likelihood of a point's label under `scheme` [nats]
  double margin = 0.0;        ///< how much better than `runner_up` [nats per point]
  double known = 0.0;         ///< fraction of points whose ids `scheme` knows, in [0, 1]
  std::size_t instances = 0;  ///< points with an instance id (upper 16 bits) set
  std::string reason;         ///< for `none`: why, in words
};

/// Detects the numbering of `cloud`'s labels among the built-in schemes (indoor included).
LabelDetection detect_label_scheme(const PointCloud& cloud);

/// How well `scheme` explains the labels: {mean log-likelihood per point [nats], fraction of
/// points whose ids it knows}. Custom schemes are scored by their class names (a class name the
/// frequency table does not know counts as a rare class). {0, 0} for a cloud without labels.
std::pair<double, double> label_fit(const PointCloud& cloud, const LabelScheme& scheme);

/// How a cloud's labels are read.
struct LabelReading {
  LabelScheme scheme;        ///< the scheme in use: `none` when the labels are not used
  bool automatic = false;    ///< chosen by detection (configured `auto`)
  LabelDetection detection;  ///< what the labels look like (also for a configured scheme)
  /// Labels that do not fit a configured scheme: the message, naming the scheme they look like;
  /// empty when they fit (always empty for `auto` and `none`).
  std::string mismatch;
};

/// The scheme `cloud`'s labels are read with under the configured one: `auto` takes the detected
/// scheme (`none` when nothing fits), `none` ignores the labels, a cloud without labels reads as
/// `none`; any other scheme is used as configured, and `mismatch` says when the labels do not fit
/// it (most points carry ids it does not know, or a built-in scheme explains them better by more
/// than a nat per point).
LabelReading read_labels(const PointCloud& cloud, const LabelScheme& configured);

/// For labels whose numbering was detected (`auto`) when another built-in one explains them
/// almost as well (within a nat per point, where a numbering shifted by one usually loses several
/// on real scans): a warning naming both and how to settle it; empty otherwise. Class shares far
/// from a driving scan's (a corridor of pillars labelled trunk) can make the wrong one win.
std::string numbering_doubt(const LabelReading& reading);

}  // namespace pagor
