#include "web/live_run.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/control_software_document.hpp"
#include "app/documents.hpp"
#include "app/evaluation_job.hpp"
#include "evaluation/simulation.hpp"
#include "missions/svg.hpp"
#include "simulator/epuck.hpp"

namespace sd::web {

namespace {

constexpr int kTicksPerBatch = 10;  // one simulated second per message

std::string sse(const char* event, const std::string& data) {
  return std::string("event: ") + event + "\ndata: " + data + "\n\n";
}

/// Frames of kTicksPerBatch ticks as compact JSON arrays (robot-major inside a tick),
/// positions to 0.1 mm and headings to 1 mrad: far below what a screen shows.
class FrameBatcher : public TickObserver {
 public:
  FrameBatcher(int robots, std::function<void(std::string)> emit, const std::atomic<bool>& stopping)
      : robots_(robots), emit_(std::move(emit)), stopping_(stopping) {}

  void on_tick(const Simulation& sim) override {
    if (stopping_.load(std::memory_order_relaxed)) throw Stopped{};
    if (count_ == 0) first_ = sim.tick();
    const SwarmState& s = sim.swarm();
    char number[32];
    for (int r = 0; r < robots_; ++r) {
      const auto i = static_cast<std::size_t>(r);
      const char* sep = (count_ == 0 && r == 0) ? "" : ",";
      std::snprintf(number, sizeof number, "%s%.4f", sep, s.position[i].x);
      x_ += number;
      std::snprintf(number, sizeof number, "%s%.4f", sep, s.position[i].y);
      y_ += number;
      std::snprintf(number, sizeof number, "%s%.3f", sep, s.yaw[i]);
      yaw_ += number;
      std::snprintf(number, sizeof number, "%s%u", sep, static_cast<unsigned>(s.led[i]));
      led_ += number;
      std::snprintf(number, sizeof number, "%s%d", sep, sim.fsm_state(r));
      state_ += number;
    }
    std::snprintf(number, sizeof number, "%s%.17g", count_ == 0 ? "" : ",", sim.score());
    objective_ += number;
    if (++count_ == kTicksPerBatch || sim.finished()) flush();
  }

  struct Stopped {};

 private:
  void flush() {
    std::string data = "{\"first\":" + std::to_string(first_) + ",\"count\":" + std::to_string(count_) + ",\"x\":[" +
                       x_ + "],\"y\":[" + y_ + "],\"yaw\":[" + yaw_ + "],\"led\":[" + led_ + "],\"state\":[" + state_ +
                       "],\"objective\":[" + objective_ + "]}";
    emit_(sse("frames", data));
    x_.clear(), y_.clear(), yaw_.clear(), led_.clear(), state_.clear(), objective_.clear();
    count_ = 0;
  }

  int robots_;
  std::function<void(std::string)> emit_;
  const std::atomic<bool>& stopping_;
  int first_ = 0, count_ = 0;
  std::string x_, y_, yaw_, led_, state_, objective_;
};

}  // namespace

LiveRun::LiveRun(std::int64_t owner, Mission mission, ControlSoftware software, std::string text, std::uint64_t seed)
    : owner_(owner), mission_(std::move(mission)), software_(std::move(software)), text_(std::move(text)), seed_(seed) {
  thread_ = std::thread([this] { simulate(); });
}

LiveRun::~LiveRun() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
}

bool LiveRun::finished() const {
  std::lock_guard lock(mutex_);
  return done_;
}

void LiveRun::publish(std::string event, bool last) {
  {
    std::lock_guard lock(mutex_);
    events_.push_back(std::move(event));
    done_ = done_ || last;
  }
  changed_.notify_all();
}

void LiveRun::simulate() {
  try {
    nlohmann::json scene{{"mission", app::mission_document(mission_)},
                         {"seed", seed_},
                         {"text", text_},
                         {"software", app::software_document(software_)},
                         {"svg", mission_svg(mission_)},
                         {"robots", mission_.robots},
                         {"robot_radius", epuck::kBodyRadius},
                         {"rab_range", mission_.robot.rab_range},
                         {"ticks", mission_.ticks},
                         {"tick_seconds", epuck::kTickSeconds}};
    publish(sse("scene", scene.dump()));
    // The same run as `evaluate`, observed: the score is the same bits.
    FrameBatcher batcher(mission_.robots, [this](std::string e) { publish(std::move(e)); }, stopping_);
    const double score = app::observed_run(mission_, software_, seed_, batcher);
    char number[40];
    std::snprintf(number, sizeof number, "%.17g", score);
    publish(sse("end", std::string("{\"score\":") + number + ",\"ticks\":" + std::to_string(mission_.ticks) + "}"), true);
  } catch (const FrameBatcher::Stopped&) {
    publish(sse("failure", R"({"error":"the run was stopped"})"), true);
  } catch (const std::exception& e) {
    publish(sse("failure", nlohmann::json{{"error", e.what()}}.dump()), true);
  }
}

std::size_t LiveRun::wait_events(std::size_t from, std::string& out, int timeout_ms, bool& done) const {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, std::chrono::milliseconds(timeout_ms), [&] { return events_.size() > from || done_; });
  for (std::size_t i = from; i < events_.size(); ++i) out += events_[i];
  done = done_;
  return events_.size();
}

}  // namespace sd::web
