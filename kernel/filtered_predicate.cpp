#include "kernel/filtered_predicate.hpp"

#include <algorithm>
#include <mutex>

namespace exactvis {
namespace {
std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::vector<PredicateCounter*>& registry() {
  static std::vector<PredicateCounter*> r;
  return r;
}
std::atomic<bool> g_filter_enabled{true};
}  // namespace

PredicateCounter::PredicateCounter(std::string n) : name(std::move(n)) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  registry().push_back(this);
}

unsigned PredicateCounter::thread_slot() {
  static std::atomic<unsigned> next{0};
  thread_local const unsigned slot = next.fetch_add(1, std::memory_order_relaxed) % kSlots;
  return slot;
}

std::uint64_t PredicateCounter::calls() const {
  std::uint64_t t = 0;
  for (const Slot& s : slots) t += s.calls.load(std::memory_order_relaxed);
  return t;
}

std::uint64_t PredicateCounter::exact() const {
  std::uint64_t t = 0;
  for (const Slot& s : slots) t += s.exact.load(std::memory_order_relaxed);
  return t;
}

void PredicateCounter::reset() {
  for (Slot& s : slots) s.calls = 0, s.exact = 0;
}

std::vector<PredicateCounterSnapshot> predicate_counters() {
  std::lock_guard<std::mutex> lock(registry_mutex());
  // One entry per name: a predicate implemented as a template (double and Exact inputs) has one counter per
  // instantiation under the same name; they are summed.
  std::vector<PredicateCounterSnapshot> out;
  for (auto* c : registry()) {
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& s) { return s.name == c->name; });
    if (it == out.end()) it = out.insert(out.end(), {c->name, 0, 0});
    it->calls += c->calls();
    it->exact += c->exact();
  }
  return out;
}

void reset_predicate_counters() {
  std::lock_guard<std::mutex> lock(registry_mutex());
  for (auto* c : registry()) c->reset();
}

std::uint64_t exact_evaluations_total() {
  std::uint64_t t = 0;
  for (const auto& c : predicate_counters()) t += c.exact;
  return t;
}

void set_filter_enabled(bool enabled) { g_filter_enabled = enabled; }
bool filter_enabled() { return g_filter_enabled; }

}  // namespace exactvis
