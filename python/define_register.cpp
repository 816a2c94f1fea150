// pagor.register and pagor.register_correspondences: the core's run with the GIL released.

#include <atomic>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "json_objects.hpp"
#include "pagor/errors.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/registration.hpp"
#include "pagor/report.hpp"

namespace pagor::python {
namespace {

int thread_count(int threads) {
  if (threads < 1)
    throw py::value_error("threads: expected 1 or more, got " + std::to_string(threads));
  return threads;
}

PointCloud cloud_from(const py::handle& points, const py::handle& labels, const std::string& what) {
  PointCloud cloud;
  cloud.points = points_from_array(points, what);
  if (!labels.is_none()) cloud.labels = labels_from_array(labels, cloud.size(), what + "_labels");
  return cloud;
}

std::string array_name(const char* side, std::size_t points) {
  return std::string(side) + " array (" + std::to_string(points) + " points)";
}

// Runs the pipeline without the GIL. Between stages the GIL is taken back briefly to let Python
// handle signals: Ctrl+C cancels the run and raises KeyboardInterrupt.
nlohmann::json run_pipeline(Pipeline& pipeline, const std::string& source_name,
                            const std::string& target_name) {
  std::atomic<bool> cancel{false};
  std::optional<py::error_already_set> interrupted;
  const ProgressFn check_signals = [&](Stage, double) {
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
      interrupted.emplace();
      cancel = true;
    }
  };
  nlohmann::json report;
  try {
    const py::gil_scoped_release release;
    pipeline.run(check_signals, &cancel);
    RegistrationContext context;
    context.source_name = source_name;
    context.target_name = target_name;
    report = report_object(make_registration(pipeline, context));
  } catch (const Cancelled&) {
    if (!interrupted) throw;
  }
  if (interrupted) throw std::move(*interrupted);  // also when it came after the last stage
  return report;
}

Result register_clouds(const py::handle& source, const py::handle& target,
                       const py::handle& source_labels, const py::handle& target_labels,
                       const py::handle& config, const py::handle& ground_truth, int threads) {
  // Everything is checked, and the arrays copied into the core's clouds, with the GIL held.
  PointCloud s = cloud_from(source, source_labels, "source");
  PointCloud t = cloud_from(target, target_labels, "target");
  const Config c = config_from_python(config);
  std::optional<Transform> truth;
  if (!ground_truth.is_none()) truth = transform_from_array(ground_truth, "ground_truth");
  const std::string source_name = array_name("source", s.size());
  const std::string target_name = array_name("target", t.size());
  Pipeline pipeline(c, thread_count(threads));
  pipeline.set_input(std::move(s), std::move(t));
  pipeline.set_ground_truth(truth);
  return Result{run_pipeline(pipeline, source_name, target_name)};
}

Result register_correspondences(const py::handle& p, const py::handle& q, const py::handle& weights,
                                const py::handle& config, const py::handle& source,
                                const py::handle& target, const py::handle& ground_truth,
                                int threads) {
  const std::vector<Eigen::Vector3d> ps = vectors_from_array(p, "p");
  const std::vector<Eigen::Vector3d> qs = vectors_from_array(q, "q");
  if (ps.size() != qs.size())
    throw py::value_error("p and q: " + std::to_string(ps.size()) + " source points and " +
                          std::to_string(qs.size()) +
                          " target points; expected one of each "
                          "per correspondence");
  std::vector<double> w;
  if (!weights.is_none()) w = weights_from_array(weights, ps.size(), "weights");
  if (source.is_none() != target.is_none())
    throw py::value_error("source and target: give both clouds to verify on, or neither");
  const Config c = config_from_python(config);
  std::optional<Transform> truth;
  if (!ground_truth.is_none()) truth = transform_from_array(ground_truth, "ground_truth");
  // As a correspondences file gives them: a matcher's, each its own ids, score = weight.
  std::vector<Correspondence> items(ps.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    items[i].class_index = -1;
    items[i].origin = CorrespondenceOrigin::matcher;
    items[i].source = items[i].target = static_cast<int>(i);
    items[i].p = ps[i];
    items[i].q = qs[i];
    items[i].score = w.empty() ? 1.0 : w[i];
  }
  Pipeline pipeline(c, thread_count(threads));
  pipeline.set_matches(std::move(items));
  std::string source_name = "correspondences (" + std::to_string(ps.size()) + ")";
  std::string target_name = source_name;
  if (!source.is_none()) {
    PointCloud s = cloud_from(source, py::none(), "source");
    PointCloud t = cloud_from(target, py::none(), "target");
    source_name = array_name("source", s.size());
    target_name = array_name("target", t.size());
    pipeline.set_input(std::move(s), std::move(t));
  }
  pipeline.set_ground_truth(truth);
  return Result{run_pipeline(pipeline, source_name, target_name)};
}

}  // namespace

void define_register(py::module_& m) {
  m.def("register", &register_clouds, py::arg("source"), py::arg("target"),
        py::arg("source_labels") = py::none(), py::arg("target_labels") = py::none(),
        py::arg("config") = py::none(), py::kw_only(), py::arg("ground_truth") = py::none(),
        py::arg("threads") = 1,
        "Registers `source` to `target`: finds T_target_source, the transform that maps source "
        "points into the target frame, with no initial guess.\n\n"
        "source, target: N x 3 float32 or float64 arrays [m] (numpy arrays, or anything "
        "numpy.asarray takes, e.g. Open3D's pcd.points). Any strides are read in place; the one "
        "copy made is into the core's cloud (float32). source_labels, target_labels: one uint32 "
        "label per point in the configured label scheme (default semantickitti-train), or None "
        "(class-agnostic keypoints then). config: a dict with the JSON configuration's keys "
        "(absent keys: its 'preset', else the default), or None for default_config(). "
        "ground_truth: a 4 x 4 T_target_source to judge the result against (errors per level, "
        "the diagnosis). threads: for graph construction and verification (as `pagor register "
        "--threads`).\n\n"
        "The core runs with the GIL released (other Python threads keep running); Ctrl+C cancels "
        "between stages. Returns a pagor.Result. Wrong shapes or dtypes, non-finite "
        "coordinates, a label count other than the point count, an unknown config key or a value "
        "out of range raise ValueError (pagor.Error for the core's checks) naming what was "
        "wrong.");
  m.def("register_correspondences", &register_correspondences, py::arg("p"), py::arg("q"),
        py::arg("weights") = py::none(), py::arg("config") = py::none(), py::kw_only(),
        py::arg("source") = py::none(), py::arg("target") = py::none(),
        py::arg("ground_truth") = py::none(), py::arg("threads") = 1,
        "Registers a matcher's correspondences (FPFH, FCGF, GeDi, ...): p[i] in the source "
        "matches q[i] in the target. p, q: N x 3 float arrays [m] (copied once, as float64); "
        "weights: N non-negative numbers or None (kept as each correspondence's score). Runs "
        "the pyramid of consistency graphs, the densest clique and the pose per level through "
        "the same pipeline as `pagor register --correspondences`. source, target: N x 3 clouds "
        "to verify the candidates on (as register's), or None: then the level is selected "
        "without clouds and `accepted` is False with the reason (nothing to verify on). "
        "ground_truth: a 4 x 4 T_target_source to judge the result against. Returns a "
        "pagor.Result (to_json(): schema pagor.register/1). At most 20000 correspondences. The "
        "GIL is released while the core runs.");
}

}  // namespace pagor::python
