#pragma once
// Per-predicate counters of the filtered predicates: how many calls, and which layer of filtered_sign
// decided each (semi-static filter, interval filter, exact evaluation). docs/theory.md section 1 lists
// every counter name.
//
// Counting is thread-local: every thread owns one block of counts (one row per predicate), written only by
// that thread with a relaxed load and store (no atomic read-modify-write, no shared cache line), and read by
// predicate_counters() from any thread. A thread's counts are folded into a global total when it exits.
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace exactvis {

// The layer of filtered_sign that decided a call (docs/theory.md section 1).
enum class FilterLayer : int { SemiStatic = 0, Interval = 1, Exact = 2 };

namespace detail {
inline constexpr unsigned kMaxPredicateCounters = 256;
// One thread's counts: row = counter id; column 0 = calls, 1 + FilterLayer = decided by that layer.
struct ThreadPredicateCounts {
  std::atomic<std::uint64_t> counts[kMaxPredicateCounters][4];
};
// This thread's block, or nullptr before its first counted call.
extern constinit thread_local ThreadPredicateCounts* thread_predicate_counts;
// Allocates and registers the calling thread's block (first counted call of the thread).
ThreadPredicateCounts* attach_thread_predicate_counts();
// +1 by the owning thread (the only writer): a plain load and store, not a locked read-modify-write.
inline void bump(std::atomic<std::uint64_t>& c) {
  c.store(c.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
}
}  // namespace detail

// The counter of one predicate, usually a function-local static next to the predicate:
// `static PredicateCounter counter("name");` (constant-initialized: no guard, no static-order issue; it
// registers itself on its first counted call). Counters sharing a name (e.g. the double and the rational
// instantiation of one template) are reported as one. Throws std::length_error beyond
// detail::kMaxPredicateCounters counters.
class PredicateCounter {
 public:
  constexpr explicit PredicateCounter(const char* name) : name_(name) {}
  PredicateCounter(const PredicateCounter&) = delete;
  PredicateCounter& operator=(const PredicateCounter&) = delete;

  const char* name() const { return name_; }
  // The calling thread's row for this predicate: [0] calls, [1 + FilterLayer] decisions by that layer.
  std::atomic<std::uint64_t>* thread_counts() {
    unsigned id = id_.load(std::memory_order_acquire);
    if (id == kUnregistered) [[unlikely]]
      id = register_name();
    detail::ThreadPredicateCounts* t = detail::thread_predicate_counts;
    if (t == nullptr) [[unlikely]]
      t = detail::attach_thread_predicate_counts();
    return t->counts[id];
  }

 private:
  static constexpr unsigned kUnregistered = ~0u;
  unsigned register_name();  // assigns the id (once, under the registry lock)
  const char* name_;
  std::atomic<unsigned> id_{kUnregistered};
};

// Totals of one predicate name over all threads (live and exited). Each call is decided by exactly one
// layer, so semi_static + interval + exact == calls once no call is in progress.
struct PredicateCounterSnapshot {
  std::string name;
  std::uint64_t calls = 0;
  std::uint64_t semi_static = 0;  // decided by the semi-static filter (plain doubles, error bound)
  std::uint64_t interval = 0;     // decided by the interval filter
  std::uint64_t exact = 0;        // decided by exact evaluation (= exact evaluations)
};

// All counters registered so far, one entry per predicate name, in order of first registration.
// O(threads x counters); takes a lock (not for hot loops).
std::vector<PredicateCounterSnapshot> predicate_counters();
// Zeroes every counter. Call it while no other thread evaluates predicates (tests, benchmarks).
void reset_predicate_counters();
// Total exact evaluations over all predicates.
std::uint64_t exact_evaluations_total();

}  // namespace exactvis
