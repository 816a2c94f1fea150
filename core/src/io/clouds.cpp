#include "pagor/io/clouds.hpp"

#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "pagor/errors.hpp"
#include "io/pcd_reader.hpp"
#include "io/ply_reader.hpp"

namespace pagor {
namespace {

constexpr std::size_t kKittiPointBytes = 4 * sizeof(float);

std::vector<char> read_file_bytes(const std::string& path, const char* what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": " + what + " does not exist");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": " + what + " is a directory, expected a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open " + what + " for reading");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(path + ": cannot read " + what);
  in.seekg(0, std::ios::beg);
  std::vector<char> bytes(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(bytes.data(), size)) throw InputError(path + ": cannot read " + what);
  return bytes;
}

void write_file_bytes(const std::string& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path + ": cannot open for writing");
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) throw InputError(path + ": write failed");
}

PointCloud read_cloud_file(const std::string& path, const std::string& ext) {
  const std::vector<char> bytes = read_file_bytes(path, "point cloud");
  const std::string_view view(bytes.data(), bytes.size());
  return ext == ".pcd" ? parse_pcd(view, path) : parse_ply(view, path);
}

pcl::PCLPointCloud2 to_blob(const PointCloud& cloud) {
  pcl::PCLPointCloud2 blob;
  auto add_field = [&](const char* name, std::uint8_t type) {
    pcl::PCLPointField f;
    f.name = name;
    f.offset = blob.point_step;
    f.datatype = type;
    f.count = 1;
    blob.fields.push_back(f);
    blob.point_step += 4;
  };
  add_field("x", pcl::PCLPointField::FLOAT32);
  add_field("y", pcl::PCLPointField::FLOAT32);
  add_field("z", pcl::PCLPointField::FLOAT32);
  if (cloud.has_intensities()) add_field("intensity", pcl::PCLPointField::FLOAT32);
  if (cloud.has_labels()) add_field("label", pcl::PCLPointField::UINT32);
  blob.width = static_cast<std::uint32_t>(cloud.size());
  blob.height = 1;
  blob.is_dense = true;
  blob.row_step = blob.point_step * blob.width;
  blob.data.resize(blob.row_step);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    std::uint8_t* base = blob.data.data() + i * blob.point_step;
    std::memcpy(base, cloud.points[i].data(), 12);
    std::size_t off = 12;
    if (cloud.has_intensities()) {
      std::memcpy(base + off, &cloud.intensities[i], 4);
      off += 4;
    }
    if (cloud.has_labels()) std::memcpy(base + off, &cloud.labels[i], 4);
  }
  return blob;
}

std::string replace_extension(const std::string& path, const std::string& ext) {
  return std::filesystem::path(path).replace_extension(ext).string();
}

}  // namespace

std::string file_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

PointCloud read_kitti_bin(const std::string& path) {
  const std::vector<char> bytes = read_file_bytes(path, "scan");
  if (bytes.size() % kKittiPointBytes != 0)
    throw InputError(path + ": size " + std::to_string(bytes.size()) +
                     " bytes is not a multiple of 16 (float32 x, y, z, reflectance per point)");
  const std::size_t n = bytes.size() / kKittiPointBytes;
  PointCloud cloud;
  cloud.points.resize(n);
  cloud.intensities.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    float v[4];
    std::memcpy(v, bytes.data() + i * kKittiPointBytes, kKittiPointBytes);
    cloud.points[i] = Eigen::Vector3f(v[0], v[1], v[2]);
    cloud.intensities[i] = v[3];
  }
  return cloud;
}

std::vector<std::uint32_t> read_kitti_labels(const std::string& path) {
  const std::vector<char> bytes = read_file_bytes(path, "label file");
  if (bytes.size() % sizeof(std::uint32_t) != 0)
    throw InputError(path + ": size " + std::to_string(bytes.size()) +
                     " bytes is not a multiple of 4 (one uint32 per point)");
  std::vector<std::uint32_t> labels(bytes.size() / sizeof(std::uint32_t));
  if (!labels.empty()) std::memcpy(labels.data(), bytes.data(), bytes.size());
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
  const pcl::PCLPointCloud2 blob = to_blob(cloud);
  int status = 0;
  if (ext == ".pcd") {
    pcl::PCDWriter writer;
    status = writer.writeBinary(path, blob);
  } else {
    pcl::PLYWriter writer;
    status = writer.writeBinary(path, blob);
  }
  if (status < 0) throw InputError(path + ": cannot write " + ext.substr(1) + " file");
}

LoadedCloud load_cloud(const std::string& path, const std::string& labels_path) {
  const std::string ext = file_extension(path);
  LoadedCloud out;
  if (ext == ".bin") {
    out.cloud = read_kitti_bin(path);
  } else if (ext == ".pcd" || ext == ".ply") {
    out.cloud = read_cloud_file(path, ext);
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

  // Drop non-finite points, keeping the per-point arrays aligned.
  PointCloud& c = out.cloud;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!c.points[i].allFinite()) continue;
    c.points[kept] = c.points[i];
    if (c.has_intensities()) c.intensities[kept] = c.intensities[i];
    if (c.has_labels()) c.labels[kept] = c.labels[i];
    ++kept;
  }
  out.dropped_nonfinite = c.size() - kept;
  c.points.resize(kept);
  if (c.has_intensities()) c.intensities.resize(kept);
  if (c.has_labels()) c.labels.resize(kept);
  if (out.dropped_nonfinite > 0)
    out.warnings.push_back(path + ": dropped " + std::to_string(out.dropped_nonfinite) +
                           " points with NaN or Inf coordinates");
  if (c.empty())
    throw InputError(path +
                     (out.dropped_nonfinite > 0 ? ": no finite points" : ": the cloud is empty"));
  return out;
}

}  // namespace pagor
