#include "pagor/io/clouds.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string_view>

#include "io/cloud_frame.hpp"
#include "io/read_pieces.hpp"
#include "io/pcd_reader.hpp"
#include "io/ply_reader.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/file_input.hpp"

namespace pagor {
namespace {

constexpr std::size_t kKittiPointBytes = 4 * sizeof(float);
// A rounding of coordinates to float32 worth a warning [m].
constexpr double kReportedNarrowing = 1e-3;

// Whole or not at all: an interrupted write leaves the previous file (atomic_file.hpp).
void write_file_bytes(const std::string& path, const void* data, std::size_t size) {
  write_file_atomic(path, std::string_view(static_cast<const char*>(data), size));
}

PointCloud read_cloud_file(const std::string& path, const std::string& ext,
                           double& narrowing_loss) {
  const std::string bytes = read_file(path, "point cloud", kMaxCloudFileBytes);
  return ext == ".pcd" ? parse_pcd(bytes, path, &narrowing_loss)
                       : parse_ply(bytes, path, &narrowing_loss);
}

// A cloud read as float32 far from its file's origin moves to its own frame: exact, since a float
// minus whole metres is exact in double, and the small result fits a float again.
void move_to_own_frame(PointCloud& c) {
  if (!c.origin.isZero()) return;  // the reader chose the frame
  c.origin = frame_origin(c.size(), [&](std::size_t i) { return c.points[i].cast<double>(); });
  if (c.origin.isZero()) return;
  double loss = 0;
  for (auto& p : c.points)
    for (int k = 0; k < 3; ++k) p[k] = narrowed(p[k], c.origin[k], loss);
}

// Drops the points with a non-finite coordinate or one beyond kMaxCoordinate, keeping the
// per-point arrays aligned and counting both.
void drop_unusable(LoadedCloud& out) {
  PointCloud& c = out.cloud;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!c.points[i].allFinite()) {
      ++out.dropped_nonfinite;
      continue;
    }
    if (!(c.points[i].cwiseAbs().maxCoeff() <= kMaxCoordinate)) {
      ++out.dropped_far;
      continue;
    }
    c.points[kept] = c.points[i];
    if (c.has_intensities()) c.intensities[kept] = c.intensities[i];
    if (c.has_labels()) c.labels[kept] = c.labels[i];
    ++kept;
  }
  c.points.resize(kept);
  if (c.has_intensities()) c.intensities.resize(kept);
  if (c.has_labels()) c.labels.resize(kept);
}

// PCD and PLY are written by the project itself, as binary files PCL and other readers load:
// x y z as float32, then intensity (float32) and label (uint32) when the cloud has them. (PCL's
// writers were the only use of its io component, which loads ~120 shared libraries, VTK and Qt
// among them, into every process that links the core.)
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the binary PCD and PLY bodies are written in the host's byte order");

// The body of both formats: one record a point, the fields in the header's order.
std::string binary_points(const PointCloud& cloud) {
  const std::size_t step = 12 + (cloud.has_intensities() ? 4 : 0) + (cloud.has_labels() ? 4 : 0);
  std::string body(cloud.size() * step, '\0');
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    char* base = body.data() + i * step;
    std::memcpy(base, cloud.points[i].data(), 12);
    std::size_t off = 12;
    if (cloud.has_intensities()) {
      std::memcpy(base + off, &cloud.intensities[i], 4);
      off += 4;
    }
    if (cloud.has_labels()) std::memcpy(base + off, &cloud.labels[i], 4);
  }
  return body;
}

std::string pcd_header(const PointCloud& cloud) {
  std::string fields = "x y z", sizes = "4 4 4", types = "F F F", counts = "1 1 1";
  const auto add = [&](const char* name, const char* type) {
    fields += std::string(" ") + name;
    sizes += " 4";
    types += std::string(" ") + type;
    counts += " 1";
  };
  if (cloud.has_intensities()) add("intensity", "F");
  if (cloud.has_labels()) add("label", "U");
  const std::string n = std::to_string(cloud.size());
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " + fields +
         "\nSIZE " + sizes + "\nTYPE " + types + "\nCOUNT " + counts + "\nWIDTH " + n +
         "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + n + "\nDATA binary\n";
}

