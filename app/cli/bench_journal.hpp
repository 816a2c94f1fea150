#pragma once
/// \file bench_journal.hpp
/// Where `pagor bench --out FILE` keeps its results so that nothing is lost: one complete JSON
/// line per pair is appended (and flushed) to FILE.partial as each pair finishes; a finished run
/// renames it over FILE. A killed run leaves FILE as it was and FILE.partial with every pair
/// finished so far; `--resume` continues FILE.partial (or, when there is none, a copy of FILE),
/// skipping the pairs it already holds for the same configuration.

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "pagor/io/atomic_file.hpp"

namespace pagor::cli {

class BenchJournal {
 public:
  /// Opens the journal of `out`. `run_key` identifies the configuration (lines with another key
  /// are kept but not skipped). Throws InputError naming the file and line of a malformed line.
  BenchJournal(const std::string& out, bool resume, std::string run_key);

  /// The line already recorded for the pair named `pair` under this run key, or nullptr.
  const nlohmann::json* find(const std::string& pair) const;
  /// Number of pairs already recorded under this run key.
  std::size_t recorded() const { return done_.size(); }

  /// Appends one result line, adding "pair" (the pair's name in its set) and "run_key".
  /// Throws InputError.
  void append(nlohmann::json line, const std::string& pair);

  /// Renames the journal into place as `out`. Throws InputError.
  void finish();

 private:
  std::string out_, partial_, run_key_;
  std::map<std::string, nlohmann::json> done_;
  std::unique_ptr<LineAppender> appender_;
};

}  // namespace pagor::cli
