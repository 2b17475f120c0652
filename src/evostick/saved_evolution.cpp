#include "evostick/saved_evolution.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/bounded_file.hpp"
#include "core/durable_file.hpp"
#include "core/json_integer.hpp"
#include "evostick/weight_document.hpp"

namespace sd::evostick {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "swarmdesign-evostick-state";
constexpr int kFormatVersion = 1;

std::uint64_t digest_from_text(const std::string& text) {
  std::size_t used = 0;
  std::uint64_t value = 0;
  try {
    value = std::stoull(text, &used, 16);
  } catch (const std::logic_error&) {  // stoull's invalid_argument and out_of_range
    used = 0;
  }
  if (used == 0 || used != text.size()) throw std::invalid_argument("a digest is not 64-bit hexadecimal");
  return value;
}

/// An integer field, range-checked before it is converted (get_to on 1e300 is undefined).
template <class Int>
void integer_to(const json& value, Int& out, const char* what) {
  const auto read = json_integer<Int>(value);
  if (!read) throw std::invalid_argument(std::string(what) + " is not an integer it can hold");
  out = *read;
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
    int version = 0;
    integer_to(doc.at("version"), version, "version");
    if (version != kFormatVersion)
      throw std::runtime_error(file.string() + " has state format version " + doc.at("version").dump() +
                               "; this swarmdesign reads version " + std::to_string(kFormatVersion));
    SavedEvolution saved;
    EvolutionTarget& t = saved.target;
    doc.at("mission").get_to(t.mission);
    doc.at("mission_digest").get_to(t.mission_digest);
    doc.at("module").get_to(t.module);
    t.settings = settings_from_json(doc.at("settings"));
    integer_to(doc.at("results_version"), t.results_version, "results_version");
    Checkpoint& c = saved.checkpoint;
    integer_to(doc.at("generation"), c.generation, "generation");
    for (const json& w : doc.at("population")) c.population.push_back(w.get<arlequin::Weights>());
    const json& rng = doc.at("rng");
    const json& words = rng.at("s");
    if (!words.is_array() || words.size() != 4) throw std::invalid_argument("rng.s is not a list of four words");
    for (std::size_t i = 0; i < 4; ++i) integer_to(words.at(i), c.rng.s[i], "rng.s");
    integer_to(rng.at("coarse_bits"), c.rng.coarse_bits, "rng.coarse_bits");
    integer_to(rng.at("coarse_left"), c.rng.coarse_left, "rng.coarse_left");
    integer_to(doc.at("runs"), c.result.runs, "runs");
    for (const json& r : doc.at("history")) {
      GenerationRecord record{};
      integer_to(r.at("generation"), record.generation, "history.generation");
      record.best_mean = r.at("best_mean").get<double>();
      record.population_mean = r.at("population_mean").get<double>();
      record.best_digest = digest_from_text(r.at("best_digest").get<std::string>());
      c.result.history.push_back(record);
    }
    return saved;
  } catch (const json::exception& e) {
    throw std::runtime_error(file.string() + " is a damaged EvoStick state file (" + e.what() + ")");
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(file.string() + " is a damaged EvoStick state file (" + e.what() + ")");
  }
}

}  // namespace sd::evostick
