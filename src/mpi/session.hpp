#pragma once
// A process's place in an MPI job. `mpirun -np N swarmdesign <command>` starts N copies of the
// program: rank 0 runs the command (and races), every other rank serves evaluations until rank
// 0 is done. Rank 0 installs the MPI evaluator as the process's evaluation backend
// (evaluation/evaluator.hpp), so every job that evaluates — a design, `evaluate --seeds`, an
// evolution, an experiment — spreads over the ranks without knowing it.
#include <memory>
#include <vector>

#include <mpi.h>

namespace sd::mpi {

class Session {
 public:
  /// Joins the MPI job when an MPI launcher (mpirun, srun) started this process among two or
  /// more ranks; nullptr when the process runs alone (it then evaluates on its threads).
  static std::unique_ptr<Session> join_if_launched(int& argc, char**& argv);
  /// Rank 0 tells the other ranks to stop; every rank leaves MPI.
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_root() const { return rank_ == 0; }
  MPI_Comm comm() const { return comm_; }
  /// Cores of each rank's machine, by rank (gathered when the job starts).
  const std::vector<int>& cores() const { return cores_; }

  /// Ranks > 0: evaluates what rank 0 sends until it says stop. The process's exit status.
  int serve();

 private:
  Session() = default;
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  int size_ = 1;
  std::vector<int> cores_;
};

}  // namespace sd::mpi
