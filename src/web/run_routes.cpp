// Exec: a run of the editor's control software on a mission and seed, streamed whole to any
// viewer of its owner as server-sent events (live_run.hpp).
#include <charconv>

#include "app/documents/reality.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/pseudo_realities.hpp"
#include "app/user_files.hpp"
#include "control/config_string.hpp"
#include "web/http_io.hpp"
#include "web/mission_access.hpp"
#include "web/routes.hpp"

namespace sd::web {

namespace {

/// A pseudo-reality sample's number as a body gives it (a number or its digits): 1 or more.
std::uint64_t sample_number(const nlohmann::json& body) {
  const std::string text = text_field(body, "sample");
  std::uint64_t k = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), k);
  if (error != std::errc() || end != text.data() + text.size() || k < 1 || k > 1'000'000'000)
    throw app::InvalidRequest("sample '" + text + "': must be a whole number from 1 to 1000000000");
  return k;
}

}  // namespace

void add_run_routes(Routes& routes) {
  // The shipped pseudo-realities (reality/pseudo_reality.hpp), for the pages' choices.
  routes.get("/api/pseudo-realities", [](Call&) { return app::pseudo_realities_document(); });

  routes.post("/api/runs", [](Call& call) -> nlohmann::json {
    ControlSoftware software = parse_control_software(text_field(call.body, "text"));
    Mission mission = load_user_mission(call.home, call.user, text_field(call.body, "mission"));
    if (LiveRun::robot_ticks(mission) > RunRegistry::kMaxRobotTicks)
      throw app::InvalidRequest("mission " + mission.name + " has " + std::to_string(mission.robots) + " robots for " +
                                std::to_string(mission.ticks) + " ticks, more than the " +
                                std::to_string(RunRegistry::kMaxRobotTicks) +
                                " robot-ticks Exec records; score it with swarmdesign evaluate");
    const std::uint64_t seed = app::parse_seed(text_field(call.body, "seed"));
    // In a pseudo-reality sample (issue #46): the mission's robot model replaced by sample k of
    // a shipped specification or one of the user's own files.
    nlohmann::json reality = nullptr;
    const bool in_reality = call.body.contains("pseudo_reality") && !call.body.at("pseudo_reality").is_null() &&
                            call.body.at("pseudo_reality") != "";
    if (in_reality) {
      const std::string reference = text_field(call.body, "pseudo_reality");
      app::NamedPseudoReality named;
      try {
        named = app::load_requested_pseudo_reality(reference, app::FileScope::own_projects(call.home, call.user));
      } catch (const app::InvalidRequest& e) {
        throw app::InvalidRequest(std::string("pseudo_reality: ") + e.what());
      } catch (const app::NotFound& e) {
        throw app::InvalidRequest(std::string("pseudo_reality: ") + e.what());
      }
      const std::uint64_t k = call.body.contains("sample") ? sample_number(call.body) : 1;
      mission = app::in_pseudo_reality(mission, named.spec, k);
      reality = {{"spec", reference}, {"name", named.spec.name}, {"sample", k}, {"robot", app::robot_model_document(mission.robot)}};
    } else if (call.body.contains("sample") && !call.body.at("sample").is_null()) {
      throw app::InvalidRequest("sample: a sample needs a pseudo_reality");
    }
    std::string text = to_config_string(software);
    const std::int64_t id =
        call.context.runs.start(call.user.id, std::move(mission), std::move(software), std::move(text), seed);
    return {{"id", id}, {"pseudo_reality", std::move(reality)}};
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
