#include "bench_journal.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pagor/errors.hpp"
#include "io/json_input.hpp"

namespace pagor::cli {
namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

BenchJournal::BenchJournal(const std::string& out, bool resume, std::string run_key)
    : out_(out), partial_(out + ".partial"), run_key_(std::move(run_key)) {
  std::error_code ec;
  if (!resume)
    write_file_atomic(partial_, "");  // a fresh journal; `out` itself is untouched until finish()
  else if (!std::filesystem::exists(partial_, ec) && std::filesystem::exists(out_, ec))
    write_file_atomic(partial_, read_all(out_));         // continue from a copy; `out` stays intact
  appender_ = std::make_unique<LineAppender>(partial_);  // cuts an incomplete last line

  std::istringstream lines(read_all(partial_));
  std::string line;
  int line_no = 0;
  while (std::getline(lines, line)) {
    ++line_no;
    if (line.empty()) continue;
    const std::string at = partial_ + ":" + std::to_string(line_no);
    const nlohmann::json j = parse_json_limited(line, at);
    const auto pair = j.find("pair");
    const auto key = j.find("run_key");
    if (!j.is_object() || pair == j.end() || !pair->is_string() || key == j.end() ||
        !key->is_string())
      throw InputError(at + ": not a result line of pagor bench (needs \"pair\" and \"run_key\")");
    if (key->get<std::string>() == run_key_) done_[pair->get<std::string>()] = j;
  }
}

const nlohmann::json* BenchJournal::find(const std::string& pair) const {
  const auto it = done_.find(pair);
  return it == done_.end() ? nullptr : &it->second;
}

void BenchJournal::append(nlohmann::json line, const std::string& pair) {
  line["pair"] = pair;
  line["run_key"] = run_key_;
  appender_->append(line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  done_[pair] = std::move(line);
}

void BenchJournal::finish() {
  appender_.reset();
  if (std::rename(partial_.c_str(), out_.c_str()) != 0)
    throw InputError(out_ + ": cannot rename " + partial_ + " into place (" + std::strerror(errno) +
                     "); the results are in " + partial_);
}

}  // namespace pagor::cli
