// _pagor.read_cloud and _pagor.synthetic_scene: clouds as numpy arrays.

#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/io/clouds.hpp"

namespace pagor::python {
namespace {

// (points, labels or None), both arrays owning the core's vectors.
py::tuple cloud_tuple(PointCloud&& cloud) {
  py::object labels = py::none();
  if (cloud.has_labels()) labels = labels_to_array(std::move(cloud.labels));
  return py::make_tuple(points_to_array(std::move(cloud.points)), labels);
}

// A path as the file system's bytes (os.fsencode in pagor.read_cloud), refusing a NUL: the C
// library would cut the name there and read another file.
std::string path_bytes(const py::bytes& path, const char* what) {
  std::string out = path;
  if (out.find('\0') != std::string::npos)
    throw py::value_error(std::string(what) + ": the path contains a NUL byte");
  return out;
}

// (points, labels or None, origin, warnings): float32 points in the cloud's frame, whose origin
// (3 float64) lies at `origin` in the file's frame (zero but for a cloud far from its file's
// origin); pagor.read_cloud adds it back.
py::tuple read_cloud(const py::bytes& path, const py::object& labels_path) {
  const std::string file = path_bytes(path, "path");
  const std::string labels =
      labels_path.is_none() ? std::string() : path_bytes(labels_path, "labels_path");
  LoadedCloud loaded;
  {
    py::gil_scoped_release release;
    loaded = load_cloud(file, labels);
  }
  const Eigen::Vector3d origin = loaded.cloud.origin;
  const py::tuple cloud = cloud_tuple(std::move(loaded.cloud));
  py::list warnings;
  for (const std::string& w : loaded.warnings)
    warnings.append(py::reinterpret_steal<py::str>(
        PyUnicode_DecodeUTF8((file + ": " + w).data(),
                             static_cast<py::ssize_t>(file.size() + 2 + w.size()), "replace")));
  return py::make_tuple(cloud[0], cloud[1], py::make_tuple(origin[0], origin[1], origin[2]),
                        warnings);
}

py::dict synthetic_scene(std::uint64_t seed) {
  SyntheticParams params;
  params.seed = seed;
  SyntheticScene scene;
  {
    py::gil_scoped_release release;
    scene = make_synthetic_scene(params);
  }
  const py::tuple source = cloud_tuple(std::move(scene.source));
  const py::tuple target = cloud_tuple(std::move(scene.target));
  py::dict out;
  out["source"] = source[0];
  out["source_labels"] = source[1];
  out["target"] = target[0];
  out["target_labels"] = target[1];
  out["T_target_source"] = transform_to_array(scene.T_target_source);
  return out;
}

}  // namespace

void define_io(py::module_& m) {
  m.def("read_cloud", &read_cloud, py::arg("path"), py::arg("labels_path"),
        "pagor.read_cloud's reading (paths as bytes): (points, labels or None, origin, "
        "warnings).");
  m.def("synthetic_scene", &synthetic_scene, py::arg("seed"),
        "pagor.synthetic_scene's scene (see there).");
}

}  // namespace pagor::python
