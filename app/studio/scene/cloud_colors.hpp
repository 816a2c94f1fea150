#pragma once
/// \file cloud_colors.hpp
/// The dense clouds' colours per ColorMode, and what the legend says of them: the classes drawn
/// (each with its colour and how many points carry it), or the range of a continuous scale
/// (height, intensity) with its unit. The legend is built from the same numbers the colours are,
/// so that it cannot say grey where the points are green.

#include <array>
#include <map>
#include <string>
#include <vector>

#include "runners/worker.hpp"
#include "state/app_state.hpp"

namespace pagor::studio {

using Rgba = std::array<unsigned char, 4>;

/// Class colours from the embedded assets/class_colors.json.
class ClassColors {
 public:
  ClassColors();
  /// Colour of a class name (grey when unlisted).
  Rgba of(const std::string& class_name) const;
  /// Colour of each raw label under a scheme (grey for labels of no class).
  std::vector<Rgba> per_point(const PointCloud& cloud, const LabelScheme& scheme) const;

 private:
  std::map<std::string, Rgba> colors_;
};

/// A continuous colour scale: viridis from `lo` (dark) to `hi` (yellow).
struct ColorScale {
  std::string title;  ///< with its unit, e.g. "height z [m]"
  double lo = 0, hi = 1;
  bool valid = false;  ///< false: nothing to scale (no intensities)
  std::string unit;    ///< of lo and hi, printed after them ("m"; empty: unitless)
};

/// One class as drawn: its colour and its points in both clouds.
struct DrawnClass {
  std::string name;  ///< "" for points of no class (grey)
  Rgba color{};
  std::size_t points = 0;
};

/// The scale of height colouring: z in the target frame from the target's 2 % to 98 % quantile.
ColorScale height_scale(const Snapshot& s);
/// The scale of intensity colouring: from 0 to the 98 % quantile of both clouds' intensities.
ColorScale intensity_scale(const Snapshot& s);

/// Viridis as the clouds use it, at t in [0, 1] (clamped).
Rgba scale_color(double t);

/// The colour of each point of `cloud` under `mode` (by_class, height, intensity; by_cloud and
/// residual are drawn otherwise): `pose` places the cloud in the target frame (height).
std::vector<Rgba> cloud_colors(const PointCloud& cloud, ColorMode mode, const ClassColors& colors,
                               const LabelScheme& scheme, const Transform& pose,
                               const ColorScale& scale);

/// The classes the class colouring draws over both clouds, most points first; points of no class
/// of the scheme (grey) as one entry named "". Empty when neither cloud has labels.
std::vector<DrawnClass> drawn_classes(const Snapshot& s, const ClassColors& colors);

/// The scheme the source's (or the target's) labels were read with: the configured one, or for
/// `auto` the one detected for that cloud. Every colouring, legend and pick reads labels with it.
inline const LabelScheme& cloud_scheme(const Snapshot& s, bool source) {
  return source ? s.source_landmarks.labels.scheme : s.target_landmarks.labels.scheme;
}

/// The class a raw label belongs to under `scheme` ("" for none).
std::string class_of_label(const LabelScheme& scheme, std::uint32_t raw_label);

}  // namespace pagor::studio