std::string ply_header(const PointCloud& cloud) {
  std::string h = "ply\nformat binary_little_endian 1.0\ncomment written by pagor\nelement vertex " +
                  std::to_string(cloud.size()) +
                  "\nproperty float x\nproperty float y\nproperty float z\n";
  if (cloud.has_intensities()) h += "property float intensity\n";
  if (cloud.has_labels()) h += "property uint label\n";
  return h + "end_header\n";
}

std::string replace_extension(const std::string& path, const std::string& ext) {
  return std::filesystem::path(path).replace_extension(ext).string();
}

}  // namespace

Transform to_cloud_frames(const Transform& T_files, const Eigen::Vector3d& source_origin,
                          const Eigen::Vector3d& target_origin) {
  if (source_origin.isZero() && target_origin.isZero()) return T_files;
  // q_file = R p_file + t with p_file = p + o_s, q_file = q + o_t:  q = R p + (R o_s + t - o_t).
  Transform T = T_files;
  T.block<3, 1>(0, 3) += T_files.block<3, 3>(0, 0) * source_origin - target_origin;
  return T;
}

Transform to_file_frames(const Transform& T_clouds, const Eigen::Vector3d& source_origin,
                         const Eigen::Vector3d& target_origin) {
  if (source_origin.isZero() && target_origin.isZero()) return T_clouds;
  Transform T = T_clouds;
  T.block<3, 1>(0, 3) += target_origin - T_clouds.block<3, 3>(0, 0) * source_origin;
  return T;
}

std::string file_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

namespace {

// Reads `path` as records of `record` bytes, handing them to add(bytes, count) as they arrive
// (no copy of the whole file: on a virtual machine its fresh pages cost more than the reading).
// Throws InputError when the size is not a whole number of records (of at most 16 bytes).
template <class Reserve, class Add>
void read_records(const std::string& path, const char* what, std::size_t record,
                         const char* layout, const Reserve& reserve, const Add& add) {
  char partial[16];
  std::size_t carry = 0;
  const std::uint64_t total = read_file_pieces(
      path, what, kMaxCloudFileBytes,
      [&](std::uint64_t size) { reserve(static_cast<std::size_t>(size / record)); },
      [&](const char* data, std::size_t n) {
        if (carry > 0) {  // a record split between two pieces
          const std::size_t take = std::min(record - carry, n);
          std::memcpy(partial + carry, data, take);
          carry += take, data += take, n -= take;
          if (carry < record) return;
          add(partial, std::size_t{1}), carry = 0;
        }
        const std::size_t whole = n / record;
        if (whole > 0) add(data, whole);
        carry = n - whole * record;
        std::memcpy(partial, data + whole * record, carry);
      });
  if (carry > 0)
    throw InputError(path + ": size " + std::to_string(total) + " bytes is not a multiple of " +
                     std::to_string(record) + " (" + layout + ")");
}

}  // namespace

PointCloud read_kitti_bin(const std::string& path) {
  PointCloud cloud;
  read_records(
      path, "scan", kKittiPointBytes, "float32 x, y, z, reflectance per point",
      [&](std::size_t n) {
        cloud.points.reserve(n);
        cloud.intensities.reserve(n);
      },
      [&](const char* bytes, std::size_t count) {
        for (std::size_t i = 0; i < count; ++i, bytes += kKittiPointBytes) {
          float v[4];
          std::memcpy(v, bytes, kKittiPointBytes);
          cloud.points.emplace_back(v[0], v[1], v[2]);
          cloud.intensities.push_back(v[3]);
        }
      });
  return cloud;
}

