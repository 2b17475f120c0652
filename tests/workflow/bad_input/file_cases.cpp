// Each file format the CLI reads, malformed: mission files, experiment protocols, Arlequin
// module sets (folders of weight documents), EvoStick state documents, control-software
// documents (--config-file), start traces (--start-from) and design folders.
#include <fstream>

#include "workflow/bad_input/catalogue.hpp"
#include "test_paths.hpp"

namespace sd::test::bad_input {

namespace {
void write(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

const std::string kMissionHead =
    R"({"name": "bad", "title": "t", "origin": "o", "description": "d", "duration": 120, "robots": 20,)";

// Malformed mission documents: the file name and a phrase the error must contain.
const std::vector<std::pair<std::string, std::string>> kMissions{
    {"", "mission"},
    {"not json at all", "line 1"},
    {"{\"name\": \"bad\",", "line 1"},
    {"[1, 2, 3]", "object"},
    {"{}", "name"},
    {kMissionHead + R"("arena": {}})", "start: missing field"},
    {R"({"name": "bad", "robots": "twenty"})", "duration: missing field"},
    {R"({"name": 5})", "name"},
    {"\xff\xfe{\"name\": \"bad\"}", "line 1"},
    {R"({"name": "bad\u0000x"})", "duration: missing field"},
};

const std::vector<std::pair<std::string, std::string>> kProtocols{
    {"", "protocol"},
    {"{", "line 1"},
    {"[]", "object"},
    {"{}", "name"},
    {R"({"name": "p"})", "missions"},
    {R"({"name": "p", "missions": []})", "missions"},
    {R"({"name": "bad name", "missions": [{"mission": "aac", "budget": 1000, "conditions": [{"name": "c", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})",
     "bad name"},
    {R"({"name": "p", "designs": 0, "missions": [{"mission": "aac", "budget": 1000, "conditions": [{"name": "c", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})",
     "designs"},
    {R"({"name": "p", "missions": [{"mission": "nope", "budget": 1000, "conditions": [{"name": "c", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})", "nope"},
    {R"({"name": "p", "missions": [{"mission": "aac", "budget": -1, "conditions": [{"name": "c", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})", "budget"},
    {R"({"name": "p", "missions": [{"mission": "aac", "budget": "x", "conditions": [{"name": "c", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})", "budget"},
    {R"({"name": "p", "missions": [{"mission": "aac", "budget": 1000, "conditions": []}]})", "conditions"},
    {R"({"name": "p", "missions": [{"mission": "aac", "budget": 1000, "conditions": [{"name": "c", "architectures": ["fsm"], "flavours": ["nope"]}]}]})",
     "nope"},
    {R"({"name": "p", "missions": [{"mission": "aac", "budget": 1000, "conditions": [{"name": "c", "architectures": ["nope"]}]}]})",
     "nope"},
    {R"({"name": "p", "missions": [{"mission": "aac", "budget": 1000, "conditions": [{"name": "c", "method": "nope"}]}]})",
     "nope"},
    {R"({"name": "p", "missions": [{"mission": "aac", "budget": 1000, "conditions": [{"name": "c", "architectures": ["fsm"], "flavours": ["chocolate"]}, {"name": "c", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})",
     "c"},
};

// Malformed pseudo-reality specifications (assess --pseudo-reality, design --pseudo-reality).
const std::vector<std::pair<std::string, std::string>> kPseudoRealities{
    {"", "line 1"},
    {"[]", "document: expected an object"},
    {R"({"knobs": {"wheel_noise": -0.5}})", "knobs.wheel_noise: must not be negative"},
    {R"({"knobs": {"rab_loss": 1.5}})", "knobs.rab_loss: must be in [0, 1]"},
    {R"({"knobs": {"rab_loss": {"uniform": [0.2, 1.1]}}})", "knobs.rab_loss.uniform[1]: must be in [0, 1]"},
    {R"({"knobs": {"teleport_noise": 0.1}})", "knobs.teleport_noise: unknown knob"},
    {R"({"knobs": {"light_noise": {"around": -1}}})", "knobs.light_noise.around"},
};

const std::vector<std::pair<std::string, std::string>> kStates{
    {"", "is not an EvoStick state file"},
    {"garbage", "is not an EvoStick state file"},
    {"{}", "is not an EvoStick state file"},
    {"[1]", "is not an EvoStick state file"},
};

const std::vector<std::pair<std::string, std::string>> kConfigFiles{
    {"", "empty control software"},
    {"hello world", "hello"},
    {"--fsm-config --nstates 1 --s0 0 --rwm0 50 junk", "junk"},
    {"--fsm-config --nstates \xff", "nstates"},
    {"--fsm-config\n--nstates 1 --s0 0 --rwm0 5x", "5x"},
};

// Malformed start traces (evaluate --start-from) and what the error names.
std::string start_rows(int robots, const std::string& first = "") {
  std::string text = "tick,robot,x,y,yaw\n";
  for (int r = 0; r < robots; ++r)
    text += r == 0 && !first.empty() ? first + "\n" : "0,epuck" + std::to_string(r) + ",0." + std::to_string(r % 10) + ",0.1,0\n";
  return text;
}
const std::vector<std::pair<std::string, std::string>> kStartTraces{
    {"", "empty"},
    {"tick,robot,x,y\n0,epuck0,0,0\n", "no column 'yaw'"},
    {start_rows(19), "19 robots at tick 0; the mission has 20"},
    {start_rows(20, "0,epuck20,0,0,0"), "'epuck20' is no robot"},
    {start_rows(20, "0,epuck1,0,0,0"), "appears twice"},
    {start_rows(20, "0,epuck0,abc,0,0"), "finite numbers"},
    {start_rows(20, "0,epuck0,1e300,0,0"), "beyond 10 m"},
    {start_rows(20, "0,epuck0,0"), "line 2 has 3 fields"},
};

const char* kArlequinModules[] = {"exploration", "stop", "phototaxis", "antiphototaxis", "attraction", "repulsion"};

std::filesystem::path numbered(const std::filesystem::path& folder, const std::string& stem, std::size_t i) {
  return folder / (stem + std::to_string(i) + ".json");
}
}  // namespace

void write_bad_files(const Inputs& in) {
  for (std::size_t i = 0; i < kMissions.size(); ++i) write(numbered(in.files, "mission", i), kMissions[i].first);
  write(in.files / "huge-mission.json", "{\"name\": \"" + std::string(2 << 20, 'x') + "\"}");
  for (std::size_t i = 0; i < kProtocols.size(); ++i) write(numbered(in.files, "protocol", i), kProtocols[i].first);
  for (std::size_t i = 0; i < kStates.size(); ++i) write(numbered(in.files, "state", i), kStates[i].first);
  for (std::size_t i = 0; i < kPseudoRealities.size(); ++i) write(numbered(in.files, "reality", i), kPseudoRealities[i].first);
  for (std::size_t i = 0; i < kConfigFiles.size(); ++i) write(numbered(in.files, "config", i), kConfigFiles[i].first);
  for (std::size_t i = 0; i < kStartTraces.size(); ++i) write(numbered(in.files, "start", i), kStartTraces[i].first);
  // Arlequin module sets: one weight document missing, one malformed, one of the wrong size.
  const std::filesystem::path shipped = std::filesystem::path(::sd::test::source_dir()) / "data" / "arlequin";
  for (const char* set : {"set-missing", "set-garbage", "set-short"}) {
    std::filesystem::create_directories(in.files / set);
    for (const char* module : kArlequinModules)
      std::filesystem::copy_file(shipped / (std::string(module) + ".json"), in.files / set / (std::string(module) + ".json"));
  }
  std::filesystem::remove(in.files / "set-missing" / "stop.json");
  write(in.files / "set-garbage" / "stop.json", "{ not json");
  write(in.files / "set-short" / "stop.json", R"({"weights": [1, 2, 3]})");
  // Design folders: empty, and with a file where the checkpoint would be.
  std::filesystem::create_directories(in.files / "empty-design");
  write(in.files / "garbage-design" / "design.db", "not a database");
}

std::vector<CliCase> file_cases(const Inputs& in) {
  const std::vector<std::string> fsm{"--fsm-config", "--nstates", "1", "--s0", "0", "--rwm0", "50"};
  std::vector<CliCase> cases;
  const auto evaluate = [&](std::vector<std::string> args) {
    args.insert(args.end(), fsm.begin(), fsm.end());
    return args;
  };
  // A mission file is read by set-mission, evaluate, mission show, design and irace-export.
  for (std::size_t i = 0; i < kMissions.size(); ++i) {
    const std::string file = numbered(in.files, "mission", i).string();
    const std::string phrase = kMissions[i].second;
    cases.push_back({{"set-mission", file}, "", 2, phrase});
    cases.push_back({evaluate({"evaluate", "--mission", file}), "", 2, phrase});
    cases.push_back({{"mission", "show", file, "--json"}, "", 2, phrase});
  }
  const std::string huge = (in.files / "huge-mission.json").string();
  for (const std::string& file : {huge, std::string("/dev/zero"), in.files.string(), (in.files / "absent.json").string()}) {
    const std::string phrase = file == huge ? "larger than 1 MiB" : file;
    cases.push_back({{"set-mission", file}, "", 2, phrase});
    cases.push_back({evaluate({"evaluate", "--mission", file}), "", 2, phrase});
    cases.push_back({{"design", "--mission", file, "--budget", "1000", "--out", (in.scratch / "d").string()}, "", 2, phrase});
    cases.push_back({{"irace-export", "--mission", file, "--out", (in.scratch / "i").string()}, "", 2, phrase});
    cases.push_back({{"mission", "export-argos", file, "--out", (in.scratch / "x.argos").string()}, "", 2, phrase});
  }
  for (std::size_t i = 0; i < kProtocols.size(); ++i)
    cases.push_back({{"experiment", "--file", numbered(in.files, "protocol", i).string(), "--dry-run"}, "", 2,
                     kProtocols[i].second});
  for (std::size_t i = 0; i < kPseudoRealities.size(); ++i) {
    const std::string file = numbered(in.files, "reality", i).string();
    cases.push_back({evaluate({"assess", "--mission", "aac", "--pseudo-reality", file}), "", 2, kPseudoRealities[i].second});
    cases.push_back({{"pseudo-realities", file}, "", 2, kPseudoRealities[i].second});
    cases.push_back({{"design", "--mission", "aac", "--budget", "2000", "--fsm", "--chocolate", "--pseudo-reality", file,
                      "--out", (in.scratch / "d").string()}, "", 2, kPseudoRealities[i].second});
  }
  for (const std::string& file : {std::string("/dev/zero"), (in.files / "absent.json").string()}) {
    cases.push_back({evaluate({"assess", "--mission", "aac", "--pseudo-reality", file}), "", 2, file});
    cases.push_back({{"mission", "export-argos", "aac", "--out", (in.scratch / "x.argos").string(), "--pseudo-reality", file,
                      "--sample", "1"}, "", 2, file});
  }
  for (std::size_t i = 0; i < kStates.size(); ++i)
    // A state file is stored work, like a design folder: a damaged one is a refusal (1).
    cases.push_back({{"evostick", "--resume", numbered(in.files, "state", i).string()}, "", 1, kStates[i].second});
  for (std::size_t i = 0; i < kConfigFiles.size(); ++i) {
    const std::string file = numbered(in.files, "config", i).string();
    cases.push_back({{"show-config", "--config-file", file}, "", 2, kConfigFiles[i].second});
    cases.push_back({{"evaluate", "--mission", "aac", "--config-file", file}, "", 2, kConfigFiles[i].second});
  }
  for (const std::string& file : {std::string("/dev/zero"), in.files.string(), (in.files / "absent.txt").string()}) {
    cases.push_back({{"show-config", "--config-file", file}, "", 2, file});
    cases.push_back({{"test-design", "--config-file", file}, "", 2, file});
  }
  cases.push_back({evaluate({"show-config", "--config-file", numbered(in.files, "config", 1).string()}), "", 2, "not both"});
  for (std::size_t i = 0; i < kStartTraces.size(); ++i)
    cases.push_back({evaluate({"evaluate", "--mission", "aac", "--start-from", numbered(in.files, "start", i).string()}),
                     "", 2, kStartTraces[i].second});
  for (const std::string& file : {std::string("/dev/zero"), (in.files / "absent.csv").string()})
    cases.push_back({evaluate({"evaluate", "--mission", "aac", "--start-from", file}), "", 2, file});
  for (const char* set : {"set-missing", "set-garbage", "set-short"})
    cases.push_back({evaluate({"evaluate", "--mission", "aac", "--arlequin-modules", (in.files / set).string()}), "", 2,
                     "stop"});
  for (const char* design : {"empty-design", "garbage-design"}) {
    const std::string folder = (in.files / design).string();
    cases.push_back({{"design-status", folder}, "", 1, folder});
    cases.push_back({{"design", "--resume", folder}, "", 1, folder});
  }
  return cases;
}

}  // namespace sd::test::bad_input
