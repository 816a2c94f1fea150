#pragma once
/// \file work_budget.hpp
/// Bounds on the work and memory a configuration may ask of a stage, derived from the size of the
/// input. Legal but absurd parameters (a 10^6 m cluster tolerance, no cap on correspondences with
/// every voxel a landmark) end in a ConfigError naming the key instead of running for minutes or
/// exhausting memory.

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

namespace pagor {

/// Neighbour visits a radius-search stage (Euclidean clustering, normals, FPFH) may make on one
/// class: about 10 s of work.
constexpr double kMaxNeighbourVisits = 1e8;

/// Candidate correspondences all-to-all matching may create for one pair (~72 bytes each).
constexpr std::size_t kMaxCandidateCorrespondences = 4000000;

/// Correspondences the consistency graph may take (it tests every pair of them).
constexpr std::size_t kMaxGraphCorrespondences = 20000;

/// Estimates the neighbour visits of a radius search of `radius` [m] from every point (sampling
/// up to 64 points, exactly counted) and throws ConfigError naming `key` when the estimate exceeds
/// kMaxNeighbourVisits. `what` describes the points for the message (e.g. "class 'car'").
void check_radius_work(const std::vector<Eigen::Vector3f>& points, double radius,
                       const std::string& key, const std::string& what);

}  // namespace pagor
