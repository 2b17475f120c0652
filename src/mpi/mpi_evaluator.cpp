#include "mpi/mpi_evaluator.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <atomic>
#include <chrono>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <unordered_map>

#include "control/config_string.hpp"
#include "core/executor.hpp"
#include "mpi/wire.hpp"

namespace sd::mpi {

namespace {

constexpr int kChunksInFlight = 2;

// The ranks are one resource: two jobs of one process (a server's, say) take turns.
std::mutex& ranks_mutex() {
  static std::mutex m;
  return m;
}

std::uint64_t next_evaluator_id() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

}  // namespace

std::size_t chunk_size(std::size_t tasks, int width, int total_width) {
  const auto per_thread_share = (tasks + static_cast<std::size_t>(total_width) * 3 - 1) /
                                (static_cast<std::size_t>(total_width) * 3);
  const auto w = static_cast<std::size_t>(std::max(width, 1));
  return std::max<std::size_t>(1, std::min(w * 2, per_thread_share * w));
}

struct MpiEvaluator::Outgoing {
  MPI_Request request = MPI_REQUEST_NULL;
  std::unique_ptr<std::vector<char>> bytes;  // stays put until the send completes
};

MpiEvaluator::MpiEvaluator(Session& session, int threads)
    : session_(session),
      threads_(threads),
      id_(next_evaluator_id()),
      local_(threads),
      mission_known_(static_cast<std::size_t>(session.size())),
      runs_by_rank_(static_cast<std::size_t>(session.size()), 0) {
  for (int r = 0; r < session.size(); ++r) {
    const int w = threads > 0 ? threads : session.cores()[static_cast<std::size_t>(r)];
    width_.push_back(std::max(w, 1));
    total_width_ += width_.back();
  }
}

MpiEvaluator::~MpiEvaluator() {
  try {
    complete_sends(true);
    if (const char* stats = std::getenv("SWARMDESIGN_MPI_STATS"); stats && std::string(stats) == "1") {
      std::fprintf(stderr, "mpi: %lld batches, %lld chunks, %.3f s evaluating (%.3f s on rank 0); runs by rank:",
                   static_cast<long long>(batches_), static_cast<long long>(chunks_), evaluate_seconds_, local_seconds_);
      for (const auto runs : runs_by_rank_) std::fprintf(stderr, " %lld", static_cast<long long>(runs));
      std::fprintf(stderr, "\n");
    }
  } catch (...) {
  }
}

void MpiEvaluator::send(int rank, int tag, std::vector<char> bytes) {
  Outgoing out;
  out.bytes = std::make_unique<std::vector<char>>(std::move(bytes));
  MPI_Isend(out.bytes->data(), static_cast<int>(out.bytes->size()), MPI_CHAR, rank, tag, session_.comm(), &out.request);
  outgoing_.push_back(std::move(out));
}

void MpiEvaluator::complete_sends(bool wait) {
  std::erase_if(outgoing_, [&](Outgoing& out) {
    int done = 0;
    if (wait) {
      MPI_Wait(&out.request, MPI_STATUS_IGNORE);
      done = 1;
    } else {
      MPI_Test(&out.request, &done, MPI_STATUS_IGNORE);
    }
    return done != 0;
  });
}

void MpiEvaluator::share_mission(const Mission& mission) {
  for (int r = 1; r < session_.size(); ++r) {
    auto& known = mission_known_[static_cast<std::size_t>(r)];
    if (known == mission.digest) continue;
    send(r, kMissionTag, encode(MissionText{mission.digest, mission.document, mission.source}));
    known = mission.digest;
  }
}

void MpiEvaluator::evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) {
  local_.stop_when(stop_flag());  // rank 0's own runs stop as the threaded ones do
  // A mission that was not read from a document cannot be rebuilt by another rank.
  if (session_.size() < 2 || mission.document.empty() || tasks.empty()) {
    local_.evaluate(mission, tasks, scores);
    return;
  }
  const std::lock_guard lock(ranks_mutex());
  const auto started = std::chrono::steady_clock::now();
  const auto batch = static_cast<std::uint64_t>(++batches_);
  share_mission(mission);

  // Each control software is written as a string once per batch.
  std::unordered_map<const ControlSoftware*, std::string> texts;
  auto text_of = [&](const ControlSoftware* software) -> const std::string& {
    auto [it, fresh] = texts.try_emplace(software);
    if (fresh) it->second = to_config_string(*software);
    return it->second;
  };

  std::size_t next = 0;      // first task not yet handed out
  std::size_t finished = 0;  // tasks whose scores are in
  std::vector<int> in_flight(static_cast<std::size_t>(session_.size()), 0);
  auto hand_out = [&](int rank) {
    const std::size_t count = std::min(chunk_size(tasks.size(), width_[static_cast<std::size_t>(rank)], total_width_),
                                       tasks.size() - next);
    WorkChunk chunk{id_, batch, next, threads_, mission.digest, {}};
    for (std::size_t i = next; i < next + count; ++i)
      chunk.tasks.push_back({tasks[i].key, tasks[i].seed, text_of(tasks[i].software),
                             tasks[i].robot ? std::optional<RobotModel>(*tasks[i].robot) : std::nullopt});
    send(rank, kWorkTag, encode(chunk));
    next += count;
    ++in_flight[static_cast<std::size_t>(rank)];
    ++chunks_;
  };
  // Every rank gets a chunk, then a second one (to work on while its first answer travels)
  // only as long as what is left exceeds rank 0's own share: on a narrow batch rank 0 would
  // otherwise wait idle for a rank working off its second chunk.
  const std::size_t share_here = (tasks.size() * static_cast<std::size_t>(width_[0]) + static_cast<std::size_t>(total_width_) - 1) /
                                 static_cast<std::size_t>(total_width_);
  for (int round = 0; round < kChunksInFlight; ++round)
    for (int r = 1; r < session_.size() && next < tasks.size(); ++r)
      if (round == 0 || tasks.size() - next > share_here) hand_out(r);

  std::string failure;
  // A stop (a cancel) is a failure that is no one's: no more work goes out, the chunks out (a
  // few runs each) are collected, and the batch is void (EvaluationStopped).
  bool stopped = false;
  const auto handing_out = [&] { return next < tasks.size() && failure.empty() && !stopped; };
  auto idle = std::chrono::microseconds(5);
  while (finished < tasks.size()) {
    stopped = stopped || stop_requested();
    MPI_Status status;
    int arrived = 0;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, session_.comm(), &arrived, &status);
    if (arrived) {
      idle = std::chrono::microseconds(5);
      int size = 0;
      MPI_Get_count(&status, MPI_CHAR, &size);
      std::vector<char> bytes(static_cast<std::size_t>(size));
      MPI_Recv(bytes.data(), size, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, session_.comm(), MPI_STATUS_IGNORE);
      const int rank = status.MPI_SOURCE;
      std::size_t count = 0;
      if (status.MPI_TAG == kResultTag) {
        const ChunkScores result = decode_scores(bytes);
        if (result.batch != batch) continue;  // of a batch an exception abandoned
        --in_flight[static_cast<std::size_t>(rank)];
        count = result.scores.size();
        if (result.first + count > scores.size()) throw WireError("rank " + std::to_string(rank) + " answered out of range");
        std::copy(result.scores.begin(), result.scores.end(), scores.begin() + static_cast<std::ptrdiff_t>(result.first));
      } else if (status.MPI_TAG == kFailureTag) {
        const ChunkFailure result = decode_failure(bytes);
        if (result.batch != batch) continue;
        --in_flight[static_cast<std::size_t>(rank)];
        // No more work goes out; the chunks still out are collected, so that no answer of
        // this batch is left for the next one to misread, and then the failure is thrown.
        if (failure.empty()) failure = "rank " + std::to_string(rank) + ": " + result.message;
      } else {
        throw WireError("unexpected message from rank " + std::to_string(rank));
      }
      finished += count;
      runs_by_rank_[static_cast<std::size_t>(rank)] += static_cast<std::int64_t>(count);
      if (handing_out()) hand_out(rank);
      complete_sends(false);
      continue;
    }
    if ((!failure.empty() || stopped) && std::all_of(in_flight.begin(), in_flight.end(), [](int n) { return n == 0; })) break;
    if (handing_out()) {
      // Nothing to collect: rank 0 evaluates a chunk of its own, one run per thread.
      const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(width_[0]), tasks.size() - next);
      const auto local_start = std::chrono::steady_clock::now();
      try {
        local_.evaluate(mission, tasks.subspan(next, count), scores.subspan(next, count));
      } catch (const EvaluationStopped&) {
        stopped = true;  // raised during rank 0's chunk: its runs are void, the ranks' are collected
        continue;
      }
      local_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - local_start).count();
      next += count;
      finished += count;
      runs_by_rank_[0] += static_cast<std::int64_t>(count);
      continue;
    }
    std::this_thread::sleep_for(idle);
    idle = std::min(idle * 2, std::chrono::microseconds(200));
  }
  complete_sends(true);
  evaluate_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!failure.empty()) throw std::runtime_error("evaluation failed on " + failure);
  if (finished < tasks.size()) throw EvaluationStopped();
}

}  // namespace sd::mpi
