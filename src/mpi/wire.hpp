#pragma once
// What rank 0 and the evaluating ranks say to each other, as flat byte buffers: a mission (its
// document's text, sent once per rank), a chunk of work (control software as configuration
// strings, which round-trip exactly), and a chunk's scores. Pure functions, so the encoding is
// tested without MPI.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "simulator/robot_model.hpp"

namespace sd::mpi {

enum Tag : int { kMissionTag = 1, kWorkTag = 2, kStopTag = 3, kResultTag = 4, kFailureTag = 5 };

struct MissionText {
  std::string digest;
  std::string document;  // parse_mission rebuilds the same mission from it
  std::string source;
};

struct WireTask {
  std::int64_t key = -1;  // EvaluationTask::key
  std::uint64_t seed = 0;
  std::string software;   // configuration string
  std::optional<RobotModel> robot{};  // EvaluationTask::robot (a pseudo-reality), by value
};

struct WorkChunk {
  std::uint64_t evaluator = 0;  // which rank-0 evaluator (keys are promises within one)
  std::uint64_t batch = 0;      // which of its batches (answers of an abandoned one are dropped)
  std::uint64_t first = 0;      // index of the first task in rank 0's batch
  std::int32_t threads = 0;     // threads the rank evaluates with (0: one per core)
  std::string mission_digest;
  std::vector<WireTask> tasks;
};

struct ChunkScores {
  std::uint64_t batch = 0;
  std::uint64_t first = 0;
  std::vector<double> scores;
};

struct ChunkFailure {
  std::uint64_t batch = 0;
  std::uint64_t first = 0;
  std::string message;
};

/// A malformed buffer (a rank of another build, say).
struct WireError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<char> encode(const MissionText& mission);
std::vector<char> encode(const WorkChunk& chunk);
std::vector<char> encode(const ChunkScores& scores);
std::vector<char> encode(const ChunkFailure& failure);
MissionText decode_mission(const std::vector<char>& bytes);
WorkChunk decode_work(const std::vector<char>& bytes);
ChunkScores decode_scores(const std::vector<char>& bytes);
ChunkFailure decode_failure(const std::vector<char>& bytes);

}  // namespace sd::mpi
