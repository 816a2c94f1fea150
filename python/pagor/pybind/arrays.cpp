#include "arrays.hpp"

#include <cmath>
#include <sstream>

#include "io/cloud_frame.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/io/correspondence_file.hpp"

namespace pagor::python {
namespace {

// numpy's view of an argument: an ndarray is taken as it is (no copy); other objects go through
// numpy.asarray (a buffer is viewed, a list is converted once).
py::array as_array(const py::handle& object, const std::string& what) {
  if (object.is_none()) throw py::value_error(what + ": expected an array, got None");
  py::array a = py::array::ensure(object);
  if (!a) {
    PyErr_Clear();
    throw py::value_error(what +
                          ": expected a numpy array (or something numpy.asarray takes), got " +
                          std::string(py::str(py::type::handle_of(object).attr("__name__"))));
  }
  return a;
}

std::string shape_text(const py::array& a) {
  std::ostringstream s;
  s << "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s << (d ? ", " : "") << a.shape(d);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

std::string text(const py::handle& object) {
  return py::str(object);
}

std::string dtype_text(const py::array& a) {
  return py::str(a.dtype());
}

// The rows of an N x 3 float32 or float64 array as double vectors, checked finite. Any strides
// are read in place.
template <class Scalar>
void read_rows(const py::array& a, std::vector<Eigen::Vector3d>& out, const std::string& what) {
  const auto view = a.unchecked<Scalar, 2>();
  out.resize(static_cast<std::size_t>(view.shape(0)));
  for (py::ssize_t i = 0; i < view.shape(0); ++i) {
    Eigen::Vector3d& p = out[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) p[k] = static_cast<double>(view(i, k));
    if (!p.allFinite()) {
      std::ostringstream s;
      s << what << ": point " << i << " has a non-finite coordinate (" << view(i, 0) << ", "
        << view(i, 1) << ", " << view(i, 2) << ")";
      throw py::value_error(s.str());
    }
  }
}

std::vector<Eigen::Vector3d> rows_from_array(const py::handle& object, const std::string& what) {
  const py::array a = as_array(object, what);
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(what + ": expected an N x 3 array of points, got shape " + shape_text(a));
  if (a.shape(0) == 0) throw py::value_error(what + ": no points (shape " + shape_text(a) + ")");
  std::vector<Eigen::Vector3d> out;
  if (py::array_t<float>::check_(a))
    read_rows<float>(a, out, what);
  else if (py::array_t<double>::check_(a))
    read_rows<double>(a, out, what);
  else
    throw py::value_error(what + ": expected float32 or float64 coordinates, got dtype " +
                          dtype_text(a));
  return out;
}

}  // namespace

PointCloud cloud_from_array(const py::handle& points, const py::handle& labels,
                            const std::string& what, std::vector<std::string>& warnings) {
  const std::vector<Eigen::Vector3d> rows = rows_from_array(points, what);
  PointCloud cloud;
  std::vector<std::uint32_t> all_labels;
  if (!labels.is_none()) all_labels = labels_from_array(labels, rows.size(), what + "_labels");
  // The file readers' frame (cloud_frame.hpp): far from the origin, relative to an origin near
  // the points; float32 input shifts exactly (whole metres), float64 keeps its precision there.
  cloud.origin = frame_origin(rows.size(), [&](std::size_t i) { return rows[i]; });
  cloud.points.reserve(rows.size());
  if (!all_labels.empty()) cloud.labels.reserve(rows.size());
  double loss = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Eigen::Vector3f p;
    for (int k = 0; k < 3; ++k) p[k] = narrowed(rows[i][k], cloud.origin[k], loss);
    if (!(p.cwiseAbs().maxCoeff() <= kMaxCoordinate)) continue;  // corrupt (1e30): dropped
    cloud.points.push_back(p);
    if (!all_labels.empty()) cloud.labels.push_back(all_labels[i]);
  }
  const std::size_t dropped = rows.size() - cloud.points.size();
  if (cloud.points.empty())
    throw py::value_error(what + ": no point lies within 1e6 m of the cloud's centre (all " +
                          std::to_string(rows.size()) + " are corrupt or far apart)");
  if (dropped > 0)
    warnings.push_back(what + ": dropped " + std::to_string(dropped) +
                       (dropped == 1 ? " point" : " points") +
                       " lying more than 1e6 m from the cloud's centre (corrupt coordinates)");
  return cloud;
}

std::vector<Eigen::Vector3d> vectors_from_array(const py::handle& array, const std::string& what) {
  std::vector<Eigen::Vector3d> rows = rows_from_array(array, what);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!(rows[i].cwiseAbs().maxCoeff() <= kMaxMatchCoordinate)) {
      std::ostringstream s;
      s << what << ": point " << i << " (" << rows[i][0] << ", " << rows[i][1] << ", " << rows[i][2]
        << ") lies farther than " << kMaxMatchCoordinate
        << " m from the origin on an axis (corrupt coordinates)";
      throw py::value_error(s.str());
    }
  }
  return rows;
}

