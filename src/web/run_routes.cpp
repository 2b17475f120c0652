// Exec: a run of the editor's control software on a mission and seed, streamed whole to any
// viewer of its owner as server-sent events (live_run.hpp).
#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "control/config_string.hpp"
#include "web/http_io.hpp"
#include "web/mission_access.hpp"
#include "web/routes.hpp"

namespace sd::web {

void add_run_routes(Routes& routes) {
  routes.post("/api/runs", [](Call& call) -> nlohmann::json {
    ControlSoftware software = parse_control_software(text_field(call.body, "text"));
    Mission mission = load_user_mission(call.home, call.user, text_field(call.body, "mission"));
    if (LiveRun::robot_ticks(mission) > RunRegistry::kMaxRobotTicks)
      throw app::InvalidRequest("mission " + mission.name + " has " + std::to_string(mission.robots) + " robots for " +
                                std::to_string(mission.ticks) + " ticks, more than the " +
                                std::to_string(RunRegistry::kMaxRobotTicks) +
                                " robot-ticks Exec records; score it with swarmdesign evaluate");
    const std::uint64_t seed = app::parse_seed(text_field(call.body, "seed"));
    std::string text = to_config_string(software);
    const std::int64_t id =
        call.context.runs.start(call.user.id, std::move(mission), std::move(software), std::move(text), seed);
    return {{"id", id}};
  });

  routes.get_raw(R"(/api/runs/(\d{1,15})/stream)", [](Call& call) {
    std::shared_ptr<const LiveRun> run = call.context.runs.get(call.user.id, std::stoll(call.match(1)));
    call.response.set_header("Cache-Control", "no-store");
    call.response.set_chunked_content_provider(
        "text/event-stream", [run, sent = std::size_t{0}](std::size_t, httplib::DataSink& sink) mutable {
          std::string out;
          bool done = false;
          sent = run->wait_events(sent, out, 1000, done);
          if (out.empty()) out = ": waiting\n\n";  // a comment: finds a viewer that has gone
          if (!sink.write(out.data(), out.size())) return false;
          if (done) sink.done();
          return true;
        });
  });
}

}  // namespace sd::web
