#include "runners/bench_worker.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <new>
#include <numeric>
#include <string>
#include <system_error>

#include "pagor/errors.hpp"
#include "runners/pair_queue.hpp"

namespace pagor::studio {
namespace {

constexpr int kPipelineThreads = 2;                    // graph and verification, for one job
constexpr std::size_t kDefaultBudget = 1024ull << 20;  // [bytes]

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The floor plan an indoor set registers against: the first plan target (empty: none).
std::string plan_path(const PairSet& set) {
  for (const PairEntry& e : set.pairs)
    if (e.source.kind == PairSource::Kind::files && is_floor_plan_path(e.source.target))
      return e.source.target;
  return {};
}

// A path a results file names: as written when it exists from here, else beside the file (a
// manifest's relative paths are relative to its directory, which the results usually share).
std::string beside(const std::string& path, const std::string& file) {
  const std::filesystem::path p(path);
  std::error_code ec;
  if (p.is_absolute() || std::filesystem::exists(p, ec)) return path;
  return (std::filesystem::path(file).parent_path() / p).string();
}

// Why a pair or a sweep stopped, in words; nothing the core throws ends the studio.
std::string reason(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
  if (dynamic_cast<const Error*>(&e)) return e.what();
  return std::string("internal error: ") + e.what();
}

}  // namespace

BenchWorker::BenchWorker() : config_(default_config()) {
  status_.budget_bytes = kDefaultBudget;
  thread_ = std::thread([this] { loop(); });
}

BenchWorker::~BenchWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    cancel_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void BenchWorker::open(PairSet set, const Config& config) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    origin_ = set.origin;
    rows_.assign(set.pairs.size(), BenchRow{});
    for (std::size_t i = 0; i < set.pairs.size(); ++i) {
      rows_[i].outcome.name = set.pairs[i].name;
      rows_[i].outcome.negative = set.pairs[i].negative;
    }
    pending_plan_ = plan_path(set);
    plan_.reset();
    ++plan_generation_;
    status_.set_generation = plan_generation_;
    pending_set_ = std::move(set);
    rerunnable_ = true;
    config_ = config;
    status_.total = static_cast<int>(rows_.size());
    status_.done = 0;
    status_.error.clear();
    ++status_.generation;
    cancel_ = true;
  }
  changed_.notify_all();
}

void BenchWorker::show_results(std::vector<PairOutcome> outcomes, const std::string& origin) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    origin_ = origin;
    rows_.clear();
    for (PairOutcome& o : outcomes) {
      BenchRow r;
      r.outcome = std::move(o);
      r.done = r.current = true;
      r.last_ms = r.outcome.total_ms;
      rows_.push_back(std::move(r));
    }
    pending_set_ = PairSet{};  // drops the caches
    pending_plan_.reset();
    plan_.reset();
    ++plan_generation_;
    status_.set_generation = plan_generation_;
    for (const BenchRow& r : rows_)  // results of an indoor set name the plan as their target
      if (is_floor_plan_path(r.outcome.target_name)) {
        pending_plan_ = beside(r.outcome.target_name, origin);
        break;
      }
    rerunnable_ = false;
    status_.total = status_.done = static_cast<int>(rows_.size());
    status_.error.clear();
    ++status_.generation;
    cancel_ = true;
  }
  changed_.notify_all();
}

void BenchWorker::start_pass_locked() {
  for (BenchRow& r : rows_) r.current = false;
  status_.done = 0;
  status_.error.clear();
  ++status_.generation;
  cancel_ = true;  // the pass in flight ends at its next pair; the worker starts the new one
}

void BenchWorker::set_config(const Config& config) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!rerunnable_) return;
    if (config_to_json(config, -1) == config_to_json(config_, -1)) return;
    config_ = config;
    start_pass_locked();
  }
  changed_.notify_all();
}

