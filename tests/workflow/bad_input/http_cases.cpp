// Each HTTP route's body (src/web/API.md): malformed JSON, wrong types, missing fields,
// oversized bodies, signed-out requests, a missing CSRF token or content type.
#include <nlohmann/json.hpp>

#include "workflow/bad_input/catalogue.hpp"

namespace sd::test::bad_input {

namespace {
const std::string kFsm = "--fsm-config --nstates 1 --s0 10 --rwm0 50";
}

std::vector<HttpCase> http_cases(const Inputs& in) {
  using C = Caller;
  const std::string own_bad_mission = (in.own / "bad-mission.json").string();
  const std::string own_folder = in.own.string();
  const std::string big(2 << 20, 'x');
  std::vector<HttpCase> cases{
      // Sign-in: malformed bodies are 400 and are not counted as failed guesses.
      {"POST", "/api/sign-in", "", C::SignedOut, 400, "name is missing"},
      {"POST", "/api/sign-in", "{", C::SignedOut, 400, "JSON"},
      {"POST", "/api/sign-in", "[]", C::SignedOut, 400, "must be a JSON object"},
      // A number no double holds: nlohmann's out_of_range, once a 500 (found by fuzz_protocol).
      {"POST", "/api/sign-in", R"({"name": "alice", "password": 1e999})", C::SignedOut, 400, "number overflow"},
      {"POST", "/api/parse", R"({"text": 2.9e3087})", C::SignedIn, 400, "number overflow"},
      {"POST", "/api/sign-in", R"({"password": "alice-secret-pw"})", C::SignedOut, 400, "name"},
      {"POST", "/api/sign-in", R"({"name": "alice"})", C::SignedOut, 400, "password"},
      {"POST", "/api/sign-in", R"({"name": 5, "password": "x"})", C::SignedOut, 400, "name"},
      {"POST", "/api/sign-in", R"({"name": "alice", "password": ["x"]})", C::SignedOut, 400, "password"},
      {"POST", "/api/sign-in", "{\"name\": \"" + big + "\"}", C::SignedOut, 413, "larger than 1 MiB"},
      {"POST", "/api/sign-in", R"({"name": "alice", "password": "alice-secret-pw"})", C::WrongContentType, 415,
       "application/json"},
      // Every other route wants a session, and every POST its CSRF token.
      {"GET", "/api/session", "", C::SignedOut, 401, "sign"},
      {"GET", "/api/catalogue", "", C::SignedOut, 401, "sign"},
      {"GET", "/api/missions", "", C::SignedOut, 401, "sign"},
      {"GET", "/api/projects", "", C::SignedOut, 401, "sign"},
      {"GET", "/api/projects/p1/status", "", C::SignedOut, 401, "sign"},
      {"POST", "/api/sign-out", "{}", C::SignedOut, 401, "sign"},
      {"POST", "/api/parse", R"({"text": ")" + kFsm + R"("})", C::SignedOut, 401, "sign"},
      {"POST", "/api/projects", R"({"name": "x", "mission": "aac", "budget": 1000})", C::SignedOut, 401, "sign"},
      {"POST", "/api/sign-out", "{}", C::NoCsrf, 403, "CSRF"},
      {"POST", "/api/parse", R"({"text": ")" + kFsm + R"("})", C::NoCsrf, 403, "CSRF"},
      {"POST", "/api/projects", R"({"name": "x", "mission": "aac", "budget": 1000})", C::NoCsrf, 403, "CSRF"},
      {"POST", "/api/runs", R"({"text": ")" + kFsm + R"(", "mission": "aac", "seed": 1})", C::NoCsrf, 403, "CSRF"},
      {"POST", "/api/projects/p1/budget", R"({"budget": 10})", C::NoCsrf, 403, "CSRF"},
      {"POST", "/api/parse", R"({"text": ")" + kFsm + R"("})", C::WrongContentType, 415, "application/json"},
      // parse and print.
      {"POST", "/api/parse", "", C::SignedIn, 400, "text is missing"},
      {"POST", "/api/parse", "{\"text\": ", C::SignedIn, 400, "JSON"},
      {"POST", "/api/parse", "{}", C::SignedIn, 400, "text"},
      {"POST", "/api/parse", R"({"text": {}})", C::SignedIn, 400, "text must be text"},
      {"POST", "/api/parse", R"({"text": "--fsm-config --nstates 0"})", C::SignedIn, 400, "--nstates"},
      {"POST", "/api/parse", R"({"text": "--fsm-config --nstates 1 --s0 10 --rwm0 abc"})", C::SignedIn, 400, "--rwm0"},
      {"POST", "/api/parse", R"({"text": "--bt-config --nroot 3 --nchildroot 0"})", C::SignedIn, 400, "--nchildroot"},
      {"POST", "/api/parse", R"({"text": "--nn-config --w0x0 abc"})", C::SignedIn, 400, "--w0x0"},
      {"POST", "/api/parse", "{\"text\": \"--fsm-config --nstates \xff\"}", C::SignedIn, 400, "JSON"},
      {"POST", "/api/parse", "{\"text\": \"" + big + "\"}", C::SignedIn, 413, "larger than 1 MiB"},
      {"POST", "/api/print", "{}", C::SignedIn, 400, "software"},
      {"POST", "/api/print", R"({"software": 5})", C::SignedIn, 400, "software"},
      {"POST", "/api/print", R"({"software": {"architecture": "nope"}})", C::SignedIn, 400, "software.architecture"},
      {"POST", "/api/print", R"({"software": {"architecture": "fsm", "states": []}})", C::SignedIn, 400, "state"},
      {"POST", "/api/print", R"({"software": {"architecture": "fsm", "states": [{"behaviour": {"id": 99}}]}})",
       C::SignedIn, 400, "99"},
      {"POST", "/api/print",
       R"({"software": {"architecture": "fsm", "states": [{"behaviour": {"id": 10, "parameters": {"rwm": "x"}}}]}})",
       C::SignedIn, 400, "rwm"},
      {"POST", "/api/print",
       R"({"software": {"architecture": "fsm", "states": [{"behaviour": {"id": 10, "parameters": {"rwm": 50}}, "transitions": [{"target": 7, "condition": {"id": 15, "parameters": {"p": 0.5}}}]}]}})",
       C::SignedIn, 400, "'--n0 1'"},
      {"POST", "/api/print", R"({"software": {"architecture": "bt", "nodes": [{"type": "nope"}]}})", C::SignedIn, 400,
       "nope"},
      {"POST", "/api/print", R"({"software": {"architecture": "bt", "nodes": [{"type": "sequence*", "children": [5]}]}})",
       C::SignedIn, 400, "children"},
      // The drawing fuzzer's finding: a number where the list of transitions belongs answered 500.
      {"POST", "/api/print",
       R"({"software": {"architecture": "fsm", "states": [{"behaviour": {"id": 10, "parameters": {"rwm": 50}}, "transitions": 11}]}})",
       C::SignedIn, 400, "software.states[0].transitions must be a list"},
      // get<int>() on 1e300 is undefined behaviour; 2^32 + 10 would wrap to Exploration's id.
      {"POST", "/api/print", R"({"software": {"architecture": "fsm", "states": [{"behaviour": {"id": 1e300}}]}})",
       C::SignedIn, 400, "software.states[0].behaviour.id must be an integer"},
      {"POST", "/api/print", R"({"software": {"architecture": "fsm", "states": [{"behaviour": {"id": 4294967306}}]}})",
       C::SignedIn, 400, "software.states[0].behaviour.id must be an integer"},
      {"POST", "/api/print", R"({"software": {"architecture": "bt", "nodes": [{"type": "sequence*", "children": 1}]}})",
       C::SignedIn, 400, "software.nodes[0].children must be a list"},
      {"POST", "/api/print",
       R"({"software": {"architecture": "bt", "nodes": [{"type": "sequence*", "children": [18446744073709551617]}]}})",
       C::SignedIn, 400, "children"},
      // Missions.
      {"GET", "/api/missions/svg", "", C::SignedIn, 400, "unknown mission ''"},
      // An unknown catalogue name is malformed (400, as the CLI's exit 2); a path is 404.
      {"GET", "/api/missions/svg?name=nope", "", C::SignedIn, 400, "unknown mission 'nope'"},
      {"GET", "/api/missions/svg?name=/etc/passwd", "", C::SignedIn, 404, "mission"},
      {"GET", "/api/missions/svg?name=" + own_bad_mission, "", C::SignedIn, 400, "line 1"},
      {"GET", "/api/missions/svg?name=" + own_folder, "", C::SignedIn, 400, "regular file"},
      // Runs.
      {"POST", "/api/runs", "{}", C::SignedIn, 400, "text"},
      {"POST", "/api/runs", R"({"text": ")" + kFsm + R"(", "seed": 1})", C::SignedIn, 400, "mission"},
      {"POST", "/api/runs", R"({"text": ")" + kFsm + R"(", "mission": "nope", "seed": 1})", C::SignedIn, 400, "unknown mission 'nope'"},
      {"POST", "/api/runs", R"({"text": ")" + kFsm + R"(", "mission": "aac", "seed": "x"})", C::SignedIn, 400, "seed"},
      {"POST", "/api/runs", R"({"text": ")" + kFsm + R"(", "mission": "aac", "seed": -1})", C::SignedIn, 400, "seed"},
      {"POST", "/api/runs", R"({"text": ")" + kFsm + R"(", "mission": "aac", "seed": 1.5})", C::SignedIn, 400, "seed"},
      {"POST", "/api/runs", R"({"text": "--fsm-config --nstates 9", "mission": "aac", "seed": 1})", C::SignedIn, 400,
       "--nstates"},
      {"POST", "/api/runs", R"({"text": ")" + kFsm + R"(", "mission": ")" + own_bad_mission + R"(", "seed": 1})",
       C::SignedIn, 400, "line 1"},
      {"GET", "/api/runs/999999/stream", "", C::SignedIn, 404, "run"},
      {"GET", "/api/runs/abc/stream", "", C::SignedIn, 404, "run"},
      // Projects.
      {"POST", "/api/projects", "{}", C::SignedIn, 400, "is missing"},
      {"POST", "/api/projects", "[1]", C::SignedIn, 400, "must be a JSON object"},
      {"POST", "/api/projects", R"({"name": "bad name", "mission": "aac", "budget": 1000})", C::SignedIn, 400,
       "bad name"},
      {"POST", "/api/projects", R"({"name": "p1", "mission": "aac", "budget": 1000})", C::SignedIn, 409, "p1"},
      {"POST", "/api/projects", R"({"name": "x", "mission": "nope", "budget": 1000})", C::SignedIn, 400, "unknown mission 'nope'"},
      {"POST", "/api/projects", R"({"name": "x", "mission": "aac", "budget": 0})", C::SignedIn, 400, "budget"},
      {"POST", "/api/projects", R"({"name": "x", "mission": "aac", "budget": "ten"})", C::SignedIn, 400, "budget"},
      {"POST", "/api/projects", R"({"name": "x", "mission": "aac", "budget": -3})", C::SignedIn, 400, "budget"},
      // A whole number stands for its text (text_field), so {"name": 7} is project "7"; a list is not.
      {"POST", "/api/projects", R"({"name": [7], "mission": "aac", "budget": 1000})", C::SignedIn, 400, "name must be text"},
      {"POST", "/api/projects", R"({"name": "x", "mission": "aac"})", C::SignedIn, 400, "budget"},
      {"GET", "/api/projects/nope/status", "", C::SignedIn, 404, "nope"},
      {"GET", "/api/projects/bobs-project/status", "", C::SignedIn, 404, "bobs-project"},
      {"GET", "/api/projects/nope/designs", "", C::SignedIn, 404, "nope"},
      {"GET", "/api/projects/nope/experiments", "", C::SignedIn, 404, "nope"},
      {"GET", "/api/projects/p1/experiments/nope/report", "", C::SignedIn, 404, "nope"},
      {"GET", "/api/projects/nope/software", "", C::SignedIn, 404, "nope"},
      {"POST", "/api/projects/p1/budget", "{}", C::SignedIn, 400, "budget"},
      {"POST", "/api/projects/p1/budget", R"({"budget": 0})", C::SignedIn, 400, "budget"},
      {"POST", "/api/projects/p1/budget", R"({"budget": "x"})", C::SignedIn, 400, "budget"},
      {"POST", "/api/projects/p1/budget", R"({"budget": 1e30})", C::SignedIn, 400, "budget"},
      {"POST", "/api/projects/nope/budget", R"({"budget": 10})", C::SignedIn, 404, "nope"},
      {"POST", "/api/projects/p1/designs", R"({"flavours": "nope"})", C::SignedIn, 400, "nope"},
      {"POST", "/api/projects/p1/designs", R"({"architectures": "nope"})", C::SignedIn, 400, "nope"},
      {"POST", "/api/projects/p1/designs", R"({"seed": "x"})", C::SignedIn, 400, "seed"},
      {"POST", "/api/projects/p1/designs", R"({"seed": -1})", C::SignedIn, 400, "seed"},
      {"POST", "/api/projects/p1/designs", R"({"fresh": "yes"})", C::SignedIn, 400, "fresh must be true or false"},
      {"POST", "/api/projects/p1/designs", "{", C::SignedIn, 400, "JSON"},
      {"POST", "/api/projects/nope/designs", "{}", C::SignedIn, 404, "nope"},
      {"POST", "/api/projects/p1/designs/stop", "{}", C::SignedIn, 409, "design"},
      {"POST", "/api/projects/nope/designs/stop", "{}", C::SignedIn, 404, "nope"},
      {"GET", "/api/design-space?architectures=nope", "", C::SignedIn, 400, "nope"},
      {"GET", "/api/design-space?flavours=nope", "", C::SignedIn, 400, "nope"},
      {"POST", "/api/projects/p1/software", "{}", C::SignedIn, 400, "is missing"},
      {"POST", "/api/projects/p1/software", R"({"name": "s"})", C::SignedIn, 400, "text"},
      {"POST", "/api/projects/p1/software", R"({"name": "../x", "text": ")" + kFsm + R"("})", C::SignedIn, 400, "../x"},
      {"POST", "/api/projects/p1/software", R"({"name": "s", "text": "--fsm-config --nstates 0"})", C::SignedIn, 400,
       "--nstates"},
      {"POST", "/api/projects/p1/software", R"({"name": [5], "text": ")" + kFsm + R"("})", C::SignedIn, 400, "name"},
      {"POST", "/api/projects/nope/software", R"({"name": "s", "text": ")" + kFsm + R"("})", C::SignedIn, 404, "nope"},
      {"GET", "/api/no-such-route", "", C::SignedIn, 404, "/api/no-such-route"},
  };
  return cases;
}

}  // namespace sd::test::bad_input
