#include "apps/pvs_run.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#ifdef EXACTVIS_WITH_MPI
// The C API only (OpenMPI/MPICH would otherwise pull in their deprecated C++ bindings).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace exactvis::app {

namespace {

bool launched_by_mpirun() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE"); }

#ifdef EXACTVIS_WITH_MPI
constexpr int kTagJob = 1, kTagResult = 2, kTagError = 3;
constexpr long long kStop = -1;

// Rank 0: hands out positions in `jobs`, one at a time, to whichever worker reports back first.
void run_master(const std::vector<CellJob>& jobs, const PvsRunHooks& hooks, int size) {
  std::size_t next = 0;
  int busy = 0;
  for (int r = 1; r < size; ++r) {
    const long long job = next < jobs.size() ? static_cast<long long>(next++) : kStop;
    MPI_Send(&job, 1, MPI_LONG_LONG, r, kTagJob, MPI_COMM_WORLD);
    if (job != kStop) ++busy;
  }
  while (busy > 0) {
    MPI_Status status;
    MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::string text(static_cast<std::size_t>(length), '\0');
    MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (status.MPI_TAG == kTagError) {
      // The other ranks may be busy: end the whole job with the worker's one-line message.
      std::fprintf(stderr, "exactvis pvs: error: %s\n", text.c_str());
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    --busy;
    const long long job = next < jobs.size() ? static_cast<long long>(next++) : kStop;
    MPI_Send(&job, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagJob, MPI_COMM_WORLD);
    if (job != kStop) ++busy;
    hooks.finished(nlohmann::ordered_json::parse(text));
  }
}

void run_worker(const std::vector<CellJob>& jobs, const PvsRunHooks& hooks) {
  for (;;) {
    long long job = kStop;
    MPI_Recv(&job, 1, MPI_LONG_LONG, 0, kTagJob, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (job == kStop) return;
    std::string text;
    int tag = kTagResult;
    try {
      text = hooks.compute(jobs.at(static_cast<std::size_t>(job))).dump();
    } catch (const std::exception& e) {
      text = e.what();
      tag = kTagError;
    }
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, tag, MPI_COMM_WORLD);
  }
}
#endif

}  // namespace

CellScheduler::CellScheduler() {
  if (!launched_by_mpirun()) return;
#ifdef EXACTVIS_WITH_MPI
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  mpi_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#else
  throw std::runtime_error("started by mpirun, but this exactvis was built without MPI (install libopenmpi-dev "
                           "and rebuild)");
#endif
}

CellScheduler::~CellScheduler() {
#ifdef EXACTVIS_WITH_MPI
  if (mpi_) MPI_Finalize();
#endif
}

void CellScheduler::run(const std::vector<CellJob>& jobs, const PvsRunHooks& hooks) {
#ifdef EXACTVIS_WITH_MPI
  if (mpi_ && size_ > 1) {
    if (rank_ == 0) run_master(jobs, hooks, size_);
    else run_worker(jobs, hooks);
    return;
  }
#endif
  for (const CellJob& job : jobs) hooks.finished(hooks.compute(job));
}

}  // namespace exactvis::app
