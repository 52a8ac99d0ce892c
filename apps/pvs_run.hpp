#pragma once
// How `exactvis pvs` runs its cells: in this process, one cell after another (each cell on all cores), or,
// when started by mpirun, spread over the ranks dynamically (docs/cli.md "pvs under MPI").
#include "region/convex_polygon_3.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace exactvis::app {

struct Shard {
  std::int64_t index = 0, count = 1;  // --shard K/N
};

struct CellJob {
  std::int64_t index = 0;  // cell number in the run
  region::RationalBox3 box;
};

struct PvsRunHooks {
  // Computes one cell and returns its JSON (io/pvs_json.hpp CELL). Called on the ranks that compute.
  std::function<nlohmann::ordered_json(const CellJob&)> compute;
  // Receives each finished cell, in finishing order. Called only where writer() is true.
  std::function<void(const nlohmann::ordered_json&)> finished;
};

// One per run. Under mpirun (OMPI_COMM_WORLD_SIZE or PMI_SIZE set, and MPI support built in), the
// constructor calls MPI_Init and the destructor MPI_Finalize; otherwise no MPI call is made at all.
class CellScheduler {
 public:
  CellScheduler();
  ~CellScheduler();
  CellScheduler(const CellScheduler&) = delete;
  CellScheduler& operator=(const CellScheduler&) = delete;

  // True on the process that writes the outputs (rank 0, or the only process).
  bool writer() const { return rank_ == 0; }
  int ranks() const { return size_; }

  // Runs the jobs: serially here, or under MPI rank 0 hands out one cell at a time to the other ranks (the
  // next cell goes to whichever rank finishes first) and receives their JSON. With one rank, rank 0
  // computes itself. An exception on a worker rank aborts the whole MPI job with its message.
  void run(const std::vector<CellJob>& jobs, const PvsRunHooks& hooks);

 private:
  int rank_ = 0, size_ = 1;
  bool mpi_ = false;
};

}  // namespace exactvis::app
