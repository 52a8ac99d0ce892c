#include "kernel/predicate_counters.hpp"

#include <algorithm>
#include <array>
#include <mutex>
#include <stdexcept>

namespace exactvis {
namespace detail {

constinit thread_local ThreadPredicateCounts* thread_predicate_counts = nullptr;

namespace {

using Row = std::array<std::uint64_t, 4>;

// Names by counter id, the live threads' blocks and the totals of exited threads. Never destroyed: worker
// threads may exit after static destruction has begun.
struct Registry {
  std::mutex mutex;
  std::vector<std::string> names;
  std::vector<ThreadPredicateCounts*> live;
  std::array<Row, kMaxPredicateCounters> retired{};
  ThreadPredicateCounts late{};  // shared by threads counting after their own block was retired (exit)
};

Registry& registry() {
  static Registry* r = new Registry;
  return *r;
}

// Folds an exiting thread's counts into the retired totals.
struct ThreadBlockOwner {
  ThreadPredicateCounts* block = nullptr;
  ~ThreadBlockOwner() {
    if (!block) return;
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    for (unsigned id = 0; id < kMaxPredicateCounters; ++id)
      for (int k = 0; k < 4; ++k) r.retired[id][k] += block->counts[id][k].load(std::memory_order_relaxed);
    r.live.erase(std::find(r.live.begin(), r.live.end(), block));
    delete block;
    thread_predicate_counts = &r.late;
  }
};

}  // namespace

ThreadPredicateCounts* attach_thread_predicate_counts() {
  thread_local ThreadBlockOwner owner;
  Registry& r = registry();
  auto* block = new ThreadPredicateCounts{};
  {
    std::lock_guard<std::mutex> lock(r.mutex);
    r.live.push_back(block);
  }
  owner.block = block;
  thread_predicate_counts = block;
  return block;
}

}  // namespace detail

unsigned PredicateCounter::register_name() {
  detail::Registry& r = detail::registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  unsigned id = id_.load(std::memory_order_relaxed);
  if (id != kUnregistered) return id;  // another thread registered it meanwhile
  if (r.names.size() >= detail::kMaxPredicateCounters)
    throw std::length_error("more than kMaxPredicateCounters predicate counters (raise it)");
  id = static_cast<unsigned>(r.names.size());
  r.names.emplace_back(name_);
  id_.store(id, std::memory_order_release);
  return id;
}

std::vector<PredicateCounterSnapshot> predicate_counters() {
  detail::Registry& r = detail::registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::vector<PredicateCounterSnapshot> out;
  for (unsigned id = 0; id < r.names.size(); ++id) {
    detail::Row t = r.retired[id];
    for (int k = 0; k < 4; ++k) t[k] += r.late.counts[id][k].load(std::memory_order_relaxed);
    for (const auto* block : r.live)
      for (int k = 0; k < 4; ++k) t[k] += block->counts[id][k].load(std::memory_order_relaxed);
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& s) { return s.name == r.names[id]; });
    if (it == out.end()) it = out.insert(out.end(), PredicateCounterSnapshot{r.names[id]});
    it->calls += t[0];
    it->semi_static += t[1 + static_cast<int>(FilterLayer::SemiStatic)];
    it->interval += t[1 + static_cast<int>(FilterLayer::Interval)];
    it->exact += t[1 + static_cast<int>(FilterLayer::Exact)];
  }
  return out;
}

void reset_predicate_counters() {
  detail::Registry& r = detail::registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.retired = {};
  for (unsigned id = 0; id < detail::kMaxPredicateCounters; ++id)
    for (int k = 0; k < 4; ++k) {
      r.late.counts[id][k].store(0, std::memory_order_relaxed);
      for (auto* block : r.live) block->counts[id][k].store(0, std::memory_order_relaxed);
    }
}

std::uint64_t exact_evaluations_total() {
  std::uint64_t t = 0;
  for (const auto& c : predicate_counters()) t += c.exact;
  return t;
}

}  // namespace exactvis
