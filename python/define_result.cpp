// pagor.Result and pagor.Level: read-only views of a registration's report.

#include <cstdio>

#include "arrays.hpp"
#include "bindings.hpp"
#include "json_objects.hpp"

namespace pagor::python {
namespace {

using json = nlohmann::json;

// One level of a report (levels[i]).
struct Level {
  json level;
};

// A member as a Python object; None when it is absent or null.
py::object member(const json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() ? py::object(py::none()) : to_python(*it);
}

// A 4 x 4 row-major nested list as an array; None for null or absent.
py::object transform_member(const json& object, const char* key) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return py::none();
  Transform T;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      T(r, c) = (*it)[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].get<double>();
  return transform_to_array(T);
}

std::string result_repr(const json& report) {
  char buf[200];
  const auto T = report.find("T_target_source");
  if (T == report.end() || T->is_null()) return "<pagor.Result: no valid candidate>";
  const auto acceptance = report.find("acceptance");
  const char* verdict = acceptance == report.end()              ? ""
                        : (*acceptance)["accepted"].get<bool>() ? ", accepted"
                                                                : ", rejected";
  std::snprintf(buf, sizeof(buf), "<pagor.Result: level %d, t = (%.3f, %.3f, %.3f) m%s>",
                report["selected_level"].get<int>(), (*T)[0][3].get<double>(),
                (*T)[1][3].get<double>(), (*T)[2][3].get<double>(), verdict);
  return buf;
}

void define_level(py::module_& m) {
  py::class_<Level>(m, "Level",
                    "One level of the pyramid: its threshold, graph, clique and pose (a view of "
                    "the report's levels[i]; attributes absent from it are None).")
      .def_property_readonly("level", [](const Level& l) { return member(l.level, "level"); })
      .def_property_readonly(
          "epsilon", [](const Level& l) { return member(l.level, "epsilon"); },
          "The TRIM threshold [m for a difference TRIM; unitless for a ratio].")
      .def_property_readonly(
          "vertices", [](const Level& l) { return member(l.level, "vertices"); },
          "Correspondences with at least one edge at this level.")
      .def_property_readonly("edges", [](const Level& l) { return member(l.level, "edges"); })
      .def_property_readonly("clique_size",
                             [](const Level& l) { return member(l.level, "clique_size"); })
      .def_property_readonly(
          "clique", [](const Level& l) { return member(l.level, "clique"); },
          "The clique's correspondence indices.")
      .def_property_readonly(
          "inliers", [](const Level& l) { return member(l.level, "inliers"); },
          "GNC-TLS inliers of the level's pose (a count).")
      .def_property_readonly("pose_valid",
                             [](const Level& l) { return member(l.level, "pose_valid"); })
      .def_property_readonly(
          "T_target_source",
          [](const Level& l) { return transform_member(l.level, "T_target_source"); },
          "The level's pose (4 x 4 float64), None when invalid.")
      .def_property_readonly(
          "score_D", [](const Level& l) { return member(l.level, "score_D"); },
          "Verification score D [m]: lower is better; None when not scored.")
      .def_property_readonly("translation_error_m",
                             [](const Level& l) { return member(l.level, "translation_error_m"); })
      .def_property_readonly("rotation_error_deg",
                             [](const Level& l) { return member(l.level, "rotation_error_deg"); })
      .def_property_readonly(
          "success", [](const Level& l) { return member(l.level, "success"); },
          "Within the success criterion of the ground truth; None without one.")
      .def("to_dict", [](const Level& l) { return to_python(l.level); })
      .def("__repr__", [](const Level& l) {
        char buf[160];
        std::snprintf(buf, sizeof(buf), "<pagor.Level %d: epsilon %g, clique %d, inliers %d>",
                      l.level.value("level", -1), l.level.value("epsilon", 0.0),
                      l.level.value("clique_size", 0), l.level.value("inliers", 0));
        return std::string(buf);
      });
}

}  // namespace

void define_result(py::module_& m) {
  define_level(m);
  py::class_<Result>(m, "Result",
                     "A registration's outcome. Every attribute is read from the report that "
                     "to_json() returns (the pagor tool's --json schema).")
      .def_property_readonly(
          "T_target_source",
          [](const Result& r) { return transform_member(r.report, "T_target_source"); },
          "The selected transform (4 x 4 float64 array) that maps source points into the target "
          "frame; None when no level has a valid pose.")
      .def_property_readonly("selected_level",
                             [](const Result& r) { return member(r.report, "selected_level"); })
      .def_property_readonly(
          "accepted",
          [](const Result& r) -> py::object {
            const auto a = r.report.find("acceptance");
            return a == r.report.end() ? py::object(py::none()) : to_python((*a)["accepted"]);
          },
          "The verdict: whether the selected pose is trusted (None without clouds to judge on).")
      .def_property_readonly(
          "acceptance", [](const Result& r) { return member(r.report, "acceptance"); },
          "The verdict's numbers: accepted, overlap, inliers, margin, reason.")
      .def_property_readonly(
          "levels",
          [](const Result& r) {
            py::list out;
            for (const json& l : r.report["levels"]) out.append(py::cast(Level{l}));
            return out;
          },
          "Per pyramid level: epsilon, clique size, inliers, pose, score D (pagor.Level).")
      .def_property_readonly(
          "diagnosis", [](const Result& r) { return member(r.report, "diagnosis"); },
          "The stage at fault against the ground truth (a dict with 'verdict'); "
          "None without ground truth.")
      .def_property_readonly(
          "timings_ms", [](const Result& r) { return member(r.report, "timings_ms"); },
          "Wall time per stage and in total [ms].")
      .def_property_readonly("warnings",
                             [](const Result& r) { return member(r.report, "warnings"); })
      .def_property_readonly(
          "config", [](const Result& r) { return member(r.report, "config"); },
          "The full configuration used.")
      .def(
          "to_json",
          [](const Result& r, int indent) {
            return r.report.dump(indent, ' ', false, json::error_handler_t::replace);
          },
          py::arg("indent") = 2,
          "The report as JSON text: schema pagor.register/1 (what `pagor register --json` "
          "writes), or pagor.register-correspondences/1 for register_correspondences(). "
          "indent -1: one line.")
      .def(
          "to_dict", [](const Result& r) { return to_python(r.report); },
          "The report as a dict (json.loads(to_json())).")
      .def("__repr__", [](const Result& r) { return result_repr(r.report); });
}

}  // namespace pagor::python
