#pragma once
/// \file pagor.hpp
/// The whole public API of the core in one include, in the order of the paper's pipeline:
///
///   io      clouds, KITTI sequences, correspondence files, atomic writes
///   front   label schemes, semantic landmarks, correspondences
///   graph   TRIM, the pyramid of consistency graphs, the densest-clique solvers
///   pose    GNC with a truncated least-squares cost
///   verify  verification ("distrust and verify"), refinement, acceptance, evaluation, diagnosis
///   indoor  floor plans, the scan's floor projection, columns, the generated car park
///   sets    a pair's data, pairs manifests, the runner over many pairs, sweeps, generated scenes
///   util    parameter tables, kd-tree, voxel grid, work budgets
///
/// `Pipeline` (pipeline.hpp) runs all stages with caching on a `Config` (config.hpp, which
/// gathers each stage's parameters); `registration_report_json` (report.hpp) is the result as
/// JSON. Each header can also be included alone.

#include "pagor/errors.hpp"
#include "pagor/types.hpp"

#include "pagor/io/atomic_file.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/io/kitti.hpp"

#include "pagor/front/correspondences.hpp"
#include "pagor/front/label_scheme.hpp"
#include "pagor/front/landmarks.hpp"

#include "pagor/graph/densest_clique.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/graph/trim.hpp"

#include "pagor/pose/gnc.hpp"
#include "pagor/pose/gravity.hpp"

#include "pagor/verify/acceptance.hpp"
#include "pagor/verify/diagnosis.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/level_selection.hpp"
#include "pagor/verify/refinement.hpp"
#include "pagor/verify/verification.hpp"

#include "pagor/indoor/column_detector.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "pagor/indoor/floor_projection.hpp"
#include "pagor/indoor/indoor_synthetic.hpp"

#include "pagor/sets/association_problem.hpp"
#include "pagor/sets/benchmark.hpp"
#include "pagor/sets/dataset.hpp"
#include "pagor/sets/pair_set.hpp"
#include "pagor/sets/runner.hpp"
#include "pagor/sets/sweep.hpp"
#include "pagor/sets/synthetic.hpp"
#include "pagor/sets/threshold_comparison.hpp"

#include "pagor/util/fields.hpp"
#include "pagor/util/kdtree.hpp"
#include "pagor/util/voxel_grid.hpp"
#include "pagor/util/work_budget.hpp"

#include "pagor/config.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/report.hpp"
