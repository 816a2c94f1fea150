// _pagor.register_clouds and _pagor.register_correspondences: the core's run with the GIL
// released; the result as a dict of the report and numpy arrays (results.py wraps it).

#include <atomic>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "json_objects.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/clouds.hpp"
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

// "source array (N points)": what an array is called in the report.
std::string array_name(const char* side, const Pipeline& pipeline) {
  const PointCloud& cloud = std::string(side) == "source" ? pipeline.source() : pipeline.target();
  return std::string(side) + " array (" + std::to_string(cloud.size()) + " points)";
}

std::optional<Transform> truth_from(const py::handle& ground_truth) {
  if (ground_truth.is_none()) return std::nullopt;
  return transform_from_array(ground_truth, "ground_truth");
}

// Runs the pipeline without the GIL. Between stages the GIL is taken back briefly to let Python
// handle signals: Ctrl+C cancels the run and raises KeyboardInterrupt. The ground truth is given
// in the frames of the arrays as passed; the pipeline's clouds may have been moved to frames near
// their points (their origin), as make_registration's poses are moved back.
Registration run_pipeline(Pipeline& pipeline, std::optional<Transform> truth,
                          const std::string& source_name, const std::string& target_name) {
  if (truth && pipeline.has_clouds())
    truth = to_cloud_frames(*truth, pipeline.source().origin, pipeline.target().origin);
  pipeline.set_ground_truth(truth);
  std::atomic<bool> cancel{false};
  std::optional<py::error_already_set> interrupted;
  const ProgressFn check_signals = [&](Stage, double) {
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
      interrupted.emplace();
      cancel = true;
    }
  };
  Registration registration;
  try {
    const py::gil_scoped_release release;
    pipeline.run(check_signals, &cancel);
    RegistrationContext context;
    context.source_name = source_name;
    context.target_name = target_name;
    registration = make_registration(pipeline, context);
  } catch (const Cancelled&) {
    if (!interrupted) throw;
  }
  if (interrupted) throw std::move(*interrupted);  // also when it came after the last stage
  return registration;
}

// A cloud's landmarks in the frame of its array: positions (N x 3 float64) and class indices.
py::dict landmarks_dict(const LandmarkSet& set, const Eigen::Vector3d& origin) {
  std::vector<Eigen::Vector3d> positions;
  py::array_t<std::int32_t> classes(static_cast<py::ssize_t>(set.landmarks.size()));
  auto view = classes.mutable_unchecked<1>();
  for (std::size_t i = 0; i < set.landmarks.size(); ++i) {
    positions.push_back(set.landmarks[i].centroid);
    view(static_cast<py::ssize_t>(i)) = set.landmarks[i].class_index;
  }
  py::dict out;
  out["positions"] = vectors_to_array(positions, origin);
  out["class_index"] = classes;
  return out;
}

// The run's result: the report (schema pagor.register/1), each cloud's landmarks, the
// correspondences the levels' cliques index (p and q in the frames of the arrays as passed), the
// configured class names and the warnings about the inputs.
py::dict result_dict(const Pipeline& pipeline, const Registration& registration,
                     const std::vector<std::string>& input_warnings) {
  const Eigen::Vector3d source_origin =
      pipeline.has_clouds() ? pipeline.source().origin : Eigen::Vector3d::Zero();
  const Eigen::Vector3d target_origin =
      pipeline.has_clouds() ? pipeline.target().origin : Eigen::Vector3d::Zero();
  const std::vector<Correspondence>& items = pipeline.correspondences().items;
  std::vector<Eigen::Vector3d> p, q;
  const auto n = static_cast<py::ssize_t>(items.size());
  py::array_t<std::int32_t> classes(n), source_ids(n), target_ids(n);
  py::array_t<std::uint8_t> origins(n);
  py::array_t<double> scores(n);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    p.push_back(items[i].p);
    q.push_back(items[i].q);
    classes.mutable_at(k) = items[i].class_index;
    source_ids.mutable_at(k) = items[i].source;
    target_ids.mutable_at(k) = items[i].target;
    origins.mutable_at(k) = static_cast<std::uint8_t>(items[i].origin);
    scores.mutable_at(k) = items[i].score;
  }
  py::dict correspondences;
  correspondences["p"] = vectors_to_array(p, source_origin);
  correspondences["q"] = vectors_to_array(q, target_origin);
  correspondences["class_index"] = classes;
  correspondences["origin"] = origins;
  correspondences["source"] = source_ids;
  correspondences["target"] = target_ids;
  correspondences["score"] = scores;
  py::dict landmarks;
  landmarks["source"] = landmarks_dict(pipeline.source_landmarks(), source_origin);
  landmarks["target"] = landmarks_dict(pipeline.target_landmarks(), target_origin);
  py::list class_names;
  for (const ClassCount& c : registration.classes) class_names.append(c.name);
  py::dict out;
  out["report"] = to_python(report_object(registration));
  out["landmarks"] = landmarks;
  out["correspondences"] = correspondences;
  out["class_names"] = class_names;
  py::list warnings;
  for (const std::string& w : input_warnings) warnings.append(w);
  out["input_warnings"] = warnings;
  return out;
}