void BenchWorker::cancel() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (status_.finished != status_.generation) cancelled_generation_ = status_.generation;
    sweep_cancelled_ = status_.sweeping && !pending_sweep_;
    cancel_ = true;
    if (pending_sweep_) {  // queued behind the pass: never started
      pending_sweep_.reset();
      status_.sweeping = false;
      status_.sweep_error = "the sweep was cancelled before it started";
    }
  }
  changed_.notify_all();
}

void BenchWorker::rerun() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!rerunnable_) return;
    start_pass_locked();
  }
  changed_.notify_all();
}

void BenchWorker::set_budget(std::size_t bytes) {
  std::lock_guard<std::mutex> lock(mutex_);
  status_.budget_bytes = bytes;
}

void BenchWorker::set_jobs(int jobs) {
  std::lock_guard<std::mutex> lock(mutex_);
  jobs_ = std::clamp(jobs, 1, kMaxBenchJobs);
}

void BenchWorker::close() {
  show_results({}, "");
}

std::vector<BenchRow> BenchWorker::rows() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return rows_;
}

BenchStatus BenchWorker::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  BenchStatus s = status_;
  if (s.busy) s.pass_ms = ms_since(pass_start_);
  return s;
}

PairSet BenchWorker::set() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return rerunnable_ ? (pending_set_ ? *pending_set_ : set_) : PairSet{};
}

std::string BenchWorker::origin() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return origin_;
}

std::shared_ptr<const FloorPlan> BenchWorker::plan() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return plan_;
}

void BenchWorker::load_pending_plan() {
  std::string path;
  std::uint64_t generation = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!pending_plan_) return;
    path = std::move(*pending_plan_);
    pending_plan_.reset();
    generation = plan_generation_;
  }
  if (path.empty()) return;
  std::shared_ptr<const FloorPlan> plan;
  std::string error;
  try {
    plan = std::make_shared<const FloorPlan>(read_floor_plan(path));
  } catch (const std::bad_alloc&) {
    error = path + ": out of memory while reading the floor plan";
  } catch (const Error& e) {
    error = e.what();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (plan_generation_ != generation) return;  // a newer set or results file replaced it
  plan_ = std::move(plan);
  if (!error.empty()) status_.error = error;
}

bool BenchWorker::can_rerun() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return rerunnable_;
}

bool BenchWorker::wait_idle(double timeout_s) const {
  std::unique_lock<std::mutex> lock(mutex_);
  return changed_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                           [this] { return status_.finished == status_.generation; });
}

void BenchWorker::loop() {
  std::uint64_t handled = 0;
  for (;;) {
    Config config;
    std::uint64_t gen = 0;
    std::vector<std::size_t> order;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] {
        return stop_ || status_.generation != handled || pending_sweep_.has_value();
      });
      if (stop_) return;
      if (status_.generation == handled) {  // only a sweep to do
        lock.unlock();
        run_pending_sweep();
        continue;
      }
      gen = handled = status_.generation;
      config = config_;
      cancel_ = cancelled_generation_ == gen;  // cancelled before it began: stops at once
      status_.cancelled = false;
      prepare_runners();
      status_.busy = !set_.pairs.empty();
      status_.pass_ms = 0;
      pass_start_ = std::chrono::steady_clock::now();
      // Cached pairs first: they re-run only what the change invalidated, so the rates of most
      // of the set update at once. (Several jobs: each runner's kept pairs first, PairQueue.)
      order.resize(set_.pairs.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_partition(order.begin(), order.end(),
                            [&](std::size_t i) { return runners_.front()->cached(i); });
    }
    load_pending_plan();
    const bool complete = evaluate_all(order, config, gen);
    if (complete) {
      bool sweep = false;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        sweep = pending_sweep_.has_value() && status_.generation == gen;
        if (sweep) {
          status_.finished = gen;
          status_.busy = false;
          status_.pass_ms = ms_since(pass_start_);
        }
      }
      if (sweep) run_pending_sweep();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (complete && status_.generation == gen) {
      status_.finished = gen;
      status_.busy = false;
      status_.pass_ms = ms_since(pass_start_);
    } else if (!complete && status_.generation == gen && cancelled_generation_ == gen) {
      status_.busy = false;
      status_.cancelled = true;
      status_.pass_ms = ms_since(pass_start_);
      status_.error = "cancelled after " + std::to_string(status_.done) + " of " +
                      std::to_string(status_.total) + " pairs";
    }
    changed_.notify_all();
  }
}

