#pragma once
/// \file eval.hpp
/// The evaluation harness and the generators (library pagor::eval), in one include:
///
///   dataset               a pair's data: files, a KITTI pair, a generated scene, a car park scan
///   pair_set              pairs manifests and KITTI pairs files
///   runner                the one runner over many pairs (SetRunner, run_set)
///   benchmark             what a pair gave (PairOutcome) and the rates of a set (summarize)
///   sweep                 settings over a set
///   threshold_comparison  the pyramid against each threshold alone
///   synthetic             the generated outdoor scene
///   indoor_synthetic      the generated car park and its scans
///   self_similar          generated self-similar scenes (corridors, repeated facades, halls)
///   association_problem   generated correspondence problems with known inliers
///   file_lock             one writer per results file

#include "pagor/eval/association_problem.hpp"
#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/dataset.hpp"
#include "pagor/eval/file_lock.hpp"
#include "pagor/eval/indoor_synthetic.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/eval/runner.hpp"
#include "pagor/eval/self_similar.hpp"
#include "pagor/eval/sweep.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/eval/threshold_comparison.hpp"