std::vector<std::uint32_t> labels_from_array(const py::handle& object, std::size_t count,
                                             const std::string& what) {
  py::array a = as_array(object, what);
  if (a.ndim() != 1)
    throw py::value_error(what + ": expected a 1-D array of labels, got shape " + shape_text(a));
  if (static_cast<std::size_t>(a.shape(0)) != count)
    throw py::value_error(what + ": " + std::to_string(a.shape(0)) + " labels for " +
                          std::to_string(count) + " points; expected one label per point");
  const char kind = a.dtype().kind();
  if (kind != 'u' && kind != 'i')
    throw py::value_error(what + ": expected integer labels (uint32), got dtype " + dtype_text(a));
  if (!py::array_t<std::uint32_t>::check_(a) && count > 0) {
    // Another integer type: every value must fit a uint32 (one conversion copy, by numpy).
    const py::int_ low = a.attr("min")(), high = a.attr("max")();
    if (low < py::int_(0) || high > py::int_(0xFFFFFFFFu))
      throw py::value_error(what + ": labels must be within 0 .. 4294967295, got " + text(low) +
                            " .. " + text(high));
    a = a.attr("astype")(py::dtype::of<std::uint32_t>());
  }
  const auto view = a.unchecked<std::uint32_t, 1>();
  std::vector<std::uint32_t> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = view(static_cast<py::ssize_t>(i));
  return out;
}

std::vector<double> weights_from_array(const py::handle& object, std::size_t count,
                                       const std::string& what) {
  const py::array a = as_array(object, what);
  if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != count)
    throw py::value_error(what + ": expected " + std::to_string(count) +
                          " weights (one per correspondence), got shape " + shape_text(a));
  if (a.dtype().kind() != 'f' && a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw py::value_error(what + ": expected numbers, got dtype " + dtype_text(a));
  const py::array d = a.attr("astype")(py::dtype::of<double>(), py::arg("copy") = false);
  const auto view = d.unchecked<double, 1>();
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    out[i] = view(static_cast<py::ssize_t>(i));
    if (!std::isfinite(out[i]) || out[i] < 0)
      throw py::value_error(what + ": weight " + std::to_string(i) + " is " +
                            text(py::float_(out[i])) + "; expected a finite number >= 0");
  }
  return out;
}

Transform transform_from_array(const py::handle& object, const std::string& what) {
  const py::array a = as_array(object, what);
  if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
    throw py::value_error(what + ": expected a 4 x 4 transform, got shape " + shape_text(a));
  if (a.dtype().kind() != 'f' && a.dtype().kind() != 'i')
    throw py::value_error(what + ": expected numbers, got dtype " + dtype_text(a));
  const py::array d = a.attr("astype")(py::dtype::of<double>(), py::arg("copy") = false);
  const auto view = d.unchecked<double, 2>();
  Transform T;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) T(r, c) = view(r, c);
  try {
    check_rigid(T, what);
  } catch (const InputError& e) {
    throw py::value_error(e.what());
  }
  return T;
}

py::array_t<double> transform_to_array(const Transform& T) {
  py::array_t<double> out({4, 4});
  auto view = out.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) view(r, c) = T(r, c);
  return out;
}

py::array_t<double> vectors_to_array(const std::vector<Eigen::Vector3d>& rows,
                                     const Eigen::Vector3d& offset) {
  py::array_t<double> out({static_cast<py::ssize_t>(rows.size()), py::ssize_t{3}});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) view(static_cast<py::ssize_t>(i), k) = rows[i][k] + offset[k];
  return out;
}

py::array_t<float> points_to_array(std::vector<Eigen::Vector3f>&& points) {
  static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "points are packed x, y, z");
  auto* owner = new std::vector<Eigen::Vector3f>(std::move(points));
  const py::capsule base(owner,
                         [](void* p) { delete static_cast<std::vector<Eigen::Vector3f>*>(p); });
  const auto n = static_cast<py::ssize_t>(owner->size());
  return py::array_t<float>(
      {n, py::ssize_t{3}},
      {static_cast<py::ssize_t>(sizeof(Eigen::Vector3f)), static_cast<py::ssize_t>(sizeof(float))},
      owner->empty() ? nullptr : owner->front().data(), base);
}

py::array_t<std::uint32_t> labels_to_array(std::vector<std::uint32_t>&& labels) {
  auto* owner = new std::vector<std::uint32_t>(std::move(labels));
  const py::capsule base(owner,
                         [](void* p) { delete static_cast<std::vector<std::uint32_t>*>(p); });
  return py::array_t<std::uint32_t>({static_cast<py::ssize_t>(owner->size())},
                                    {static_cast<py::ssize_t>(sizeof(std::uint32_t))},
                                    owner->data(), base);
}

}  // namespace pagor::python
