#pragma once
// Variants of a cloud's labels derived in code (never stored as files): the same classes in
// another SemanticKITTI numbering.

#include <cstdint>
#include <random>
#include <vector>

#include "pagor/types.hpp"

namespace pagor::test {

/// The raw SemanticKITTI id of each learning-map id 0..19 (0 unlabeled, 1 car, ..., 19
/// traffic-sign): car 10, bicycle 11, motorcycle 15, truck 18, other-vehicle 20, person 30,
/// bicyclist 31, motorcyclist 32, road 40, parking 44, sidewalk 48, other-ground 49, building 50,
/// fence 51, vegetation 70, trunk 71, terrain 72, pole 80, traffic-sign 81.
inline std::uint32_t raw_id_of_learning(std::uint32_t learning) {
  static const std::uint32_t kRaw[20] = {0,  10, 11, 15, 18, 20, 30, 31, 32, 40,
                                         44, 48, 49, 50, 51, 70, 71, 72, 80, 81};
  return learning < 20 ? kRaw[learning] : 0;
}

/// Learning-map labels rewritten as raw SemanticKITTI labels, each with a random instance id in
/// the upper 16 bits (fixed seed), as a raw `.label` file carries them.
inline PointCloud learning_to_raw(PointCloud cloud, unsigned seed = 5) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::uint32_t> instance(0, 0xFFFF);
  for (auto& l : cloud.labels) l = raw_id_of_learning(semantic_id(l)) | (instance(rng) << 16);
  return cloud;
}

/// Learning-map labels rewritten in the 0-based training numbering (unlabeled: 255).
inline PointCloud learning_to_train(PointCloud cloud) {
  for (auto& l : cloud.labels) l = semantic_id(l) == 0 ? 255u : semantic_id(l) - 1;
  return cloud;
}

/// The cloud without its labels (x y z only).
inline PointCloud without_labels(PointCloud cloud) {
  cloud.labels.clear();
  return cloud;
}

}  // namespace pagor::test