void BenchWorker::sweep(std::vector<SweepSetting> settings, const Config& base) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!rerunnable_) return;
    sweep_base_ = base;
    status_.sweep_total = static_cast<int>(settings.size()) * status_.total;
    status_.sweep_done = 0;
    status_.sweep_error.clear();
    status_.sweeping = true;
    pending_sweep_ = std::move(settings);
  }
  changed_.notify_all();
}

std::shared_ptr<const SweepRecord> BenchWorker::sweep_result() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return sweep_result_;
}

void BenchWorker::run_pending_sweep() {
  std::vector<SweepSetting> settings;
  auto result = std::make_shared<SweepRecord>();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!pending_sweep_) return;  // cancelled between the pass and here
    settings = std::move(*pending_sweep_);
    pending_sweep_.reset();
    cancel_ = false;
    sweep_cancelled_ = false;
    status_.cancelled = false;
    result->base = sweep_base_;
    result->set = status_.set_generation;
    // The jobs changed since the pass: the sweep runs on as many runners. (A set opened meanwhile
    // is the next pass's to take.)
    if (!pending_set_) prepare_runners();
  }
  std::string error;
  try {
    result->result = run_sweep(
        runners_, settings,
        [this](int, int, const PairOutcome&) {
          std::lock_guard<std::mutex> lock(mutex_);
          ++status_.sweep_done;
        },
        &cancel_);
  } catch (const Cancelled&) {
    std::lock_guard<std::mutex> lock(mutex_);
    error = sweep_cancelled_
                ? "the sweep was cancelled after " + std::to_string(status_.sweep_done) + " of " +
                      std::to_string(status_.sweep_total) + " runs"
                : "the sweep was cancelled by a parameter change";
    // The pass before it was whole: `cancelled` (the pass's) stays as it was; the sweep's
    // cancel is said by sweep_error.
    result.reset();
  } catch (const std::exception& e) {
    error = reason(e);
    result.reset();
  }
  for (int job = 0; job < static_cast<int>(runners_.size()); ++job) note_cache(job);
  std::lock_guard<std::mutex> lock(mutex_);
  if (result) sweep_result_ = std::move(result);
  status_.sweep_error = error;
  status_.sweeping = pending_sweep_.has_value();
  changed_.notify_all();
}

void BenchWorker::prepare_runners() {
  const bool new_set = pending_set_.has_value();
  if (new_set) {
    set_ = std::move(*pending_set_);
    pending_set_.reset();
  }
  if (new_set || static_cast<int>(runners_.size()) != jobs_) {
    // One job uses the pipelines' parallel stages; several share the cores between them.
    runners_ = make_runners(set_, jobs_, std::max(1, kPipelineThreads / jobs_));
    cache_views_.assign(runners_.size(), CacheView{});
    runners_set_ = status_.set_generation;
    status_.cached = 0;
    status_.cache_bytes = 0;
    for (BenchRow& r : rows_) r.cached = false;
  }
  // The budget is the view's: each runner keeps its share, so N jobs hold no more than one.
  for (const auto& runner : runners_)
    runner->set_cache_budget(status_.budget_bytes / runners_.size());
  status_.jobs = static_cast<int>(runners_.size());
}

