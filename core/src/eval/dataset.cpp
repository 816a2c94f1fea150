#include "pagor/eval/dataset.hpp"

#include "pagor/errors.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "pagor/indoor/floor_projection.hpp"
#include "pagor/io/kitti.hpp"

#include "util/parallel.hpp"

namespace pagor {

LoadedPair load_pair(const PairSource& src, const IndoorParams& indoor, int threads) {
  LoadedPair out;
  switch (src.kind) {
    case PairSource::Kind::files:
      if (src.source.empty() || src.target.empty())
        throw InputError("a file pair needs both a source and a target cloud");
      if (!is_floor_plan_path(src.target)) {
        parallel_pair(
            threads, [&] { out.source = load_cloud(src.source, src.source_labels); },
            [&] { out.target = load_cloud(src.target, src.target_labels); });
      } else {
        out.source = load_cloud(src.source, src.source_labels);
        out.plan = read_floor_plan(src.target);
        try {
          out.target.cloud = sample_floor_plan(*out.plan, indoor.plan_spacing);
        } catch (const InputError& e) {
          throw InputError(src.target + ": " + e.what());
        }
        try {
          FloorScan scan = prepare_floor_scan(out.source.cloud, indoor);
          scan.cloud.origin = out.source.cloud.origin;  // the projection keeps the scan's frame
          out.source.cloud = std::move(scan.cloud);
          out.scan_columns = std::move(scan.columns);
        } catch (const InputError& e) {
          throw InputError(src.source + ": " + e.what());
        }
      }
      out.source_name = src.source;
      out.target_name = src.target;
      break;
    case PairSource::Kind::kitti: {
      const KittiSequence seq(src.kitti_root, src.sequence);
      parallel_pair(
          threads, [&] { out.source = seq.load_frame(src.source_frame); },
          [&] { out.target = seq.load_frame(src.target_frame); });
      out.source_name = seq.scan_path(src.source_frame);
      out.target_name = seq.scan_path(src.target_frame);
      out.T_target_source_gt = seq.ground_truth(src.source_frame, src.target_frame);
      break;
    }
    case PairSource::Kind::synthetic: {
      SyntheticParams p;
      p.seed = src.synthetic_seed;
      SyntheticScene scene = make_synthetic_scene(p);
      out.source.cloud = std::move(scene.source);
      out.target.cloud = std::move(scene.target);
      out.source_name = "synthetic scene (seed " + std::to_string(p.seed) + "), source";
      out.target_name = "synthetic scene (seed " + std::to_string(p.seed) + "), target";
      out.T_target_source_gt = scene.T_target_source;
      break;
    }
  }
  // A ground-truth file replaces what the source knows (e.g. better poses for a KITTI pair).
  if (!src.ground_truth.empty()) out.T_target_source_gt = read_transform_file(src.ground_truth);
  // The pipeline works, and judges poses, in the clouds' own frames (near their points).
  if (out.T_target_source_gt)
    out.T_target_source_gt =
        to_cloud_frames(*out.T_target_source_gt, out.source.cloud.origin, out.target.cloud.origin);
  return out;
}

std::optional<LabelScheme> pair_label_scheme(const PairSource& src) {
  if (src.label_scheme.empty()) return std::nullopt;
  return builtin_label_scheme(src.label_scheme);
}

std::string describe(const PairSource& src) {
  switch (src.kind) {
    case PairSource::Kind::files:
      return src.source + " -> " + src.target;
    case PairSource::Kind::kitti:
      return "KITTI " + src.sequence + ": " + std::to_string(src.source_frame) + " -> " +
             std::to_string(src.target_frame);
    case PairSource::Kind::synthetic:
      return "synthetic scene (seed " + std::to_string(src.synthetic_seed) + ")";
  }
  return {};
}

}  // namespace pagor
