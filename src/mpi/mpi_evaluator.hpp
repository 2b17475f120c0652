#pragma once
// The evaluation interface over MPI ranks: rank 0 hands a batch out by dynamic self-scheduling
// — chunks of a few runs, two chunks in flight per rank, the next chunk to whichever rank
// answers first, because runs differ in length by control software — and evaluates chunks
// itself while it waits. Scores are written by task index, so a batch's result is the threaded
// one bit for bit, whatever the number of ranks and threads per rank.
#include <cstdint>
#include <vector>

#include "evaluation/evaluator.hpp"
#include "mpi/session.hpp"

namespace sd::mpi {

/// How a batch of `tasks` runs is cut for a rank `width` threads wide, when the job's ranks
/// are `total_width` threads wide in all: a few runs per thread, fewer when the batch is short,
/// so that every rank gets work and the batch's tail stays short.
std::size_t chunk_size(std::size_t tasks, int width, int total_width);

class MpiEvaluator final : public Evaluator {
 public:
  /// threads: per rank (0: one per core of each rank's machine).
  MpiEvaluator(Session& session, int threads);
  ~MpiEvaluator() override;
  void evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) override;
  /// Threads over all ranks.
  int workers() const override { return total_width_; }

 private:
  struct Outgoing;
  void send(int rank, int tag, std::vector<char> bytes);
  void complete_sends(bool wait);
  void share_mission(const Mission& mission);

  Session& session_;
  int threads_;
  std::uint64_t id_;
  std::vector<int> width_;  // threads of each rank
  int total_width_ = 0;
  ThreadedEvaluator local_;
  std::vector<std::string> mission_known_;  // digest each rank holds
  std::vector<Outgoing> outgoing_;
  // What the ranks did, printed to stderr at the end with SWARMDESIGN_MPI_STATS=1 (bench/).
  std::vector<std::int64_t> runs_by_rank_;
  std::int64_t batches_ = 0, chunks_ = 0;
  double evaluate_seconds_ = 0, local_seconds_ = 0;
};

}  // namespace sd::mpi
