// pagor.read_cloud and pagor.synthetic_scene: clouds as numpy arrays.

#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/sets/synthetic.hpp"

namespace pagor::python {
namespace {

std::string path_text(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fsdecode")(path));
}

// (points, labels or None), both arrays owning the core's vectors.
py::tuple cloud_tuple(PointCloud&& cloud) {
  py::object labels = py::none();
  if (cloud.has_labels()) labels = labels_to_array(std::move(cloud.labels));
  return py::make_tuple(points_to_array(std::move(cloud.points)), labels);
}

py::tuple read_cloud(const py::handle& path, const py::handle& labels_path) {
  const std::string file = path_text(path);
  const std::string labels = labels_path.is_none() ? std::string() : path_text(labels_path);
  LoadedCloud loaded;
  {
    py::gil_scoped_release release;
    loaded = load_cloud(file, labels);
  }
  for (const std::string& w : loaded.warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, (file + ": " + w).c_str(), 1) != 0)
      throw py::error_already_set();
  return cloud_tuple(std::move(loaded.cloud));
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
  m.def("read_cloud", &read_cloud, py::arg("path"), py::arg("labels_path") = py::none(),
        "Reads a cloud as the pagor tool does: KITTI .bin (float32 x, y, z, reflectance), .pcd "
        "(ASCII, binary, binary_compressed) or .ply, with labels from the file's `label` field or "
        "from a SemanticKITTI .label file (labels_path). Returns (points, labels): an N x 3 "
        "float32 array [m] and an N uint32 array, or None without labels. Points with a "
        "non-finite coordinate are dropped with a UserWarning. The arrays own the data read (no "
        "copy). A missing, unreadable or malformed file raises pagor.Error (a ValueError) "
        "naming the file.");
  m.def("synthetic_scene", &synthetic_scene, py::arg("seed") = 7,
        "The generated outdoor scene (`pagor register --synthetic SEED`): a dict with 'source', "
        "'target' (N x 3 float32 [m]), 'source_labels', 'target_labels' (uint32, "
        "semantickitti-train ids) and 'T_target_source' (4 x 4), the transform that maps source "
        "points into the target frame.");
}

}  // namespace pagor::python
