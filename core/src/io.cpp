#include "pagor/io.hpp"

#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pagor/errors.hpp"

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

// Reads one scalar of any PCL datatype as double.
double read_scalar(const std::uint8_t* p, std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8: {
      std::int8_t v;
      std::memcpy(&v, p, 1);
      return v;
    }
    case pcl::PCLPointField::UINT8: {
      std::uint8_t v;
      std::memcpy(&v, p, 1);
      return v;
    }
    case pcl::PCLPointField::INT16: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case pcl::PCLPointField::UINT16: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case pcl::PCLPointField::INT32: {
      std::int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case pcl::PCLPointField::UINT32: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case pcl::PCLPointField::FLOAT32: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case pcl::PCLPointField::FLOAT64: {
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }
    default:
      return std::nan("");
  }
}

const pcl::PCLPointField* find_field(const pcl::PCLPointCloud2& blob, const char* name) {
  for (const auto& f : blob.fields)
    if (f.name == name) return &f;
  return nullptr;
}

// PCL's readers trust their input (a text file that is not a PCD crashes loadPCDFile), so the
// header is checked here first: the fields it declares, their sizes, the point count, and that the
// file holds as many bytes as a binary body needs.
void check_pcd_header(const std::string& path, const std::vector<char>& bytes) {
  std::istringstream in(std::string(bytes.begin(), bytes.end()));
  std::string line;
  std::size_t fields = 0, sizes = 0, types = 0, point_bytes = 0, points = 0;
  bool have_points = false, have_data = false;
  std::string data;
  while (!have_data && std::getline(in, line)) {
    std::istringstream ls(line);
    std::string key;
    if (!(ls >> key) || key[0] == '#') continue;
    std::vector<std::string> words;
    for (std::string w; ls >> w;) words.push_back(w);
    if (key == "FIELDS")
      fields = words.size();
    else if (key == "TYPE")
      types = words.size();
    else if (key == "SIZE") {
      sizes = words.size();
      for (const auto& w : words) point_bytes += static_cast<std::size_t>(std::atoi(w.c_str()));
    } else if (key == "POINTS" && words.size() == 1) {
      points = static_cast<std::size_t>(std::strtoull(words[0].c_str(), nullptr, 10));
      have_points = true;
    } else if (key == "DATA" && words.size() == 1) {
      data = words[0];
      have_data = true;
    } else if (key != "VERSION" && key != "COUNT" && key != "WIDTH" && key != "HEIGHT" &&
               key != "VIEWPOINT") {
      throw InputError(path + ": not a PCD file (unexpected header line '" + line + "')");
    }
  }
  if (!have_data || !have_points || fields == 0)
    throw InputError(path + ": not a PCD file (header lacks FIELDS, POINTS or DATA)");
  if (sizes != fields || types != fields)
    throw InputError(path + ": PCD header declares " + std::to_string(fields) + " fields but " +
                     std::to_string(sizes) + " sizes and " + std::to_string(types) + " types");
  if (data != "ascii" && data != "binary" && data != "binary_compressed")
    throw InputError(path + ": unknown PCD DATA kind '" + data + "'");
  const std::streamoff body = in.tellg();
  if (data == "binary" && body >= 0 &&
      bytes.size() - static_cast<std::size_t>(body) < points * point_bytes)
    throw InputError(path + ": truncated PCD body (" + std::to_string(points) +
                     " points declared)");
}

void check_ply_header(const std::string& path, const std::vector<char>& bytes) {
  const std::string head(
      bytes.begin(),
      bytes.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(bytes.size(), 65536)));
  if (head.rfind("ply", 0) != 0 || head.find("end_header") == std::string::npos ||
      head.find("element vertex") == std::string::npos)
    throw InputError(path + ": not a PLY file with a vertex element");
}

PointCloud read_pcl_file(const std::string& path, const std::string& ext) {
  const std::vector<char> bytes = read_file_bytes(path, "point cloud");
  if (ext == ".pcd")
    check_pcd_header(path, bytes);
  else
    check_ply_header(path, bytes);
  pcl::PCLPointCloud2 blob;
  int status = -1;
  try {
    status = ext == ".pcd" ? pcl::io::loadPCDFile(path, blob) : pcl::io::loadPLYFile(path, blob);
  } catch (const std::exception& e) {
    throw InputError(path + ": cannot parse " + ext.substr(1) + " file (" + e.what() + ")");
  }
  if (status < 0) throw InputError(path + ": cannot parse " + ext.substr(1) + " file");
  const pcl::PCLPointField* fx = find_field(blob, "x");
  const pcl::PCLPointField* fy = find_field(blob, "y");
  const pcl::PCLPointField* fz = find_field(blob, "z");
  if (!fx || !fy || !fz) throw InputError(path + ": no x, y, z fields");
  const pcl::PCLPointField* fi = find_field(blob, "intensity");
  const pcl::PCLPointField* fl = find_field(blob, "label");

  const std::size_t n = static_cast<std::size_t>(blob.width) * blob.height;
  if (blob.data.size() < n * blob.point_step)
    throw InputError(path + ": truncated data (" + std::to_string(blob.data.size()) +
                     " bytes for " + std::to_string(n) + " points)");
  PointCloud cloud;
  cloud.points.resize(n);
  if (fi) cloud.intensities.resize(n);
  if (fl) cloud.labels.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* base = blob.data.data() + i * blob.point_step;
    cloud.points[i] =
        Eigen::Vector3f(static_cast<float>(read_scalar(base + fx->offset, fx->datatype)),
                        static_cast<float>(read_scalar(base + fy->offset, fy->datatype)),
                        static_cast<float>(read_scalar(base + fz->offset, fz->datatype)));
    if (fi) cloud.intensities[i] = static_cast<float>(read_scalar(base + fi->offset, fi->datatype));
    if (fl) {
      // Labels are unsigned ids; a float field holding integers is accepted too.
      const double v = read_scalar(base + fl->offset, fl->datatype);
      cloud.labels[i] = std::isfinite(v) && v >= 0 ? static_cast<std::uint32_t>(v) : 0u;
    }
  }
  return cloud;
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
    out.cloud = read_pcl_file(path, ext);
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
