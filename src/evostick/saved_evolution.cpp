#include "evostick/saved_evolution.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/bounded_file.hpp"
#include "core/durable_file.hpp"
#include "evostick/weight_document.hpp"

namespace sd::evostick {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "swarmdesign-evostick-state";
constexpr int kFormatVersion = 1;

std::uint64_t digest_from_text(const std::string& text) {
  std::size_t used = 0;
  const std::uint64_t value = std::stoull(text, &used, 16);
  if (used != text.size()) throw std::invalid_argument("digest");
  return value;
}

}  // namespace

void write_saved_evolution(const std::filesystem::path& file, const EvolutionTarget& target, const Checkpoint& c) {
  json population = json::array();
  for (const arlequin::Weights& w : c.population) population.push_back(w);
  const json doc{{"format", kFormat},
                 {"version", kFormatVersion},
                 {"mission", target.mission},
                 {"mission_digest", target.mission_digest},
                 {"module", target.module},
                 {"settings", settings_json(target.settings)},
                 {"results_version", target.results_version},
                 {"generation", c.generation},
                 {"population", std::move(population)},
                 {"rng", {{"s", c.rng.s}, {"coarse_bits", c.rng.coarse_bits}, {"coarse_left", c.rng.coarse_left}}},
                 {"runs", c.result.runs},
                 {"history", history_json(c.result.history)}};
  replace_file_durably(file, doc.dump() + '\n', 0666, Umask::Applies);  // like any file the user writes
}

SavedEvolution read_saved_evolution(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw std::runtime_error("there is no EvoStick state file " + file.string());
  // A population of a thousand networks is under 1 MiB of text; 64 MiB leaves room for any.
  const std::string text = read_bounded_file(file, "EvoStick state file", std::size_t{64} << 20).text;
  const json doc = json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || doc.value("format", "") != kFormat)
    throw std::runtime_error(file.string() + " is not an EvoStick state file (it may be damaged)");
  try {
    if (doc.at("version").get<int>() != kFormatVersion)
      throw std::runtime_error(file.string() + " has state format version " + doc.at("version").dump() +
                               "; this swarmdesign reads version " + std::to_string(kFormatVersion));
    SavedEvolution saved;
    EvolutionTarget& t = saved.target;
    doc.at("mission").get_to(t.mission);
    doc.at("mission_digest").get_to(t.mission_digest);
    doc.at("module").get_to(t.module);
    t.settings = settings_from_json(doc.at("settings"));
    doc.at("results_version").get_to(t.results_version);
    Checkpoint& c = saved.checkpoint;
    doc.at("generation").get_to(c.generation);
    for (const json& w : doc.at("population")) c.population.push_back(w.get<arlequin::Weights>());
    const json& rng = doc.at("rng");
    rng.at("s").get_to(c.rng.s);
    rng.at("coarse_bits").get_to(c.rng.coarse_bits);
    rng.at("coarse_left").get_to(c.rng.coarse_left);
    doc.at("runs").get_to(c.result.runs);
    for (const json& r : doc.at("history"))
      c.result.history.push_back({r.at("generation").get<int>(), r.at("best_mean").get<double>(),
                                  r.at("population_mean").get<double>(),
                                  digest_from_text(r.at("best_digest").get<std::string>())});
    return saved;
  } catch (const json::exception& e) {
    throw std::runtime_error(file.string() + " is a damaged EvoStick state file (" + e.what() + ")");
  } catch (const std::invalid_argument&) {
    throw std::runtime_error(file.string() + " is a damaged EvoStick state file (a digest is not hexadecimal)");
  }
}

}  // namespace sd::evostick
