#pragma once
/// \file pagor.hpp
/// What a user of registration needs, in one include:
///
///   register_clouds, register_correspondences   one call, one result (registration.hpp)
///   Registration, LevelSummary, to_json          the typed result and its JSON (report.hpp)
///   Pipeline                                     the stages with caching, for incremental re-runs
///   Config, default_config, preset_config        every stage's parameters (config.hpp gathers
///                                                the stages' Params structs of params.hpp)
///   load_cloud, KittiSequence, read_correspondence_file, read_floor_plan   reading inputs
///   PointCloud, Transform, Correspondence, Error and its kinds
///
/// The stages' own headers (front/, graph/, pose/, verify/, indoor/) can be included alone to run
/// a stage by itself. The evaluation harness and the generators (pair sets, the runner over many
/// pairs, sweeps, generated scenes) are a library of their own: pagor::eval, <pagor/eval/eval.hpp>.

#include "pagor/errors.hpp"
#include "pagor/types.hpp"

#include "pagor/config.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/registration.hpp"
#include "pagor/report.hpp"

#include "pagor/indoor/floor_plan.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/io/kitti.hpp"
