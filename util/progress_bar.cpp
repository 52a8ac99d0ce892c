#include "util/progress_bar.hpp"

#include "util/progress_observer.hpp"

#include <cstdio>

namespace exactvis {

namespace {
std::atomic<ProgressObserver*> the_observer{nullptr};
}  // namespace

ProgressObserver* set_progress_observer(ProgressObserver* observer) { return the_observer.exchange(observer); }

ProgressBar::ProgressBar(std::string label, std::uint64_t total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled), last_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  if (ProgressObserver* observer = the_observer.load()) observer->report(label_, done_.load(), total_);
  if (!enabled_) return;
  draw(done_.load());
  std::fputc('\n', stderr);
}

void ProgressBar::advance(std::uint64_t steps) {
  const std::uint64_t done = done_.fetch_add(steps) + steps;
  ProgressObserver* observer = the_observer.load(std::memory_order_relaxed);
  if (!enabled_ && !observer) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  if (enabled_) draw(done);
  if (observer) observer->report(label_, done, total_);
}

void ProgressBar::set_done(std::uint64_t done) {
  std::uint64_t cur = done_.load();
  while (cur < done && !done_.compare_exchange_weak(cur, done)) {
  }
  if (done > cur) advance(0);
}

void ProgressBar::draw(std::uint64_t done) {
  const int width = 40;
  const double f = total_ ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  const int fill = static_cast<int>(f * width);
  std::string bar(fill, '#');
  bar.resize(width, '.');
  std::fprintf(stderr, "\r%s [%s] %3d%% (%llu/%llu)", label_.c_str(), bar.c_str(), static_cast<int>(f * 100),
               static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_));
  std::fflush(stderr);
}

}  // namespace exactvis
