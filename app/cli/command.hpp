#pragma once
/// \file command.hpp
/// The subcommands of `pagor` and the helpers they share.

#include <functional>
#include <string>
#include <vector>

#include "common/args.hpp"
#include "common/config_args.hpp"
#include "common/pair_args.hpp"
#include "pagor/config.hpp"
#include "pagor/eval/dataset.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/registration.hpp"

namespace pagor::cli {

/// A subcommand: its name, a one-line summary, its options and its body.
struct Command {
  const char* name;
  const char* summary;
  std::vector<Option> (*options)();
  int (*run)(const Args& args);
};

/// All subcommands, in the order `pagor --help` lists them.
const std::vector<Command>& commands();

// Subcommand bodies and option lists.
std::vector<Option> landmarks_options();
int run_landmarks(const Args& args);
std::vector<Option> config_options();
int run_config(const Args& args);
std::vector<Option> register_options();
int run_register(const Args& args);
/// `register --correspondences FILE` (cmd_register_correspondences.cpp).
int run_register_correspondences(const Args& args, Config config);
std::vector<Option> bench_options();
int run_bench(const Args& args);
std::vector<Option> sweep_options();
int run_sweep_command(const Args& args);
std::vector<Option> indoor_options();
int run_indoor(const Args& args);
std::vector<Option> self_similar_options();
int run_self_similar(const Args& args);
/// `bench --compare-thresholds` (bench_compare.cpp).
int run_threshold_comparison(const Args& args, const Config& config, const PairSet& set);
std::vector<Option> demo_options();
int run_demo(const Args& args);

// ---- shared helpers ------------------------------------------------------------------------

/// `--threads N`: threads for the stages that parallelise inside a pair.
Option threads_option();

/// Options selecting one cloud: `--source/--source-labels`, `--kitti-root/--sequence/--frame`,
/// or `--synthetic`.
std::vector<Option> single_cloud_options();

/// Loads the cloud the single-cloud options select; `name` receives a description.
LoadedCloud load_single_cloud(const Args& args, std::string& name);

/// Runs `stage`; a ConfigError it throws (a work budget exceeded by the parameters) is re-thrown
/// with the configuration's file in front (or "built-in defaults"), so the message names both
/// the file and the key.
void with_config_origin(const Args& args, const std::function<void()>& stage);

/// Prints a registration as `pagor register` shows it (print_registration.cpp).
void print_registration(const Registration& registration);
/// The registration of a pipeline that has run: printed, and written to `--json` when given.
void report_registration(const Args& args, const Pipeline& pipeline,
                         const RegistrationContext& context);

/// Each acceptance test with its value and threshold, in one line: "overlap 0.45 >= 0.24, ...".
std::string acceptance_tests_text(const Registration& registration);

/// Prints a warning line on stderr.
void warn(const std::string& message);
/// Prints warnings: each one that may change what the result means on its own line; the benign
/// ones (a class with a few points but no landmark) in one summary line unless `verbose`.
void warn_all(const std::vector<std::string>& warnings, bool verbose);

/// How a cloud's labels were read, in words: "semantickitti-learning (detected; 3.2 nats a point
/// over semantickitti-train)", "none (no labels)", "semantickitti (configured; does not fit)".
std::string labels_text(const LabelReading& reading);

/// Writes text to a file, throwing InputError naming it on failure.
void write_text_file(const std::string& path, const std::string& text);

/// Default location of the shared KITTI data relative to the working directory, if present.
std::string find_shared_kitti();

}  // namespace pagor::cli