std::vector<std::uint32_t> read_kitti_labels(const std::string& path) {
  std::vector<std::uint32_t> labels;
  read_records(
      path, "label file", sizeof(std::uint32_t), "one uint32 per point",
      [&](std::size_t n) { labels.reserve(n); },
      [&](const char* bytes, std::size_t count) {
        const std::size_t at = labels.size();
        labels.resize(at + count);
        std::memcpy(labels.data() + at, bytes, count * sizeof(std::uint32_t));
      });
  return labels;
}

void write_kitti_bin(const PointCloud& cloud, const std::string& path) {
  std::vector<float> data(cloud.size() * 4);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    data[4 * i + 0] = cloud.points[i].x();
    data[4 * i + 1] = cloud.points[i].y();
    data[4 * i + 2] = cloud.points[i].z();
    data[4 * i + 3] = cloud.has_intensities() ? cloud.intensities[i] : 0.0f;
  }
  write_file_bytes(path, data.data(), data.size() * sizeof(float));
}

void write_kitti_labels(const std::vector<std::uint32_t>& labels, const std::string& path) {
  write_file_bytes(path, labels.data(), labels.size() * sizeof(std::uint32_t));
}

void save_cloud(const PointCloud& cloud, const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext == ".bin") {
    write_kitti_bin(cloud, path);
    if (cloud.has_labels()) write_kitti_labels(cloud.labels, replace_extension(path, ".label"));
    return;
  }
  if (ext != ".pcd" && ext != ".ply")
    throw InputError(path + ": unknown point-cloud extension '" + ext + "' (use .bin, .pcd, .ply)");
  // Whole or not at all (write_file_atomic): an interrupted write leaves the previous file.
  write_file_atomic(path, (ext == ".pcd" ? pcd_header(cloud) : ply_header(cloud)) +
                              binary_points(cloud));
}

LoadedCloud load_cloud(const std::string& path, const std::string& labels_path) {
  const std::string ext = file_extension(path);
  LoadedCloud out;
  double narrowing_loss = 0;
  if (ext == ".bin") {
    out.cloud = read_kitti_bin(path);
  } else if (ext == ".pcd" || ext == ".ply") {
    out.cloud = read_cloud_file(path, ext, narrowing_loss);
  } else {
    throw InputError(path + ": unknown point-cloud extension '" + ext + "' (use .bin, .pcd, .ply)");
  }
  if (!labels_path.empty()) {
    std::vector<std::uint32_t> labels = read_kitti_labels(labels_path);
    if (labels.size() != out.cloud.size())
      throw InputError(labels_path + ": " + std::to_string(labels.size()) + " labels for " +
                       std::to_string(out.cloud.size()) + " points in " + path);
    if (out.cloud.has_labels())
      out.warnings.push_back(path + ": its label field is replaced by " + labels_path);
    out.cloud.labels = std::move(labels);
  }

  move_to_own_frame(out.cloud);
  drop_unusable(out);
  const PointCloud& c = out.cloud;
  if (out.dropped_nonfinite > 0)
    out.warnings.push_back(path + ": dropped " + std::to_string(out.dropped_nonfinite) +
                           " points with NaN or Inf coordinates");
  if (out.dropped_far > 0)
    out.warnings.push_back(path + ": dropped " + std::to_string(out.dropped_far) +
                           " points lying more than 1e6 m from the cloud's centre (corrupt "
                           "coordinates)");
  if (narrowing_loss > kReportedNarrowing) {
    char buf[160];
    std::snprintf(buf, sizeof(buf),
                  ": coordinates stored as float32 lose up to %.1f mm (the cloud spans too far "
                  "for float32 precision)",
                  1e3 * narrowing_loss);
    out.warnings.push_back(path + buf);
  }
  if (c.empty())
    throw InputError(path + (out.dropped_nonfinite + out.dropped_far > 0
                                 ? ": no finite points within 1e6 m of the cloud's centre"
                                 : ": the cloud is empty"));
  return out;
}

}  // namespace pagor
