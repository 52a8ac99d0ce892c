#include "kernel/filtered_predicate.hpp"

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

std::vector<PredicateCounterSnapshot> predicate_counters() {
  std::lock_guard<std::mutex> lock(registry_mutex());
  std::vector<PredicateCounterSnapshot> out;
  for (auto* c : registry()) out.push_back({c->name, c->calls.load(), c->exact.load()});
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
