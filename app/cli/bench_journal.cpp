#include "bench_journal.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "pagor/errors.hpp"
#include "pagor/eval/runner.hpp"
#include "pagor/io/file_input.hpp"
#include "pagor/io/json_input.hpp"

namespace pagor::cli {
namespace {

std::string dump(const nlohmann::json& j) {  // paths are bytes, not always UTF-8
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

Option jobs_option() {
  return {"jobs", 1, "N",
          "pairs run at once, each on a worker thread of its own (default 1; 'auto': the "
          "cores); the results and their order are those of 1"};
}

int jobs_from_args(const Args& args) {
  try {
    return parse_jobs(args.get("jobs", "1"), "--jobs");
  } catch (const InputError& e) {
    throw UsageError(e.what());
  }
}

BenchJournal::BenchJournal(const std::string& out, bool resume, std::string tool)
    : out_(out), partial_(sibling_path(out, ".partial")), tool_(std::move(tool)) {
  lock_ = std::make_unique<FileLock>(out_, "pagor bench --out");
  std::error_code ec;
  if (!resume)
    write_file_atomic(partial_, "");  // a fresh journal; `out` itself is untouched until finish()
  else if (!std::filesystem::exists(partial_, ec) && std::filesystem::exists(out_, ec))
    write_file_atomic(partial_, read_file(out_, "results file", kMaxResultsFileBytes));
  appender_ = std::make_unique<LineAppender>(partial_);  // cuts an incomplete last line

  std::istringstream lines(read_file(partial_, "results journal", kMaxResultsFileBytes));
  std::string line;
  int line_no = 0;
  while (std::getline(lines, line)) {
    ++line_no;
    if (line.empty()) continue;
    const std::string at = partial_ + ":" + std::to_string(line_no);
    nlohmann::json j;
    try {
      j = parse_json_limited(line, at);
    } catch (const ConfigError& e) {
      throw InputError(e.what());
    }
    const auto key = j.is_object() ? j.find("run_key") : j.end();
    if (!j.is_object() || !j.contains("pair") || key == j.end() || !key->is_string())
      throw InputError(at + ": not a result line of pagor bench (needs \"pair\" and \"run_key\")");
    const std::string k = key->get<std::string>();
    done_[k] = std::move(j);
  }
}

const nlohmann::json* BenchJournal::find(const std::string& key) const {
  const auto it = done_.find(key);
  return it == done_.end() ? nullptr : &it->second;
}

void BenchJournal::append(const std::string& line, const std::string& key) {
  appender_->append(line);
  done_[key] = nlohmann::json::parse(line);
}

void BenchJournal::finish(const std::vector<std::string>& keys) {
  std::string text;
  for (const std::string& k : keys)
    if (const nlohmann::json* j = find(k)) text += dump(*j) + "\n";
  appender_.reset();
  write_file_atomic(out_, text);
  std::remove(partial_.c_str());
  lock_.reset();
}

}  // namespace pagor::cli
