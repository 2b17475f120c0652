#include "mpi/wire.hpp"

#include <cstring>
#include <type_traits>

namespace sd::mpi {

namespace {

// Both ends run the same build on the same kind of machine (bit-identical scores need it
// anyway), so numbers travel in the machine's own representation.
class Writer {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const char*>(&value);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    bytes_.insert(bytes_.end(), text.begin(), text.end());
  }
  std::vector<char> take() { return std::move(bytes_); }

 private:
  std::vector<char> bytes_;
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string text() {
    const auto size = get<std::uint64_t>();
    need(size);
    std::string out(bytes_.data() + at_, static_cast<std::size_t>(size));
    at_ += static_cast<std::size_t>(size);
    return out;
  }
  void finish() const {
    if (at_ != bytes_.size()) throw WireError("malformed message from another rank: trailing bytes");
  }

 private:
  void need(std::uint64_t size) const {
    if (size > bytes_.size() - at_) throw WireError("malformed message from another rank: truncated");
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::vector<char> encode(const MissionText& mission) {
  Writer w;
  w.put(mission.digest);
  w.put(mission.document);
  w.put(mission.source);
  return w.take();
}

MissionText decode_mission(const std::vector<char>& bytes) {
  Reader r(bytes);
  MissionText out;
  out.digest = r.text();
  out.document = r.text();
  out.source = r.text();
  r.finish();
  return out;
}

std::vector<char> encode(const WorkChunk& chunk) {
  Writer w;
  w.put(chunk.evaluator);
  w.put(chunk.batch);
  w.put(chunk.first);
  w.put(chunk.threads);
  w.put(chunk.mission_digest);
  w.put(static_cast<std::uint64_t>(chunk.tasks.size()));
  for (const auto& task : chunk.tasks) {
    w.put(task.key);
    w.put(task.seed);
    w.put(task.software);
    w.put(static_cast<std::uint8_t>(task.robot ? 1 : 0));
    if (task.robot)
      for (const RobotKnob& knob : kRobotKnobs) w.put((*task.robot).*(knob.member));
  }
  return w.take();
}

std::vector<char> encode(const ChunkScores& scores) {
  Writer w;
  w.put(scores.batch);
  w.put(scores.first);
  w.put(static_cast<std::uint64_t>(scores.scores.size()));
  for (const double s : scores.scores) w.put(s);
  return w.take();
}

std::vector<char> encode(const ChunkFailure& failure) {
  Writer w;
  w.put(failure.batch);
  w.put(failure.first);
  w.put(failure.message);
  return w.take();
}

WorkChunk decode_work(const std::vector<char>& bytes) {
  Reader r(bytes);
  WorkChunk chunk;
  chunk.evaluator = r.get<std::uint64_t>();
  chunk.batch = r.get<std::uint64_t>();
  chunk.first = r.get<std::uint64_t>();
  chunk.threads = r.get<std::int32_t>();
  chunk.mission_digest = r.text();
  const auto count = r.get<std::uint64_t>();
  if (count > bytes.size()) throw WireError("malformed message from another rank: task count");
  chunk.tasks.resize(static_cast<std::size_t>(count));
  for (auto& task : chunk.tasks) {
    task.key = r.get<std::int64_t>();
    task.seed = r.get<std::uint64_t>();
    task.software = r.text();
    if (r.get<std::uint8_t>() != 0) {
      RobotModel robot;
      for (const RobotKnob& knob : kRobotKnobs) robot.*(knob.member) = r.get<double>();
      task.robot = robot;
    }
  }
  r.finish();
  return chunk;
}

ChunkScores decode_scores(const std::vector<char>& bytes) {
  Reader r(bytes);
  ChunkScores out;
  out.batch = r.get<std::uint64_t>();
  out.first = r.get<std::uint64_t>();
  const auto count = r.get<std::uint64_t>();
  if (count > bytes.size()) throw WireError("malformed message from another rank: score count");
  out.scores.resize(static_cast<std::size_t>(count));
  for (double& s : out.scores) s = r.get<double>();
  r.finish();
  return out;
}

ChunkFailure decode_failure(const std::vector<char>& bytes) {
  Reader r(bytes);
  ChunkFailure out;
  out.batch = r.get<std::uint64_t>();
  out.first = r.get<std::uint64_t>();
  out.message = r.text();
  r.finish();
  return out;
}

}  // namespace sd::mpi
