#include "pagor/eval/runner.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <mutex>
#include <new>
#include <nlohmann/json.hpp>
#include <numeric>
#include <thread>

#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/file_input.hpp"

namespace pagor {
namespace {

constexpr std::size_t kTreeBytesPerPoint = 32;  // kd-tree node share, estimated

std::size_t cloud_bytes(const PointCloud& c) {
  return c.points.capacity() * sizeof(Eigen::Vector3f) + c.intensities.capacity() * sizeof(float) +
         c.labels.capacity() * sizeof(std::uint32_t);
}

// The outcome of a pair that failed, and why.
PairOutcome failed(const PairEntry& entry, std::string why) {
  PairOutcome o;
  o.name = entry.name;
  o.negative = entry.negative;
  o.load_error = std::move(why);
  return o;
}

// Lends `lent` workers to a pipeline for as long as it lives (Pipeline::lend_threads): a kept
// pipeline must not point to the count of a run that has ended.
class Lending {
 public:
  Lending(Pipeline& p, const std::atomic<int>* lent) : p_(p) { p_.lend_threads(lent); }
  ~Lending() { p_.lend_threads(nullptr); }
  Lending(const Lending&) = delete;
  Lending& operator=(const Lending&) = delete;

 private:
  Pipeline& p_;
};

}  // namespace

// A pair's kept pipeline, with the names its files were loaded under.
struct SetRunner::Slot {
  std::unique_ptr<Pipeline> pipeline;
  std::string source_name, target_name;
  std::size_t bytes = 0;
  std::uint64_t since = 0;  ///< when it was first kept (0: not kept)
};

SetRunner::SetRunner(PairSet set, int threads) : set_(std::move(set)), threads_(threads) {
  slots_.resize(set_.pairs.size());
  for (auto& s : slots_) s = std::make_unique<Slot>();
}

SetRunner::~SetRunner() = default;

std::size_t SetRunner::estimate_bytes(const Pipeline& p) {
  std::size_t bytes = cloud_bytes(p.source()) + cloud_bytes(p.target());
  if (const Verifier* v = p.verifier())
    bytes += (v->source_points().size() + v->target_points().size()) * sizeof(Eigen::Vector3f) +
             v->target_points().size() * kTreeBytesPerPoint;
  bytes += p.correspondences().items.size() * sizeof(Correspondence);
  const PyramidGraph& g = p.graph();
  bytes += g.neighbors.size() * (sizeof(int) + sizeof(std::uint8_t) + sizeof(float)) +
           g.offsets.size() * sizeof(std::int64_t);
  for (const LandmarkSet* l : {&p.source_landmarks(), &p.target_landmarks()})
    bytes += l->landmarks.size() * 256;  // centroid, extent, descriptor share
  return bytes;
}

PairOutcome SetRunner::run(std::size_t i, const Config& config, const std::atomic<bool>* cancel,
                           const std::atomic<int>* lent) {
  if (cancel && cancel->load()) throw Cancelled();
  const PairEntry& entry = set_.pairs.at(i);
  Slot& slot = *slots_[i];
  std::array<int, kStageCount> before{};
  PairOutcome o;
  if (slot.pipeline) {
    for (int s = 0; s < kStageCount; ++s) before[s] = slot.pipeline->runs(static_cast<Stage>(s));
    slot.pipeline->set_config(config);
    try {  // the pair's own failure fails the pair, as in run_pair
      const Lending lending(*slot.pipeline, lent);
      slot.pipeline->run(ProgressFn{}, cancel);
    } catch (const InputError& e) {
      o = failed(entry, describe(entry.source) + ": " + e.what());
    } catch (const std::bad_alloc&) {
      o = failed(entry, describe(entry.source) + ": out of memory while running the pair");
    }
    if (!o.load_error.empty()) {
      slot.pipeline.reset();
      slot.since = 0;
      if (last_ && *last_ == i) last_.reset();
      return o;
    }
    o = pair_outcome(*slot.pipeline, entry, slot.source_name, slot.target_name);
  } else {
    auto pipeline = std::make_unique<Pipeline>(config, threads_);
    {
      const Lending lending(*pipeline, lent);
      o = run_pair(*pipeline, entry, cancel);
    }
    if (!o.loaded) return o;
    slot.pipeline = std::move(pipeline);
    slot.source_name = o.source_name;
    slot.target_name = o.target_name;
  }
  for (int s = 0; s < kStageCount; ++s) {
    const int ran = slot.pipeline->runs(static_cast<Stage>(s)) - before[s];
    o.ran[static_cast<std::size_t>(s)] = ran > 0;
    stage_runs_[static_cast<std::size_t>(s)] += ran;
  }
  slot.bytes = estimate_bytes(*slot.pipeline);
  if (slot.since == 0) slot.since = ++clock_;
  last_ = i;
  enforce_budget();
  return o;
}

// Keeps the pipelines kept longest first while they fit the budget (a stable cached set: a newcomer
// stays only when it fits), and always the last pair run.
void SetRunner::enforce_budget() {
  std::vector<Slot*> kept;
  for (std::size_t k = 0; k < slots_.size(); ++k)
    if (slots_[k]->pipeline && !(last_ && *last_ == k)) kept.push_back(slots_[k].get());
  std::sort(kept.begin(), kept.end(),
            [](const Slot* a, const Slot* b) { return a->since < b->since; });
  std::size_t total = 0;
  for (Slot* s : kept) {
    if (total + s->bytes <= budget_) {
      total += s->bytes;
    } else {
      s->pipeline.reset();
      s->since = 0;
    }
  }
}

void SetRunner::set_cache_budget(std::size_t bytes) {
  budget_ = bytes;
  enforce_budget();
}

bool SetRunner::cached(std::size_t i) const {
  return i < slots_.size() && slots_[i]->pipeline != nullptr;
}

int SetRunner::cached_count() const {
  int n = 0;
  for (const auto& s : slots_) n += s->pipeline != nullptr;
  return n;
}

std::size_t SetRunner::cache_bytes() const {
  std::size_t n = 0;
  for (const auto& s : slots_)
    if (s->pipeline) n += s->bytes;
  return n;
}

void SetRunner::clear_cache() {
  for (auto& s : slots_) {
    s->pipeline.reset();
    s->since = 0;
  }
  last_.reset();
}

namespace {

std::vector<std::size_t> run_order(const RunSetHooks& hooks, std::size_t n) {
  std::vector<std::size_t> order = hooks.order;
  if (order.empty()) {
    order.resize(n);
    std::iota(order.begin(), order.end(), 0);
  }
  return order;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::string progress_text(const SetProgress& p) {
  char rate[32] = "n/a", left[32] = "n/a";
  if (const auto r = p.rate()) std::snprintf(rate, sizeof(rate), "%.2f", *r);
  if (const auto s = p.seconds_left()) {
    const long t = static_cast<long>(*s + 0.5);
    if (t >= 3600)
      std::snprintf(left, sizeof(left), "%ld h %02ld min", t / 3600, t / 60 % 60);
    else if (t >= 60)
      std::snprintf(left, sizeof(left), "%ld min %02ld s", t / 60, t % 60);
    else
      std::snprintf(left, sizeof(left), "%ld s", t);
  }
  char text[128];
  std::snprintf(text, sizeof(text), "%zu/%zu pairs, %s pairs/s, %s left", p.done, p.total, rate,
                left);
  return text;
}

std::vector<PairOutcome> run_set(SetRunner& runner, const Config& config,
                                 const RunSetHooks& hooks) {
  std::vector<PairOutcome> out(runner.size());
  const std::vector<std::size_t> order = run_order(hooks, runner.size());
  const auto t0 = std::chrono::steady_clock::now();
  SetProgress progress{0, runner.size(), 0, order.size(), 0.0};
  for (std::size_t i : order) {
    std::optional<PairOutcome> reused = hooks.reuse ? hooks.reuse(i) : std::nullopt;
    if (reused) {
      out[i] = std::move(*reused);
      --progress.to_run;
    } else {
      if (hooks.prepare) hooks.prepare(i);
      out[i] = runner.run(i, config, hooks.cancel);
      ++progress.ran;
      if (hooks.finished) hooks.finished(i, out[i]);
    }
    if (hooks.done) hooks.done(i, out[i]);
    ++progress.done;
    progress.elapsed_s = seconds_since(t0);
    if (hooks.progress) hooks.progress(progress);
  }
  return out;
}

std::vector<std::unique_ptr<SetRunner>> make_runners(const PairSet& set, int jobs, int threads) {
  std::vector<std::unique_ptr<SetRunner>> runners;
  for (int k = 0; k < std::max(jobs, 1); ++k)
    runners.push_back(std::make_unique<SetRunner>(set, threads));
  return runners;
}

void run_parallel(int jobs, const std::vector<std::size_t>& order,
                  const std::function<void(int, std::size_t, const std::atomic<int>*,
                                           const std::atomic<bool>*)>& work,
                  const std::function<void(std::size_t)>& finished,
                  const std::atomic<bool>* cancel) {
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<std::size_t> ready;  // finished, not yet handed to `finished`
  std::size_t next = 0;           // the next position of `order` to take
  int running = 0;
  std::exception_ptr error;
  std::atomic<bool> stop{false};
  const int n = std::max(1, std::min<int>(jobs, static_cast<int>(order.size())));
  // The workers that found nothing left lend themselves to the calls still running, shared
  // evenly (under the lock).
  std::vector<std::atomic<int>> lent(static_cast<std::size_t>(n));
  for (auto& l : lent) l.store(0);
  std::vector<char> busy(static_cast<std::size_t>(n), 0);
  int idle = 0, busy_count = 0;
  const auto share_idle = [&] {
    for (std::size_t b = 0; b < busy.size(); ++b)
      lent[b].store(busy[b] ? idle / std::max(1, busy_count) : 0);
  };
  const auto worker = [&](int w) {
    const auto me = static_cast<std::size_t>(w);
    for (;;) {
      std::size_t i;
      {
        const std::lock_guard<std::mutex> lock(mutex);
        if (stop) break;
        if (next == order.size()) {
          ++idle;
          share_idle();
          break;
        }
        i = order[next++];
        busy[me] = 1;
        ++busy_count;
        share_idle();
      }
      try {
        work(w, i, &lent[me], &stop);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        stop = true;
        busy[me] = 0;
        --busy_count;
        break;
      }
      const std::lock_guard<std::mutex> lock(mutex);
      busy[me] = 0;
      --busy_count;
      ready.push_back(i);
      changed.notify_all();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    --running;
    changed.notify_all();
  };
  std::vector<std::thread> threads;
  running = n;
  for (int w = 0; w < n; ++w) threads.emplace_back(worker, w);
  std::exception_ptr hook_error;
  {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      changed.wait_for(lock, std::chrono::milliseconds(50),
                       [&] { return !ready.empty() || running == 0; });
      if (cancel && cancel->load()) stop = true;
      while (!ready.empty()) {
        const std::size_t i = ready.front();
        ready.pop_front();
        if (hook_error) continue;
        lock.unlock();  // the workers go on while the caller writes
        try {
          finished(i);
        } catch (...) {
          hook_error = std::current_exception();
          stop = true;
        }
        lock.lock();
      }
      if (running == 0 && ready.empty()) break;
    }
  }
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  if (hook_error) std::rethrow_exception(hook_error);
  // Cancelled only when work was left undone: a cancel after the last pair ended changes nothing
  // (as with one job, which checks between pairs).
  if (cancel && cancel->load() && next < order.size()) throw Cancelled();
}

std::vector<PairOutcome> run_set(std::vector<std::unique_ptr<SetRunner>>& runners,
                                 const Config& config, const RunSetHooks& hooks) {
  if (runners.size() == 1) return run_set(*runners.front(), config, hooks);
  const std::size_t n = runners.front()->size();
  std::vector<PairOutcome> out(n);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<std::size_t> order = run_order(hooks, n);
  std::vector<bool> has(n, false);
  std::vector<std::size_t> to_run;
  for (std::size_t i : order) {
    std::optional<PairOutcome> reused = hooks.reuse ? hooks.reuse(i) : std::nullopt;
    if (reused) {
      out[i] = std::move(*reused);
      has[i] = true;
    } else {
      to_run.push_back(i);
    }
  }
  SetProgress progress{0, n, 0, to_run.size(), 0.0};
  std::size_t shown = 0;  // positions of `order` whose outcome went to `done`
  const auto flush = [&] {
    for (; shown < order.size() && has[order[shown]]; ++shown) {
      if (hooks.done) hooks.done(order[shown], out[order[shown]]);
      ++progress.done;
      progress.elapsed_s = seconds_since(t0);
      if (hooks.progress) hooks.progress(progress);
    }
  };
  flush();  // the reused pairs before the first one to run
  run_parallel(
      static_cast<int>(runners.size()), to_run,
      [&](int w, std::size_t i, const std::atomic<int>* lent, const std::atomic<bool>* stop) {
        if (hooks.prepare) hooks.prepare(i);
        out[i] = runners[static_cast<std::size_t>(w)]->run(i, config, stop, lent);
      },
      [&](std::size_t i) {
        has[i] = true;
        ++progress.ran;
        if (hooks.finished) hooks.finished(i, out[i]);
        flush();
      },
      hooks.cancel);
  return out;
}

int parse_jobs(const std::string& text, const std::string& what) {
  if (text == "auto") return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  char* end = nullptr;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || n < 1 || n > 1024)
    throw InputError(what + ": expected a number of jobs 1 .. 1024 or 'auto', got '" + text + "'");
  return static_cast<int>(n);
}

std::string run_key(const std::string& tool, const Config& config, const PairEntry& entry) {
  return fingerprint(tool + "\n" + config_to_json(config, -1) + "\n" + pair_fingerprint(entry));
}

std::string bench_result_line(const std::string& report_json, const std::string& pair,
                              const std::string& key, const std::string& tool) {
  nlohmann::json line = nlohmann::json::parse(report_json);
  line["pair"] = pair;
  line["run_key"] = key;
  line["tool_version"] = tool;
  return line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);  // paths: bytes
}

}  // namespace pagor
