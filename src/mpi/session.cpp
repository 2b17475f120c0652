#include "mpi/session.hpp"

#include <chrono>
#include <cstdlib>
#include <deque>
#include <map>
#include <string>
#include <thread>
#include <unordered_map>

#include "control/config_string.hpp"
#include "core/executor.hpp"
#include "evaluation/evaluator.hpp"
#include "mpi/mpi_evaluator.hpp"
#include "mpi/wire.hpp"

namespace sd::mpi {

namespace {

// Set by mpirun (OpenMPI) or by srun through PMI/PMIx: the process is one of an MPI job's ranks.
bool launched_by_mpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(variable)) return true;
  return false;
}

std::vector<char> receive(MPI_Comm comm, const MPI_Status& status) {
  int size = 0;
  MPI_Get_count(&status, MPI_CHAR, &size);
  std::vector<char> bytes(static_cast<std::size_t>(size));
  MPI_Recv(bytes.data(), size, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, comm, MPI_STATUS_IGNORE);
  return bytes;
}

void send(MPI_Comm comm, int tag, const std::vector<char>& bytes) {
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, 0, tag, comm);
}

/// What an evaluating rank keeps between chunks: the missions it was sent, and the control
/// software and simulations of rank 0's current evaluator (its keys promise the same software).
class Worker {
 public:
  explicit Worker(MPI_Comm comm) : comm_(comm) {}

  void take_mission(const std::vector<char>& bytes) {
    MissionText text = decode_mission(bytes);
    try {
      missions_.insert_or_assign(text.digest, parse_mission(text.document, text.source));
    } catch (const std::exception& e) {
      mission_errors_[text.digest] = e.what();
    }
  }

  void work(const std::vector<char>& bytes) {
    WorkChunk chunk;
    try {
      chunk = decode_work(bytes);
      send(comm_, kResultTag, encode(ChunkScores{chunk.batch, chunk.first, evaluate(chunk)}));
    } catch (const std::exception& e) {
      send(comm_, kFailureTag, encode(ChunkFailure{chunk.batch, chunk.first, e.what()}));
    }
  }

 private:
  std::vector<double> evaluate(const WorkChunk& chunk) {
    const auto mission = missions_.find(chunk.mission_digest);
    if (mission == missions_.end()) {
      const auto error = mission_errors_.find(chunk.mission_digest);
      throw std::runtime_error(error != mission_errors_.end() ? "the mission does not load here: " + error->second
                                                              : "the mission was never received");
    }
    if (!evaluator_ || evaluator_id_ != chunk.evaluator || threads_ != chunk.threads) {
      evaluator_ = std::make_unique<ThreadedEvaluator>(chunk.threads);
      evaluator_id_ = chunk.evaluator;
      threads_ = chunk.threads;
      keyed_.clear();
    }
    if (keyed_.size() > 4096) keyed_.clear();  // a long design's old configurations
    std::deque<ControlSoftware> unkeyed;        // this chunk's, by run of equal strings
    const std::string* last_text = nullptr;
    std::vector<EvaluationTask> tasks;
    for (const auto& task : chunk.tasks) {
      const ControlSoftware* software;
      if (task.key >= 0) {
        auto it = keyed_.find(task.key);
        if (it == keyed_.end()) it = keyed_.emplace(task.key, parse_control_software(task.software)).first;
        software = &it->second;
      } else {
        if (!last_text || *last_text != task.software) unkeyed.push_back(parse_control_software(task.software));
        last_text = &task.software;
        software = &unkeyed.back();
      }
      tasks.push_back({software, task.seed, task.key, task.robot ? &*task.robot : nullptr});
    }
    std::vector<double> scores(tasks.size());
    evaluator_->evaluate(mission->second, tasks, scores);
    return scores;
  }

  MPI_Comm comm_;
  std::map<std::string, Mission> missions_;  // by digest; nodes stay put for the evaluator's cache
  std::map<std::string, std::string> mission_errors_;
  std::unique_ptr<ThreadedEvaluator> evaluator_;
  std::uint64_t evaluator_id_ = 0;
  int threads_ = -1;
  std::unordered_map<std::int64_t, ControlSoftware> keyed_;
};

}  // namespace

std::unique_ptr<Session> Session::join_if_launched(int& argc, char**& argv) {
  if (!launched_by_mpi()) return nullptr;
  int provided = 0;
  // Rank 0's jobs may evaluate from a thread other than main (one at a time: MpiEvaluator
  // serialises them).
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  std::unique_ptr<Session> session(new Session());
  MPI_Comm_dup(MPI_COMM_WORLD, &session->comm_);
  MPI_Comm_rank(session->comm_, &session->rank_);
  MPI_Comm_size(session->comm_, &session->size_);
  const int cores = resolve_threads(0);
  session->cores_.resize(static_cast<std::size_t>(session->size_));
  MPI_Allgather(&cores, 1, MPI_INT, session->cores_.data(), 1, MPI_INT, session->comm_);
  if (session->size_ < 2) return session;  // alone: threads, as without mpirun
  if (session->is_root()) {
    Session* s = session.get();
    set_evaluator_factory([s](int threads) { return std::make_unique<MpiEvaluator>(*s, threads); });
  }
  return session;
}

Session::~Session() {
  if (is_root()) {
    set_evaluator_factory({});
    for (int r = 1; r < size_; ++r) MPI_Send(nullptr, 0, MPI_CHAR, r, kStopTag, comm_);
  }
  MPI_Comm_free(&comm_);
  MPI_Finalize();
}

int Session::serve() {
  Worker worker(comm_);
  // Polled rather than blocked on, with a growing pause: a blocking probe spins a core, which
  // on an oversubscribed node takes it from the ranks that evaluate.
  auto idle = std::chrono::microseconds(10);
  for (;;) {
    MPI_Status status;
    int arrived = 0;
    MPI_Iprobe(0, MPI_ANY_TAG, comm_, &arrived, &status);
    if (!arrived) {
      std::this_thread::sleep_for(idle);
      idle = std::min(idle * 2, std::chrono::microseconds(500));
      continue;
    }
    idle = std::chrono::microseconds(10);
    const std::vector<char> bytes = receive(comm_, status);
    switch (status.MPI_TAG) {
      case kStopTag: return 0;
      case kMissionTag: worker.take_mission(bytes); break;
      case kWorkTag: worker.work(bytes); break;
      default: break;
    }
  }
}

}  // namespace sd::mpi