void BenchWorker::note_cache(int job) {
  const SetRunner& runner = *runners_[static_cast<std::size_t>(job)];
  CacheView view;
  view.cached.resize(runner.size());
  for (std::size_t k = 0; k < runner.size(); ++k) view.cached[k] = runner.cached(k);
  view.bytes = runner.cache_bytes();
  std::lock_guard<std::mutex> lock(mutex_);
  cache_views_[static_cast<std::size_t>(job)] = std::move(view);
  status_.cache_bytes = 0;
  for (const CacheView& v : cache_views_) status_.cache_bytes += v.bytes;
  status_.cached = 0;
  const bool rows_of_set = runners_set_ == status_.set_generation;  // not a newer set's rows
  for (std::size_t k = 0; k < runner.size(); ++k) {
    bool kept = false;
    for (const CacheView& v : cache_views_) kept = kept || (k < v.cached.size() && v.cached[k]);
    status_.cached += kept;
    if (rows_of_set && k < rows_.size()) rows_[k].cached = kept;
  }
}

bool BenchWorker::evaluate(int job, std::size_t i, const Config& config, std::uint64_t gen) {
  if (cancel_) return false;
  const auto t0 = std::chrono::steady_clock::now();
  PairOutcome o;
  std::string error;
  try {
    o = runners_[static_cast<std::size_t>(job)]->run(i, config, &cancel_);
  } catch (const Cancelled&) {
    return false;
  } catch (const std::exception& e) {  // a work budget exceeded, out of memory: the row says why
    const PairEntry& entry = set_.pairs[i];
    o = PairOutcome{};
    o.name = entry.name;
    o.negative = entry.negative;
    o.load_error = reason(e);
    error = entry.name + ": " + o.load_error;
  }
  const double ms = ms_since(t0);
  note_cache(job);
  std::lock_guard<std::mutex> lock(mutex_);
  if (status_.generation != gen) return false;
  BenchRow& row = rows_[i];
  row.outcome = std::move(o);
  row.done = row.current = true;
  row.last_ms = ms;
  ++status_.done;
  if (!error.empty()) status_.error = error;
  return true;
}

bool BenchWorker::evaluate_all(const std::vector<std::size_t>& order, const Config& config,
                               std::uint64_t gen) {
  const int jobs = static_cast<int>(runners_.size());
  if (jobs == 1) {
    for (std::size_t i : order)
      if (!evaluate(0, i, config, gen)) return false;
    return true;
  }
  std::vector<int> home(set_.pairs.size(), -1);  // the first runner keeping each pair
  for (std::size_t i = 0; i < home.size(); ++i)
    for (int w = jobs - 1; w >= 0; --w)
      if (runners_[static_cast<std::size_t>(w)]->cached(i)) home[i] = w;
  PairQueue queue(home, jobs);
  // A job that stops (cancelled, or the configuration moved on) stops the others between pairs;
  // cancel_ stops the pair each is running.
  std::atomic<bool> stopped{false};
  // What evaluate() does not catch (out of memory around a row) stops every job and is the
  // pass's error, never an exception leaving a thread.
  const auto stop = [&](const std::string& what) {
    stopped = true;
    std::lock_guard<std::mutex> lock(mutex_);
    status_.error = "the pass stopped: " + what;
    status_.busy = false;
  };
  const auto job = [&](int w) {
    try {
      while (!stopped) {
        const std::optional<std::size_t> i = queue.next(w);
        if (!i) return;
        if (!evaluate(w, *i, config, gen)) stopped = true;
      }
    } catch (const std::exception& e) {
      stop(e.what());
    } catch (...) {
      stop("unknown error");
    }
  };
  std::vector<std::thread> threads;
  const int n = std::min(jobs, static_cast<int>(home.size()));
  try {
    for (int w = 1; w < n; ++w) threads.emplace_back(job, w);
  } catch (const std::system_error&) {
    // No more threads: the jobs that started take the others' pairs (PairQueue).
  }
  job(0);  // this thread is job 0
  for (std::thread& t : threads) t.join();
  return !stopped;
}

}  // namespace pagor::studio
