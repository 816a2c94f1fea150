#include "pagor/front/label_scheme.hpp"

#include "pagor/errors.hpp"

namespace pagor {

int LabelScheme::find(const std::string& class_name) const {
  for (std::size_t i = 0; i < classes.size(); ++i)
    if (classes[i].name == class_name) return static_cast<int>(i);
  return -1;
}

std::string LabelScheme::class_list() const {
  std::string s;
  for (const auto& c : classes) s += (s.empty() ? "" : ", ") + c.name;
  return s;
}

const std::vector<std::uint32_t>& LabelScheme::ids_of(const std::string& class_name) const {
  const int i = find(class_name);
  if (i < 0)
    throw ConfigError("label scheme '" + name + "' has no class '" + class_name +
                      "' (it has: " + class_list() + ")");
  return classes[static_cast<std::size_t>(i)].ids;
}

std::vector<std::string> label_numbering_names() {
  return {"semantickitti", "semantickitti-train", "semantickitti-learning", "indoor"};
}

std::vector<std::string> builtin_label_scheme_names() {
  std::vector<std::string> names{"auto", "none"};
  for (const auto& n : label_numbering_names()) names.push_back(n);
  return names;
}

LabelScheme builtin_label_scheme(const std::string& name) {
  if (name == "auto" || name == "none") {
    // Every class name of the numberings, so that any landmark class of theirs is valid.
    LabelScheme s{name, {}};
    for (const auto& numbering : label_numbering_names())
      for (const auto& c : builtin_label_scheme(numbering).classes)
        if (s.find(c.name) < 0) s.classes.push_back({c.name, {}});
    return s;
  }
  if (name == "semantickitti") {
    return {name,
            {{"car", {10}},
             {"bicycle", {11}},
             {"motorcycle", {15}},
             {"truck", {18}},
             {"other-vehicle", {13, 16, 20}},
             {"person", {30}},
             {"bicyclist", {31}},
             {"motorcyclist", {32}},
             {"road", {40, 60}},
             {"parking", {44}},
             {"sidewalk", {48}},
             {"other-ground", {49}},
             {"building", {50}},
             {"fence", {51}},
             {"vegetation", {70}},
             {"trunk", {71}},
             {"terrain", {72}},
             {"pole", {80}},
             {"traffic-sign", {81}}}};
  }
  if (name == "semantickitti-train" || name == "semantickitti-learning") {
    static const char* const kNames[] = {"car",           "bicycle", "motorcycle",  "truck",
                                         "other-vehicle", "person",  "bicyclist",   "motorcyclist",
                                         "road",          "parking", "sidewalk",    "other-ground",
                                         "building",      "fence",   "vegetation",  "trunk",
                                         "terrain",       "pole",    "traffic-sign"};
    // The learning map is the training numbering shifted by one, with 0 for unlabeled.
    const std::uint32_t first = name == "semantickitti-learning" ? 1 : 0;
    LabelScheme s{name, {}};
    for (std::uint32_t i = 0; i < 19; ++i) s.classes.push_back({kNames[i], {i + first}});
    return s;
  }
  if (name == "indoor") {
    return {name, {{"wall", {1}}, {"column", {2}}, {"door", {3}}, {"furniture", {4}}}};
  }
  std::string known;
  for (const auto& n : builtin_label_scheme_names()) known += (known.empty() ? "" : ", ") + n;
  throw ConfigError("unknown label scheme '" + name + "' (built-in: " + known + ")");
}

}  // namespace pagor
