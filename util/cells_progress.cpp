#include "util/cells_progress.hpp"

#include <cstdio>

namespace exactvis {
namespace {

std::string clock_text(double seconds) {
  const auto s = static_cast<long long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", s / 3600, (s / 60) % 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%lld:%02lld", s / 60, s % 60);
  return buf;
}

}  // namespace

CellsProgress::CellsProgress(std::string label, std::uint64_t items, std::string step_name, bool enabled)
    : label_(std::move(label)), step_name_(std::move(step_name)), items_(items), enabled_(enabled),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

CellsProgress::~CellsProgress() {
  if (!enabled_) return;
  maybe_draw(true);
  std::fputc('\n', stderr);
}

void CellsProgress::start_item(std::uint64_t steps) {
  steps_done_.store(0);
  steps_.store(steps);
  maybe_draw(false);
}

void CellsProgress::item_steps(std::uint64_t done) {
  std::uint64_t cur = steps_done_.load();
  while (cur < done && !steps_done_.compare_exchange_weak(cur, done)) {
  }
  maybe_draw(false);
}

void CellsProgress::finish_item() {
  items_done_.fetch_add(1);
  steps_done_.store(0);
  steps_.store(0);
  maybe_draw(false);
}

void CellsProgress::maybe_draw(bool force) {
  if (!enabled_) return;
  std::unique_lock lock(mutex_, std::defer_lock);
  if (force) lock.lock();
  else if (!lock.try_lock()) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const std::uint64_t done = items_done_.load(), steps = steps_.load(), sd = steps_done_.load();
  const double frac_item = steps ? static_cast<double>(sd) / static_cast<double>(steps) : 0.0;
  const double progress = static_cast<double>(done) + frac_item;
  std::string left = "?";
  if (progress > 0 && items_ > 0)
    left = clock_text(elapsed * (static_cast<double>(items_) - progress) / progress);
  std::fprintf(stderr, "\r%s: cells %llu/%llu | cell %llu/%llu %s | %s elapsed | ~%s left   ", label_.c_str(),
               static_cast<unsigned long long>(done), static_cast<unsigned long long>(items_),
               static_cast<unsigned long long>(sd), static_cast<unsigned long long>(steps), step_name_.c_str(),
               clock_text(elapsed).c_str(), left.c_str());
  std::fflush(stderr);
}

}  // namespace exactvis
