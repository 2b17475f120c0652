#include "app/documents/reality.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace sd::app {

using json = nlohmann::json;

namespace {

/// JSON has no NaN: an undefined statistic is null.
json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

}  // namespace

json robot_model_document(const RobotModel& model) {
  json out = json::object();
  for (const RobotKnob& knob : kRobotKnobs) out[std::string(knob.name)] = model.*(knob.member);
  return out;
}

json assessment_document(const Assessment& a) {
  json software = json::array();
  for (const SoftwareAssessment& s : a.software) {
    json runs = json::array();
    for (std::size_t j = 0; j < a.seeds.size(); ++j) runs.push_back({{"sample", 0}, {"seed", a.seeds[j]}, {"score", s.design_scores[j]}});
    for (std::size_t k = 0; k < a.samples.size(); ++k)
      for (std::size_t j = 0; j < a.seeds.size(); ++j)
        runs.push_back({{"sample", a.samples[k]}, {"seed", a.seeds[j]}, {"score", s.reality_scores[k * a.seeds.size() + j]}});
    software.push_back({{"label", s.label},
                        {"control_software", s.configuration},
                        {"design_mean", s.design_mean},
                        {"pseudo_reality_mean", s.reality_mean},
                        {"drop", s.drop},
                        {"drop_ci95", {s.drop_low, s.drop_high}},
                        {"relative_drop", number_or_null(s.relative_drop)},
                        {"p_value", s.p_value},
                        {"design_rank", s.design_rank},
                        {"pseudo_reality_rank", s.reality_rank},
                        {"sample_ranks", s.sample_ranks},
                        {"runs", runs}});
  }
  json models = json::array();
  for (std::size_t k = 0; k < a.samples.size(); ++k) models.push_back({{"sample", a.samples[k]}, {"robot", robot_model_document(a.models[k])}});
  return {{"mission", a.mission},
          {"direction", a.direction},
          {"pseudo_reality", {{"name", a.spec_name}, {"reference", a.spec_reference}, {"digest", a.spec_digest}}},
          {"samples", a.samples},
          {"distinct_models", a.distinct_models},
          {"seeds", a.seeds},
          {"models", models},
          {"software", software},
          {"rank_correlation", number_or_null(a.rank_correlation)},
          {"inverted_pairs", a.inverted_pairs},
          {"pairs", a.pairs},
          {"seconds", a.seconds},
          {"reference", "Ligot & Birattari, Simulation-only experiments to mimic the effects of the reality gap in the "
                        "automatic design of robot swarms, Swarm Intelligence 14, 2020"}};
}

std::string assessment_csv(const Assessment& a) {
  std::ostringstream out;
  out.precision(17);  // every score's double, as the JSON keeps it
  out << "software,world,sample,seed,score\n";
  for (const auto& s : a.software) {
    const std::string label = "\"" + s.label + "\"";
    for (std::size_t j = 0; j < a.seeds.size(); ++j) out << label << ",design,0," << a.seeds[j] << "," << s.design_scores[j] << "\n";
    for (std::size_t k = 0; k < a.samples.size(); ++k)
      for (std::size_t j = 0; j < a.seeds.size(); ++j)
        out << label << ",pseudo-reality," << a.samples[k] << "," << a.seeds[j] << ","
            << s.reality_scores[k * a.seeds.size() + j] << "\n";
  }
  return out.str();
}

}  // namespace sd::app
