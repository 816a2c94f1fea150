// Georeferenced clouds: a semreg-dev pair and a known negative moved 300 km out (and turned
// about z), written as double PCDs at test time, register as near the origin: the same success,
// verdict and diagnosis, errors judged near the data, and the JSON's poses in the files' frame.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/io/clouds.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

// `cloud` moved by M, as a binary PCD with double coordinates and its labels.
void write_moved(const std::string& path, const PointCloud& cloud, const Transform& M) {
  std::ofstream out(path, std::ios::binary);
  out << "VERSION .7\nFIELDS x y z label\nSIZE 8 8 8 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH "
      << cloud.size() << "\nHEIGHT 1\nPOINTS " << cloud.size() << "\nDATA binary\n";
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p =
        M.block<3, 3>(0, 0) * cloud.points[i].cast<double>() + M.block<3, 1>(0, 3);
    out.write(reinterpret_cast<const char*>(p.data()), 24);
    out.write(reinterpret_cast<const char*>(&cloud.labels[i]), 4);
  }
}

void write_transform(const std::string& path, const Transform& T) {
  std::ofstream(path) << transform_file_text(T);
}

PairEntry file_pair(const std::string& name, const std::string& source, const std::string& target,
                    const std::string& gt, bool negative) {
  PairEntry e;
  e.name = name;
  e.negative = negative;
  e.source.kind = PairSource::Kind::files;
  e.source.source = source;
  e.source.target = target;
  e.source.ground_truth = gt;
  return e;
}

}  // namespace

TEST_CASE("a pair 300 km from the origin registers as it does near the origin") {
  const std::string data = PAGOR_SEMREG_DIR;
  Transform M = Transform::Identity();  // a national grid: 300 km east, 4500 km north, turned
  M.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).matrix();
  M.block<3, 1>(0, 3) = Eigen::Vector3d(300000.0, 4500000.0, 52.0);
  test::TempDir dir;
  const Transform T = read_transform_file(data + "/03/T_target_source.txt");
  write_moved(dir.file("s03.pcd"), load_cloud(data + "/03/source.pcd").cloud, M);
  write_moved(dir.file("t03.pcd"), load_cloud(data + "/03/target.pcd").cloud, M);
  write_moved(dir.file("t08.pcd"), load_cloud(data + "/08/target.pcd").cloud, M);
  const Transform T_far = M * T * M.inverse();
  write_transform(dir.file("gt03.txt"), T_far);

  Config config = default_config();
  config.label_scheme = builtin_label_scheme("semantickitti-learning");
  const std::vector<std::pair<PairEntry, PairEntry>> pairs = {
      {file_pair("03", data + "/03/source.pcd", data + "/03/target.pcd",
                 data + "/03/T_target_source.txt", false),
       file_pair("03 far", dir.file("s03.pcd"), dir.file("t03.pcd"), dir.file("gt03.txt"), false)},
      {file_pair("03-vs-08", data + "/03/source.pcd", data + "/08/target.pcd", "", true),
       file_pair("03-vs-08 far", dir.file("s03.pcd"), dir.file("t08.pcd"), "", true)}};
  for (const auto& [near_entry, far_entry] : pairs) {
    Pipeline near_pipeline(config), far_pipeline(config);
    const PairOutcome near = run_pair(near_pipeline, near_entry);
    const PairOutcome far = run_pair(far_pipeline, far_entry);
    INFO(far_entry.name);
    REQUIRE(near.loaded);
    REQUIRE(far.loaded);
    CHECK_FALSE(far_pipeline.source().origin.isZero());  // kept in a frame near its points
    CHECK(far.accepted == near.accepted);
    CHECK(far.success == near.success);
    CHECK(far.diagnosis == near.diagnosis);
    if (!near.error) continue;
    REQUIRE(far.error);
    // Judged near the data, the errors are those of the pair near the origin (a 4,456 m error
    // was reported before), up to voxel boundaries falling elsewhere and the point the error is
    // judged at (the source's frame origin instead of its sensor).
    CHECK(far.error->translation == Approx(near.error->translation).margin(0.3));
    CHECK(far.error->rotation_deg == Approx(near.error->rotation_deg).margin(0.2));
    // The result is in the files' frame: the near result moved by M, and the truth as written.
    REQUIRE(far.T_target_source);
    const Transform want = M * *near.T_target_source * M.inverse();
    CHECK((far.T_target_source->block<3, 3>(0, 0) - want.block<3, 3>(0, 0)).norm() < 0.01);
    const Eigen::Vector3d c = M.block<3, 1>(0, 3);  // near the data: where the poses must agree
    const auto at = [&](const Transform& X) {
      return Eigen::Vector3d(X.block<3, 3>(0, 0) * c + X.block<3, 1>(0, 3));
    };
    CHECK((at(*far.T_target_source) - at(want)).norm() < 0.2);
    const auto json = nlohmann::json::parse(far.report_json);
    CHECK(json["ground_truth"]["T_target_source"][1][3].get<double>() ==
          Approx(T_far(1, 3)).margin(1e-6));
  }
}
