#pragma once
/// \file bench_journal.hpp
/// Where `pagor bench --out FILE` keeps its results so that nothing is lost or reused wrongly.
/// Each result line is keyed by what determines it (`run_key`: the tool, the configuration and
/// the pair's own fingerprint, pair_set.hpp: its name and the content of its files). As each pair
/// finishes, its line is appended (and flushed) to FILE.partial; a finished run writes FILE
/// atomically with the lines of this run's pairs, in set order. A killed run leaves FILE as it was
/// and FILE.partial with every pair finished so far; `--resume` continues FILE.partial (or, when
/// there is none, FILE), taking a line only for a pair whose key matches. One writer at a time:
/// FILE is locked (file_lock.hpp) while the journal is open.

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/args.hpp"
#include "pagor/eval/file_lock.hpp"
#include "pagor/io/atomic_file.hpp"

namespace pagor::cli {

/// `--jobs N` of bench and sweep: pairs run at once, each on a worker thread of its own.
Option jobs_option();
/// Its value (1 when absent; "auto": the cores). Throws UsageError naming --jobs.
int jobs_from_args(const Args& args);

class BenchJournal {
 public:
  /// Opens (and locks) the journal of `out`; `tool` names the tool and its build (written to
  /// every line as `tool_version`). Throws InputError naming the file (and line of a malformed
  /// line), or when another process writes to `out`.
  BenchJournal(const std::string& out, bool resume, std::string tool);

  /// The line recorded under `key`, or nullptr.
  const nlohmann::json* find(const std::string& key) const;
  /// Number of lines recorded.
  std::size_t recorded() const { return done_.size(); }
  /// Where the journal is kept (FILE.partial).
  const std::string& partial() const { return partial_; }

  /// The tool and its build, as written to every line.
  const std::string& tool() const { return tool_; }

  /// Appends one result line (bench_result_line, runner.hpp: its "run_key" is `key`) and flushes
  /// it. Pairs may come in any order (those run in parallel come as they finish): FILE.partial
  /// holds each finished pair once, and finish() writes them in set order. Throws InputError.
  void append(const std::string& line, const std::string& key);

  /// Writes `out` atomically with the lines recorded under `keys`, in that order (a key without a
  /// line, a pair that failed, is left out), then removes the journal. Throws InputError.
  void finish(const std::vector<std::string>& keys);

 private:
  std::string out_, partial_, tool_;
  std::unique_ptr<FileLock> lock_;
  std::map<std::string, nlohmann::json> done_;
  std::unique_ptr<LineAppender> appender_;
};

}  // namespace pagor::cli
