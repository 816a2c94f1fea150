#pragma once
/// \file arrays.hpp
/// numpy arrays to the core's types and back. Inputs are checked with the GIL held and every
/// problem raises ValueError naming the argument (`source: expected an N x 3 array ...`).
/// Reading an array never copies it on the Python side: any strides are read in place, and the
/// one copy made is into the core's own storage (PointCloud owns std::vector<Eigen::Vector3f>).
/// Arrays handed back to Python own the core's vectors (moved, not copied).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pagor/types.hpp"

namespace pagor::python {

namespace py = pybind11;

/// A cloud from an N x 3 array of float32 or float64 (anything numpy.asarray takes; a numpy array
/// or a buffer such as Open3D's Vector3dVector is read in place) and optional labels, framed as
/// the file readers frame a file's cloud (load_cloud, io/cloud_frame.hpp): a cloud whose median
/// point lies farther than 1 km from the origin keeps float32 points relative to a frame origin
/// near them (`origin`, chosen from the coordinates in double), and points farther than 1e6 m
/// from that origin on an axis (corrupt: 1e30) are dropped, with their labels, and a warning
/// naming `what` is added to `warnings`. Raises ValueError naming `what` (or `what`_labels) for
/// another shape or dtype, no points, a non-finite coordinate (naming the point), no point left,
/// or labels that do not fit (labels_from_array).
PointCloud cloud_from_array(const py::handle& points, const py::handle& labels,
                            const std::string& what, std::vector<std::string>& warnings);

/// 3-D vectors in double precision (correspondences: the core keeps them as double). Raises
/// ValueError naming `what` and the row for another shape or dtype, no rows, a non-finite
/// coordinate or one beyond kMaxMatchCoordinate (correspondence_file.hpp: as a file's).
std::vector<Eigen::Vector3d> vectors_from_array(const py::handle& array, const std::string& what);

/// N labels from a 1-D integer array (uint32 is read in place; other integer types are checked to
/// be within 0 .. 2^32 - 1). Raises ValueError for another shape, dtype or count.
std::vector<std::uint32_t> labels_from_array(const py::handle& array, std::size_t count,
                                             const std::string& what);

/// N non-negative finite weights from a 1-D float array. Raises ValueError otherwise.
std::vector<double> weights_from_array(const py::handle& array, std::size_t count,
                                       const std::string& what);

/// A 4 x 4 rigid transform. Raises ValueError for another shape, a non-finite entry or a matrix
/// that is not rigid (check_rigid's message).
Transform transform_from_array(const py::handle& array, const std::string& what);

/// A 4 x 4 float64 array (a copy: 128 bytes).
py::array_t<double> transform_to_array(const Transform& T);

/// N x 3 float64 array of `rows` plus `offset` (a copy).
py::array_t<double> vectors_to_array(const std::vector<Eigen::Vector3d>& rows,
                                     const Eigen::Vector3d& offset = Eigen::Vector3d::Zero());

/// N x 3 float32 array that owns `points` (moved in; no copy).
py::array_t<float> points_to_array(std::vector<Eigen::Vector3f>&& points);

/// N uint32 array that owns `labels` (moved in; no copy).
py::array_t<std::uint32_t> labels_to_array(std::vector<std::uint32_t>&& labels);

}  // namespace pagor::python
