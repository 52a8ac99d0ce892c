#include "kernel/filtered_predicate.hpp"

namespace exactvis {
namespace detail {
std::atomic<bool> filter_enabled_flag{true};
}  // namespace detail

void set_filter_enabled(bool enabled) { detail::filter_enabled_flag.store(enabled, std::memory_order_relaxed); }

}  // namespace exactvis