py::dict register_clouds(const py::handle& source, const py::handle& target,
                         const py::handle& source_labels, const py::handle& target_labels,
                         const py::handle& config, const py::handle& ground_truth, int threads,
                         const std::string& source_name, const std::string& target_name) {
  // Everything is checked, and the arrays copied into the core's clouds, with the GIL held.
  std::vector<std::string> warnings;
  PointCloud s = cloud_from_array(source, source_labels, "source", warnings);
  PointCloud t = cloud_from_array(target, target_labels, "target", warnings);
  const Config c = config_from_python(config);
  const std::optional<Transform> truth = truth_from(ground_truth);
  Pipeline pipeline(c, thread_count(threads));
  pipeline.set_input(std::move(s), std::move(t));
  const Registration r = run_pipeline(
      pipeline, truth, source_name.empty() ? array_name("source", pipeline) : source_name,
      target_name.empty() ? array_name("target", pipeline) : target_name);
  return result_dict(pipeline, r, warnings);
}

py::dict register_correspondences(const py::handle& p, const py::handle& q,
                                  const py::handle& weights, const py::handle& config,
                                  const py::handle& source, const py::handle& target,
                                  const py::handle& ground_truth, int threads) {
  const std::vector<Eigen::Vector3d> ps = vectors_from_array(p, "p");
  const std::vector<Eigen::Vector3d> qs = vectors_from_array(q, "q");
  if (ps.size() != qs.size())
    throw py::value_error("p and q: " + std::to_string(ps.size()) + " source points and " +
                          std::to_string(qs.size()) +
                          " target points; expected one of each per correspondence");
  std::vector<double> w;
  if (!weights.is_none()) w = weights_from_array(weights, ps.size(), "weights");
  if (source.is_none() != target.is_none())
    throw py::value_error("source and target: give both clouds to verify on, or neither");
  const Config c = config_from_python(config);
  const std::optional<Transform> truth = truth_from(ground_truth);
  std::vector<std::string> warnings;
  std::optional<PointCloud> s, t;
  if (!source.is_none()) {
    s = cloud_from_array(source, py::none(), "source", warnings);
    t = cloud_from_array(target, py::none(), "target", warnings);
  }
  // As a correspondences file gives them: a matcher's, each its own ids, score = weight; in the
  // clouds' frames when the clouds were moved near their points.
  const Eigen::Vector3d source_origin = s ? s->origin : Eigen::Vector3d::Zero();
  const Eigen::Vector3d target_origin = t ? t->origin : Eigen::Vector3d::Zero();
  std::vector<Correspondence> items(ps.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    items[i].class_index = -1;
    items[i].origin = CorrespondenceOrigin::matcher;
    items[i].source = items[i].target = static_cast<int>(i);
    items[i].p = ps[i] - source_origin;
    items[i].q = qs[i] - target_origin;
    items[i].score = w.empty() ? 1.0 : w[i];
  }
  Pipeline pipeline(c, thread_count(threads));
  pipeline.set_matches(std::move(items));
  std::string source_name = "correspondences (" + std::to_string(ps.size()) + ")";
  std::string target_name = source_name;
  if (s) {
    pipeline.set_input(std::move(*s), std::move(*t));
    source_name = array_name("source", pipeline);
    target_name = array_name("target", pipeline);
  }
  const Registration r = run_pipeline(pipeline, truth, source_name, target_name);
  return result_dict(pipeline, r, warnings);
}

}  // namespace

void define_register(py::module_& m) {
  m.def("register_clouds", &register_clouds, py::arg("source"), py::arg("target"),
        py::arg("source_labels"), py::arg("target_labels"), py::arg("config"),
        py::arg("ground_truth"), py::arg("threads"), py::arg("source_name"), py::arg("target_name"),
        "pagor.register's run on checked arguments (see pagor.register; a name \"\" for an "
        "array): a dict with 'report', "
        "'landmarks', 'correspondences', 'class_names' and 'input_warnings'.");
  m.def("register_correspondences", &register_correspondences, py::arg("p"), py::arg("q"),
        py::arg("weights"), py::arg("config"), py::arg("source"), py::arg("target"),
        py::arg("ground_truth"), py::arg("threads"),
        "pagor.register_correspondences's run (see there); the same dict as register_clouds.");
}

}  // namespace pagor::python
