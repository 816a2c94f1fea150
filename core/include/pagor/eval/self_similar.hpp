#pragma once
/// \file self_similar.hpp
/// Scenes that repeat themselves, generated from a seed with a known relative pose: where a
/// registration can be wrong by whole periods, or turned 180 degrees, and still look aligned.
/// - `corridor`: 6 m wide, walls 3 m high and a floor, a pillar every 3-8 m (one period per scene)
///   on both sides; the source sees the target's stretch moved 6-28 m along it.
/// - `facades`: a street of identical buildings (one width and gap per scene) on both sides, with a
///   street lamp in front of each; the source is moved 6-28 m along it.
/// - `sliding_street`: a street between two unbroken walls: it slides along itself at any shift.
/// - `symmetric_hall`: a 30 x 20 m hall with columns, the same turned 180 degrees about its centre;
///   both scans see all of it.
/// Each with or without three distinct objects (a car, a sign, a bench at irregular places, seen
/// by both scans) that fix the pose, labelled or as x y z only. Labels follow the
/// `semantickitti-train` scheme (synthetic.hpp): walls building 12, floor road 8, corridor pillars
/// trunk 15, street lamps and hall columns pole 17, car 0, sign traffic-sign 18, bench fence 13
/// (the scheme has no bench class).

#include <cstdint>
#include <string>
#include <vector>

#include "pagor/eval/synthetic.hpp"
#include "pagor/types.hpp"
#include "pagor/util/fields.hpp"

namespace pagor {

/// The numbering of the scenes' labels. Detection cannot be trusted with it here: a corridor whose
/// pillars (trunk) are half the points reads to it like a driving scan in the learning map.
inline const std::string kSelfSimilarLabelScheme = "semantickitti-train";

/// The kind of repetition.
enum class SelfSimilarKind { corridor, facades, sliding_street, symmetric_hall };
inline constexpr EnumEntry<SelfSimilarKind> kSelfSimilarKinds[] = {
    {SelfSimilarKind::corridor, "corridor", "a corridor with a pillar every few metres"},
    {SelfSimilarKind::facades, "facades", "a street of identical facades"},
    {SelfSimilarKind::sliding_street, "sliding-street", "a street that slides along itself"},
    {SelfSimilarKind::symmetric_hall, "symmetric-hall", "a hall that is the same turned 180 deg"},
};
static_assert(covers_every_value(kSelfSimilarKinds, SelfSimilarKind::symmetric_hall));
inline const auto& enum_entries(SelfSimilarKind) {
  return kSelfSimilarKinds;
}

/// Short name of a kind ("corridor", "facades", "sliding-street", "symmetric-hall").
const char* self_similar_kind_name(SelfSimilarKind kind);

/// Parameters of a self-similar scene.
struct SelfSimilarParams {
  SelfSimilarKind kind = SelfSimilarKind::corridor;
  std::uint64_t seed = 1;         ///< RNG seed; the same parameters give the same scene
  bool distinct_objects = false;  ///< a car, a sign and a bench that fix the pose
  bool labelled = true;           ///< semantickitti-train labels; false: x y z only
  double spacing = 0.15;          ///< sampling of objects [m]; walls every 2x, floors 4x
  double noise = 0.02;            ///< Gaussian noise on every coordinate [m]
};

/// A generated pair and what makes it ambiguous.
struct SelfSimilarScene {
  std::string name;           ///< kind, seed, objects and labels, e.g. "corridor-3+objects"
  PointCloud source;          ///< points in the source sensor frame
  PointCloud target;          ///< points in the target sensor frame
  Transform T_target_source;  ///< the truth: maps source points into the target frame
  /// repetition period along the scene's axis [m]: the pillar, building or column spacing; 0 for
  /// the sliding street (any shift) and the hall (no shift: a half turn)
  double period = 0.0;
  /// wrong poses that explain the scene as well as the truth where it repeats (without the
  /// distinct objects): the truth moved by one and two periods (the sliding street: by 6 and
  /// 12 m) both ways along the axis, and turned 180 degrees about a centre of symmetry
  std::vector<Transform> look_alikes;
  std::vector<SyntheticObject> objects;  ///< the distinct objects (empty without them)
};

/// Generates the scene. Deterministic for a given `params`.
SelfSimilarScene make_self_similar_scene(const SelfSimilarParams& params = {});

/// The set the bench and tests score: every kind, with and without distinct objects, labelled and
/// not, for seeds 1..`seeds` (16 scenes a seed).
std::vector<SelfSimilarParams> self_similar_set(int seeds);

}  // namespace pagor
