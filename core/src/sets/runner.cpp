#include "pagor/sets/runner.hpp"

#include <algorithm>
#include <new>
#include <numeric>

#include "pagor/errors.hpp"

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

PairOutcome SetRunner::run(std::size_t i, const Config& config, const std::atomic<bool>* cancel) {
  if (cancel && cancel->load()) throw Cancelled();
  const PairEntry& entry = set_.pairs.at(i);
  Slot& slot = *slots_[i];
  std::array<int, kStageCount> before{};
  PairOutcome o;
  if (slot.pipeline) {
    for (int s = 0; s < kStageCount; ++s) before[s] = slot.pipeline->runs(static_cast<Stage>(s));
    slot.pipeline->set_config(config);
    try {  // the pair's own failure fails the pair, as in run_pair
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
    o = run_pair(*pipeline, entry, cancel);
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

std::vector<PairOutcome> run_set(SetRunner& runner, const Config& config,
                                 const RunSetHooks& hooks) {
  std::vector<PairOutcome> out(runner.size());
  std::vector<std::size_t> order = hooks.order;
  if (order.empty()) {
    order.resize(runner.size());
    std::iota(order.begin(), order.end(), 0);
  }
  for (std::size_t i : order) {
    std::optional<PairOutcome> reused = hooks.reuse ? hooks.reuse(i) : std::nullopt;
    out[i] = reused ? std::move(*reused) : runner.run(i, config, hooks.cancel);
    if (hooks.done) hooks.done(i, out[i]);
  }
  return out;
}

}  // namespace pagor
