#include "scene/cloud_colors.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "render/resources.hpp"
#include "widgets/plot_map.hpp"

namespace pagor::studio {
namespace {

constexpr Rgba kGrey{120, 120, 120, 255};
constexpr std::size_t kSample = 20000;  // points a quantile looks at

// The q-quantile of `v` (reordered); 0 for an empty vector.
float quantile(std::vector<float>& v, double q) {
  if (v.empty()) return 0.0f;
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<std::size_t>(k)];
}

template <class F>
std::vector<float> sample(std::size_t n, const F& value) {
  std::vector<float> out;
  const std::size_t stride = std::max<std::size_t>(1, n / kSample);
  for (std::size_t i = 0; i < n; i += stride) out.push_back(value(i));
  return out;
}

}  // namespace

ClassColors::ClassColors() {
  const auto j = nlohmann::json::parse(resource("class_colors.json").text());
  for (const auto& item : j.items()) {
    if (!item.value().is_array() || item.value().size() != 3) continue;
    colors_[item.key()] = {item.value()[0].get<unsigned char>(),
                           item.value()[1].get<unsigned char>(),
                           item.value()[2].get<unsigned char>(), 255};
  }
}

Rgba ClassColors::of(const std::string& name) const {
  const auto it = colors_.find(name);
  return it == colors_.end() ? kGrey : it->second;
}

std::vector<Rgba> ClassColors::per_point(const PointCloud& cloud, const LabelScheme& scheme) const {
  std::unordered_map<std::uint32_t, Rgba> by_id;
  for (const auto& c : scheme.classes)
    for (std::uint32_t id : c.ids) by_id[id] = of(c.name);
  std::vector<Rgba> out(cloud.size(), kGrey);
  for (std::size_t i = 0; i < cloud.size() && i < cloud.labels.size(); ++i) {
    const auto it = by_id.find(semantic_id(cloud.labels[i]));
    if (it != by_id.end()) out[i] = it->second;
  }
  return out;
}

ColorScale height_scale(const Snapshot& s) {
  ColorScale c{"height z [m]", 0, 1, false, "m"};
  if (!s.target || s.target->points.empty()) return c;
  std::vector<float> z =
      sample(s.target->points.size(), [&](std::size_t i) { return s.target->points[i].z(); });
  c.lo = quantile(z, 0.02);
  c.hi = quantile(z, 0.98);
  if (c.hi <= c.lo) c.hi = c.lo + 1.0;
  c.valid = true;
  return c;
}

ColorScale intensity_scale(const Snapshot& s) {
  ColorScale c{"intensity (unitless)", 0, 1, false, ""};
  std::vector<float> v;
  for (const auto* cloud : {s.source.get(), s.target.get()})
    if (cloud && cloud->has_intensities()) {
      const auto part =
          sample(cloud->intensities.size(), [&](std::size_t i) { return cloud->intensities[i]; });
      v.insert(v.end(), part.begin(), part.end());
    }
  if (v.empty()) return c;
  c.hi = quantile(v, 0.98);
  if (c.hi <= c.lo) c.hi = c.lo + 1.0;
  c.valid = true;
  return c;
}

Rgba scale_color(double t) {
  const ImU32 c = plot_detail::viridis(t);
  return {static_cast<unsigned char>(c & 0xFF), static_cast<unsigned char>((c >> 8) & 0xFF),
          static_cast<unsigned char>((c >> 16) & 0xFF), 255};
}

std::string class_of_label(const LabelScheme& scheme, std::uint32_t raw_label) {
  const std::uint32_t id = semantic_id(raw_label);
  for (const auto& c : scheme.classes)
    if (std::find(c.ids.begin(), c.ids.end(), id) != c.ids.end()) return c.name;
  return {};
}

std::vector<Rgba> cloud_colors(const PointCloud& cloud, ColorMode mode, const ClassColors& colors,
                               const LabelScheme& scheme, const Transform& pose,
                               const ColorScale& scale) {
  const auto at = [&](double v) { return scale_color((v - scale.lo) / (scale.hi - scale.lo)); };
  if (mode == ColorMode::height) {
    std::vector<Rgba> out(cloud.size());
    const Eigen::Vector3d row = pose.block<1, 3>(2, 0).transpose();
    for (std::size_t i = 0; i < cloud.size(); ++i)
      out[i] = at(row.dot(cloud.points[i].cast<double>()) + pose(2, 3));
    return out;
  }
  if (mode == ColorMode::intensity) {
    std::vector<Rgba> out(cloud.size(), kGrey);
    if (cloud.has_intensities() && scale.valid)
      for (std::size_t i = 0; i < cloud.size(); ++i) out[i] = at(cloud.intensities[i]);
    return out;
  }
  return colors.per_point(cloud, scheme);
}

std::vector<DrawnClass> drawn_classes(const Snapshot& s, const ClassColors& colors) {
  std::unordered_map<std::string, std::size_t> count;
  bool labelled = false;
  for (const auto& [cloud, scheme] : {std::pair{s.source.get(), &cloud_scheme(s, true)},
                                      std::pair{s.target.get(), &cloud_scheme(s, false)}}) {
    if (!cloud || !cloud->has_labels()) continue;
    labelled = true;
    std::unordered_map<std::uint32_t, std::string> name_of;
    for (const auto& c : scheme->classes)
      for (std::uint32_t id : c.ids) name_of[id] = c.name;
    for (std::uint32_t l : cloud->labels) {
      const auto it = name_of.find(semantic_id(l));
      ++count[it == name_of.end() ? std::string() : it->second];
    }
  }
  std::vector<DrawnClass> out;
  if (!labelled) return out;
  for (const auto& [name, n] : count)
    out.push_back({name, name.empty() ? kGrey : colors.of(name), n});
  std::sort(out.begin(), out.end(), [](const DrawnClass& a, const DrawnClass& b) {
    return a.points != b.points ? a.points > b.points : a.name < b.name;
  });
  return out;
}

}  // namespace pagor::studio
