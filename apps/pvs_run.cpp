#include "apps/pvs_run.hpp"

namespace exactvis::app {

CellScheduler::CellScheduler() {}

CellScheduler::~CellScheduler() {}

void CellScheduler::run(const std::vector<CellJob>& jobs, const PvsRunHooks& hooks) {
  for (const CellJob& job : jobs) hooks.finished(hooks.compute(job));
}

}  // namespace exactvis::app
