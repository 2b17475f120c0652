#include "app/experiment_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

#include "app/control_software_document.hpp"
#include "app/design_method.hpp"
#include "app/errors.hpp"
#include "app/experiment_job.hpp"
#include "app/reality_gap.hpp"
#include "control/config_string.hpp"
#include "core/json_integer.hpp"
#include "core/markup_text.hpp"
#include "design/design_space.hpp"
#include "evaluation/results_version.hpp"
#include "experiments/protocol.hpp"
#include "missions/catalogue.hpp"
#include "statistics/box_stats.hpp"
#include "statistics/descriptive.hpp"
#include "statistics/expected_ranks.hpp"
#include "statistics/mean_interval.hpp"
#include "statistics/rank_sum.hpp"
#include "statistics/ranks.hpp"
#include "statistics/signed_rank.hpp"
#include "storage/clock.hpp"
#include "storage/design_status.hpp"
#include "storage/experiments.hpp"
#include "storage/projects.hpp"

#ifndef SWARMDESIGN_VERSION
#define SWARMDESIGN_VERSION "dev"
#endif

namespace sd::app {

using nlohmann::json;

namespace {

/// Significance level of the per-mission tests and of the Friedman post-hoc.
constexpr double kAlpha = 0.05;

const char* architecture_name(Architecture a) {
  switch (a) {
    case Architecture::Fsm: return "fsm";
    case Architecture::BehaviourTree: return "bt";
    case Architecture::NeuralNetwork: return "nn";
  }
  return "fsm";
}

/// The distinct behaviour and condition modules a control software uses.
std::pair<std::set<int>, std::set<int>> modules_used(const ControlSoftware& software) {
  std::set<int> behaviours, conditions;
  if (software.architecture == Architecture::Fsm) {
    for (const auto& state : software.fsm.states) {
      behaviours.insert(state.behaviour.id);
      for (const auto& t : state.transitions) conditions.insert(t.condition.id);
    }
  } else if (software.architecture == Architecture::BehaviourTree) {
    for (const auto& node : software.bt.nodes) {
      if (node.type == BtNodeType::Action) behaviours.insert(node.module.id);
      if (node.type == BtNodeType::Condition) conditions.insert(node.module.id);
    }
  }
  return {behaviours, conditions};
}

struct MissionInfo {
  std::string key;  // its name in the report
  bool maximise = true;
  json document;
};

/// A design's score in one world: the design model's (its assessment) or the pseudo-realities'.
using ScoreOf = double (*)(const json&);
double design_model_score(const json& d) { return d["score"].get<double>(); }
double pseudo_reality_score(const json& d) { return d["pseudo_reality"]["score"].get<double>(); }

/// One (mission, condition) cell: its finished designs, in replicate order.
struct Cell {
  std::vector<const json*> designs;
  std::vector<double> scores(ScoreOf of = design_model_score) const {
    std::vector<double> s;
    for (const json* d : designs) s.push_back(of(*d));
    return s;
  }
};

json box_document(const std::string& mission, const std::string& condition, const std::vector<double>& values) {
  const statistics::BoxStats b = statistics::box_stats(values);
  return {{"mission", mission},         {"condition", condition},       {"n", b.n},
          {"min", b.min},               {"q1", b.q1},                   {"median", b.median},
          {"q3", b.q3},                 {"max", b.max},                 {"whisker_low", b.whisker_low},
          {"whisker_high", b.whisker_high}, {"notch_low", b.notch_low}, {"notch_high", b.notch_high},
          {"outliers", b.outliers},     {"values", values}};
}

/// Which condition of a significant pair is better: the one with the better median.
json better_of(const std::string& a, const std::string& b, double median_a, double median_b, bool maximise, double p) {
  if (!(p < kAlpha) || median_a == median_b) return nullptr;
  return (median_a > median_b) == maximise ? a : b;
}

/// A design in the pseudo-realities: its scores per sample and seed, their mean, and the drop
/// from the design model with its 95 % interval and paired test over the seeds (the design-model
/// score against the mean over the samples with that seed), as app/assess_job computes them.
/// Null when the protocol asked for no pseudo-reality.
json reality_document(const std::vector<storage::RealityScore>& reality, const std::vector<std::uint64_t>& seeds,
                      const std::vector<double>& design_scores, bool maximise) {
  if (reality.empty() || seeds.empty()) return nullptr;
  std::vector<double> scores, by_seed(seeds.size(), 0.0);
  std::vector<int> count(seeds.size(), 0);
  std::set<std::uint64_t> samples;
  for (const storage::RealityScore& r : reality) {
    scores.push_back(r.score);
    samples.insert(r.sample);
    const auto at = std::find(seeds.begin(), seeds.end(), r.seed);
    if (at == seeds.end()) continue;
    by_seed[static_cast<std::size_t>(at - seeds.begin())] += r.score;
    ++count[static_cast<std::size_t>(at - seeds.begin())];
  }
  for (std::size_t j = 0; j < seeds.size(); ++j) by_seed[j] /= std::max(1, count[j]);
  const RealityGap g = reality_gap(design_scores, by_seed, statistics::mean(scores), maximise);
  return {{"samples", samples.size()},
          {"scores", scores},
          {"score", g.reality_mean},
          {"by_seed", by_seed},
          {"drop", g.drop},
          {"drop_ci95", {g.drop_low, g.drop_high}},
          {"relative_drop", g.design_mean != 0.0 ? json(g.relative_drop) : json(nullptr)},
          {"p_value", g.p_value}};
}

json design_document(const storage::ExperimentDesign& d, const std::string& mission, bool maximise,
                     storage::Experiments& store) {
  const ControlSoftware software = parse_control_software(*d.configuration);
  const auto [behaviours, conditions] = modules_used(software);
  std::vector<std::uint64_t> seeds;
  std::vector<double> scores;
  for (const auto& [seed, score] : store.assessments(d.id)) {
    seeds.push_back(seed);
    scores.push_back(score);
  }
  // The design's own record in its folder, whatever its method; a reused design's is its twin's.
  json convergence = json::array();
  const auto folder = d.reused_from ? store.design(*d.reused_from).folder : d.folder;
  for (const auto& p : design_method(d.plan.method).convergence(folder)) convergence.push_back({p.runs_used, p.best_score});
  json reality = reality_document(store.reality_assessments(d.id), seeds, scores, maximise);
  return {{"id", d.id},
          {"pseudo_reality", std::move(reality)},
          {"mission", mission},
          {"condition", d.plan.condition},
          {"replicate", d.plan.replicate},
          {"seed", d.plan.seed},
          {"budget", d.plan.budget},
          {"runs_used", d.runs_used.value_or(0)},
          {"wall_seconds", d.wall_seconds},
          {"architecture", architecture_name(software.architecture)},
          {"configuration", *d.configuration},
          {"model", software_document(software)},
          {"modules", {{"behaviours", behaviours}, {"conditions", conditions}}},
          {"design_score", d.design_score.value_or(0.0)},
          {"reused_from", d.reused_from ? json(*d.reused_from) : json(nullptr)},
          {"scores", scores},
          {"assessment_seeds", seeds},
          {"score", statistics::mean(scores)},  // a done design has >= 1 assessment: never empty
          {"convergence", std::move(convergence)}};
}

struct Analysis {
  std::vector<MissionInfo> missions;
  std::vector<std::string> conditions;
  std::map<std::pair<std::string, std::string>, Cell> cells;  // (mission, condition)
  const Cell* cell(const std::string& m, const std::string& c) const {
    const auto found = cells.find({m, c});
    return found == cells.end() || found->second.designs.empty() ? nullptr : &found->second;
  }
};

json boxes_and_tests(const Analysis& a, json& report) {
  json boxes = json::array(), wilcoxon = json::array();
  for (const MissionInfo& m : a.missions) {
    for (const auto& c : a.conditions)
      if (const Cell* cell = a.cell(m.key, c)) boxes.push_back(box_document(m.key, c, cell->scores()));
    for (std::size_t i = 0; i < a.conditions.size(); ++i)
      for (std::size_t j = i + 1; j < a.conditions.size(); ++j) {
        const Cell* x = a.cell(m.key, a.conditions[i]);
        const Cell* y = a.cell(m.key, a.conditions[j]);
        if (!x || !y) continue;
        const auto sx = x->scores(), sy = y->scores();
        const statistics::RankSumTest t = statistics::wilcoxon_rank_sum(sx, sy);
        wilcoxon.push_back({{"mission", m.key},
                            {"a", a.conditions[i]},
                            {"b", a.conditions[j]},
                            {"n_a", sx.size()},
                            {"n_b", sy.size()},
                            {"W", t.statistic},
                            {"p_value", t.p_value},
                            {"exact", t.exact},
                            {"better", better_of(a.conditions[i], a.conditions[j], statistics::median(sx),
                                                 statistics::median(sy), m.maximise, t.p_value)}});
      }
  }
  report["wilcoxon"] = std::move(wilcoxon);
  return boxes;
}

/// Friedman across missions over the conditions that every mission has.
json friedman_document(const Analysis& a, ScoreOf of = design_model_score) {
  std::vector<std::string> common;
  for (const auto& c : a.conditions)
    if (std::all_of(a.missions.begin(), a.missions.end(), [&](const MissionInfo& m) { return a.cell(m.key, c); }))
      common.push_back(c);
  if (a.missions.size() < 2 || common.size() < 2) return nullptr;
  std::vector<std::vector<double>> values;
  std::vector<bool> maximise;
  json blocks = json::array();
  for (const MissionInfo& m : a.missions) {
    std::vector<double> row;
    row.reserve(row.size() + common.size());
    for (const auto& c : common) row.push_back(statistics::median(a.cell(m.key, c)->scores(of)));
    values.push_back(std::move(row));
    maximise.push_back(m.maximise);
    blocks.push_back(m.key);
  }
  const statistics::ExpectedRanks r = statistics::expected_ranks(values, maximise, 1.0 - kAlpha);
  json ranks = json::array();
  for (std::size_t i = 0; i < common.size(); ++i) ranks.push_back({{"condition", common[i]}, {"rank", r.mean_ranks[i]}});
  return {{"blocks", blocks},
          {"conditions", common},
          {"statistic", r.statistic},
          {"df", r.df},
          {"p_value", r.p_value},
          {"expected_ranks", ranks},
          {"critical_difference", r.critical_difference ? json(*r.critical_difference) : json(nullptr)}};
}

/// Conditions ranked on one mission by their median design score, 1 = best (ties share the
/// average rank).
std::vector<double> condition_ranks(const std::vector<double>& medians, bool maximise) {
  std::vector<double> keys(medians.size());
  for (std::size_t i = 0; i < medians.size(); ++i) keys[i] = maximise ? -medians[i] : medians[i];
  return statistics::average_ranks(keys);
}

/// The reality gap as the experiment shows it (Ligot & Birattari 2020): per mission and
/// condition the designs' scores in the design model and in the pseudo-realities side by side,
/// the drop with a paired Wilcoxon signed-rank test over the designs, and how the conditions'
/// ranks change from one world to the other. Null when the protocol asked for no pseudo-reality.
json pseudo_reality_document(const Analysis& all, const experiments::Protocol& protocol) {
  if (!protocol.pseudo_reality) return nullptr;
  const auto& plan = *protocol.pseudo_reality;
  // Only the designs assessed in the pseudo-realities.
  Analysis a{all.missions, all.conditions, {}};
  for (const auto& [key, cell] : all.cells)
    for (const json* d : cell.designs)
      if (!(*d)["pseudo_reality"].is_null()) a.cells[key].designs.push_back(d);
  json cells = json::array(), ranks = json::array(), inversions = json::array();
  for (const MissionInfo& m : a.missions) {
    std::vector<std::string> present;
    std::vector<double> design_medians, reality_medians;
    for (const auto& c : a.conditions) {
      const Cell* cell = a.cell(m.key, c);
      if (!cell) continue;
      const std::vector<double> design = cell->scores(), reality = cell->scores(pseudo_reality_score);
      std::vector<double> drops;
      int dropping = 0;
      for (const json* d : cell->designs) {
        const json& r = (*d)["pseudo_reality"];
        drops.push_back(r["drop"].get<double>());
        if (r["drop"].get<double>() > 0.0 && r["p_value"].get<double>() < kAlpha) ++dropping;
      }
      const bool all_equal = std::equal(design.begin(), design.end(), reality.begin());
      json test = nullptr;
      if (!all_equal) {
        const statistics::SignedRankTest t = statistics::wilcoxon_signed_rank(design, reality);
        test = {{"V", t.statistic}, {"p_value", t.p_value}, {"exact", t.exact}};
      }
      cells.push_back({{"mission", m.key},
                       {"condition", c},
                       {"n", design.size()},
                       {"design_model", box_document(m.key, c, design)},
                       {"pseudo_reality", box_document(m.key, c, reality)},
                       {"median_drop", statistics::median(drops)},
                       {"designs_dropping", dropping},
                       {"wilcoxon", std::move(test)}});
      present.push_back(c);
      design_medians.push_back(statistics::median(design));
      reality_medians.push_back(statistics::median(reality));
    }
    const std::vector<double> before = condition_ranks(design_medians, m.maximise);
    const std::vector<double> after = condition_ranks(reality_medians, m.maximise);
    for (std::size_t i = 0; i < present.size(); ++i) {
      ranks.push_back({{"mission", m.key},
                       {"condition", present[i]},
                       {"design_model_median", design_medians[i]},
                       {"pseudo_reality_median", reality_medians[i]},
                       {"design_model_rank", before[i]},
                       {"pseudo_reality_rank", after[i]}});
      for (std::size_t j = i + 1; j < present.size(); ++j)
        if ((design_medians[i] - design_medians[j]) * (reality_medians[i] - reality_medians[j]) < 0.0)
          inversions.push_back({{"mission", m.key}, {"a", present[i]}, {"b", present[j]},
                                {"better_in_design_model", (design_medians[i] > design_medians[j]) == m.maximise ? present[i] : present[j]}});
    }
  }
  const json definition = plan.definition.empty() ? json(nullptr) : json::parse(plan.definition);
  return {{"spec", plan.spec},
          {"name", definition.is_object() ? definition.value("name", plan.spec) : plan.spec},
          {"description", definition.is_object() ? definition.value("description", "") : ""},
          {"samples", plan.samples},
          {"definition", definition},
          {"cells", std::move(cells)},
          {"ranks", std::move(ranks)},
          {"inversions", std::move(inversions)},
          {"friedman", {{"design_model", friedman_document(a)}, {"pseudo_reality", friedman_document(a, pseudo_reality_score)}}},
          {"reference", "Ligot & Birattari, Simulation-only experiments to mimic the effects of the reality gap in the "
                        "automatic design of robot swarms, Swarm Intelligence 14, 2020"}};
}

json module_frequency(const Analysis& a) {
  json rows = json::array();
  for (const auto& c : a.conditions) {
    // Per mission, then over all the condition's missions ("*").
    std::vector<std::pair<std::string, std::vector<const json*>>> groups;
    std::vector<const json*> all;
    for (const MissionInfo& m : a.missions)
      if (const Cell* cell = a.cell(m.key, c)) {
        groups.emplace_back(m.key, cell->designs);
        all.insert(all.end(), cell->designs.begin(), cell->designs.end());
      }
    if (groups.size() > 1) groups.emplace_back("*", all);
    for (const auto& [mission, designs] : groups)
      for (const auto& [kind, key, module_kind] :
           {std::tuple{"behaviour", "behaviours", ModuleKind::Behaviour}, std::tuple{"condition", "conditions", ModuleKind::Condition}}) {
        std::map<int, int> with;
        for (const json* d : designs)
          for (const int id : (*d)["modules"][key]) ++with[id];
        for (const auto& [id, count] : with) {
          const ModuleSpec* spec = find_module(module_kind, id);
          rows.push_back({{"condition", c},
                          {"mission", mission},
                          {"kind", kind},
                          {"flavour", flavour_name(static_cast<Flavour>(id / 10))},
                          {"module", id},
                          {"name", spec ? spec->name : "?"},
                          {"designs_with", count},
                          {"designs", designs.size()},
                          {"fraction", static_cast<double>(count) / static_cast<double>(designs.size())}});
        }
      }
  }
  return rows;
}

void per_cell_tables(const Analysis& a, json& report) {
  json architectures = json::array(), wall = json::array(), typical = json::array();
  for (const MissionInfo& m : a.missions)
    for (const auto& c : a.conditions) {
      const Cell* cell = a.cell(m.key, c);
      if (!cell) continue;
      std::map<std::string, int> chosen{{"fsm", 0}, {"bt", 0}, {"nn", 0}};
      double seconds = 0.0;
      std::int64_t runs = 0;
      for (const json* d : cell->designs) {
        ++chosen[(*d)["architecture"].get<std::string>()];
        seconds += (*d)["wall_seconds"].get<double>();
        runs += checked_json_integer<std::int64_t>((*d)["runs_used"], "experiment results: runs_used") + static_cast<std::int64_t>((*d)["scores"].size());
      }
      architectures.push_back({{"mission", m.key}, {"condition", c}, {"fsm", chosen["fsm"]}, {"bt", chosen["bt"]},
                               {"nn", chosen["nn"]}});
      wall.push_back({{"mission", m.key}, {"condition", c}, {"designs", cell->designs.size()}, {"runs", runs},
                      {"wall_seconds", seconds}});
      // The best design, and the median one (the worse of the two middle ones for an even count).
      std::vector<const json*> order = cell->designs;
      std::stable_sort(order.begin(), order.end(), [&](const json* x, const json* y) {
        const double sx = (*x)["score"].get<double>(), sy = (*y)["score"].get<double>();
        return m.maximise ? sx > sy : sx < sy;
      });
      typical.push_back({{"mission", m.key},
                         {"condition", c},
                         {"best", (*order.front())["id"]},
                         {"median", (*order[order.size() / 2])["id"]}});
    }
  report["architectures"] = std::move(architectures);
  report["wall_time"] = std::move(wall);
  report["typical"] = std::move(typical);
}

// ---- CSV ----

std::string csv_cell(const json& v) {
  if (v.is_null()) return "";
  if (v.is_number_float()) {
    if (!std::isfinite(v.get<double>())) return "";  // R's NA: an empty cell
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v.get<double>());
    return text;
  }
  if (v.is_string()) {
    std::string s = v.get<std::string>();
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string quoted = "\"";
    for (const char ch : s) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return quoted + "\"";
  }
  return v.dump();
}

std::string csv_text(const std::vector<std::string>& columns, const json& rows) {
  std::ostringstream out;
  for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
  out << "\n";
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << csv_cell(row.value(columns[i], json(nullptr)));
    out << "\n";
  }
  return out.str();
}

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw std::runtime_error("the report page's bundle is missing: " + file.string() +
                             " (build the front end: cmake --build build --target frontend)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Text that may sit inside <script> or <style>: "</" cannot end the element early.
std::string inert_in_element(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}


}  // namespace

json experiment_report_document(Home& home, const storage::User& user, const std::string& name,
                                const std::optional<std::string>& project) {
  storage::Projects projects(home.workspace(), user);
  const storage::Project p = project ? projects.get(*project) : projects.require_active();
  storage::Experiments store(home.workspace(), p);
  const storage::Experiment e = store.get(name);
  const experiments::Protocol protocol = experiments::protocol_from_json(json::parse(e.protocol));
  const auto designs = store.designs(e.id);

  Analysis a;
  json report;
  json design_list = json::array();
  json conditions = json::array();
  std::map<std::string, json> per_mission_spaces;  // condition -> {mission: space}
  std::map<std::string, std::string> methods;
  std::map<std::string, std::string> keys;  // mission reference -> its name in the report
  for (const auto& d : designs) {
    if (!keys.count(d.plan.mission)) {
      // Two mission files of the same file name keep their full references apart.
      std::string key = mission_label(d.plan.mission);
      if (std::any_of(keys.begin(), keys.end(), [&](const auto& k) { return k.second == key; })) key = d.plan.mission;
      keys[d.plan.mission] = key;
      const Mission mission = load_mission(d.plan.mission);
      const bool maximise = mission.objective.direction == Direction::Maximize;
      a.missions.push_back({key, maximise,
                            {{"name", key},
                             {"reference", d.plan.mission},
                             {"title", mission.title},
                             {"direction", maximise ? "maximise" : "minimise"},
                             {"budget", d.plan.budget},
                             {"description", mission.description}}});
    }
    if (std::find(a.conditions.begin(), a.conditions.end(), d.plan.condition) == a.conditions.end())
      a.conditions.push_back(d.plan.condition);
    methods[d.plan.condition] = d.plan.method;
    const std::string& mission = keys[d.plan.mission];
    per_mission_spaces[d.plan.condition][mission] = {{"architectures", design::split_list(d.plan.architectures)},
                                                            {"flavours", design::split_list(d.plan.flavours)},
                                                            {"budget", d.plan.budget}};
    if (d.stage == storage::DesignStage::done) {
      const bool maximise =
          std::find_if(a.missions.begin(), a.missions.end(), [&](const MissionInfo& m) { return m.key == mission; })->maximise;
      design_list.push_back(design_document(d, mission, maximise, store));
    }
  }
  for (const auto& d : design_list) a.cells[{d["mission"], d["condition"]}].designs.push_back(&d);
  for (const auto& c : a.conditions)
    conditions.push_back({{"name", c}, {"label", c}, {"method", methods[c]}, {"per_mission", per_mission_spaces[c]}});

  json missions = json::array();
  for (const auto& m : a.missions) missions.push_back(m.document);
  report["format"] = "swarmdesign-report/1";
  report["experiment"] = {{"name", e.name},
                          {"project", p.name},
                          {"state", storage::to_string(e.state)},
                          {"created_at", storage::format_iso_time(e.created_at)},
                          {"generated_at", storage::format_iso_time(static_cast<std::int64_t>(std::time(nullptr)))},
                          {"finished_at", e.finished_at ? json(storage::format_iso_time(*e.finished_at)) : json(nullptr)},
                          {"designs_planned", designs.size()},
                          {"designs_done", design_list.size()},
                          {"assessment_seeds", protocol.assessment_seeds},
                          {"budget_scale", protocol.budget_scale},
                          {"seed", protocol.seed},
                          {"swarmdesign_version", SWARMDESIGN_VERSION},
                          {"results_version", kResultsVersion},
                          {"protocol", json::parse(e.protocol)}};
  report["catalogue"] = catalogue_document();
  report["missions"] = std::move(missions);
  report["conditions"] = std::move(conditions);
  report["boxes"] = boxes_and_tests(a, report);
  report["friedman"] = friedman_document(a);
  report["module_frequency"] = module_frequency(a);
  report["pseudo_reality"] = pseudo_reality_document(a, protocol);
  per_cell_tables(a, report);
  report["designs"] = std::move(design_list);  // last: the cells point into design_list until here
  return report;
}

std::string experiment_report_html(const json& document, const std::filesystem::path& web_root) {
  const std::string script = inert_in_element(read_file(web_root / "report.js"), "</script", "<\\/script");
  const std::string style = inert_in_element(read_file(web_root / "report.css"), "</style", "<\\/style");
  // '<' only occurs inside JSON strings: written \u003c, no "</script" or "<!--" can end the element.
  const std::string data = inert_in_element(document.dump(), "<", "\\u003c");
  const std::string title =
      "SwarmDesign report: " + document["experiment"]["name"].get<std::string>() + " (" +
      document["experiment"]["project"].get<std::string>() + ")";
  return "<!doctype html><html><head><meta charset=\"utf-8\"><title>" + markup_text(title) + "</title><style>" + style +
         "</style></head>\n<body><div id=\"report\"></div>\n<script id=\"report-data\" type=\"application/json\">" + data +
         "</script>\n<script>" + script + "</script></body></html>\n";
}

std::vector<ReportFile> experiment_report_data_files(const json& document) {
  std::vector<ReportFile> files;
  files.push_back({"report.json", document.dump(1) + "\n"});
  auto csv = [&](const std::string& name, const std::vector<std::string>& columns, const json& rows) {
    files.push_back({name, csv_text(columns, rows)});
  };
  json designs = json::array(), assessments = json::array(), convergence = json::array();
  for (const auto& d : document["designs"]) {
    json row = d;
    row.erase("model");
    row.erase("scores");
    row.erase("assessment_seeds");
    row.erase("convergence");
    row["behaviours"] = d["modules"]["behaviours"].dump();
    row["conditions"] = d["modules"]["conditions"].dump();
    designs.push_back(std::move(row));
    for (std::size_t i = 0; i < d["scores"].size(); ++i)
      assessments.push_back({{"design", d["id"]}, {"mission", d["mission"]}, {"condition", d["condition"]},
                             {"replicate", d["replicate"]}, {"seed", d["assessment_seeds"][i]}, {"score", d["scores"][i]}});
    for (const auto& point : d["convergence"])
      convergence.push_back({{"design", d["id"]}, {"mission", d["mission"]}, {"condition", d["condition"]},
                             {"replicate", d["replicate"]}, {"runs_used", point[0]}, {"best_score", point[1]}});
  }
  csv("designs.csv",
      {"id", "mission", "condition", "replicate", "seed", "budget", "runs_used", "wall_seconds", "architecture",
       "design_score", "score", "behaviours", "conditions", "configuration"},
      designs);
  csv("assessments.csv", {"design", "mission", "condition", "replicate", "seed", "score"}, assessments);
  csv("convergence.csv", {"design", "mission", "condition", "replicate", "runs_used", "best_score"}, convergence);
  csv("boxes.csv",
      {"mission", "condition", "n", "min", "q1", "median", "q3", "max", "whisker_low", "whisker_high", "notch_low",
       "notch_high"},
      document["boxes"]);
  csv("wilcoxon.csv", {"mission", "a", "b", "n_a", "n_b", "W", "p_value", "exact", "better"}, document["wilcoxon"]);
  json friedman = json::array();
  if (!document["friedman"].is_null()) {
    const json& f = document["friedman"];
    for (const auto& r : f["expected_ranks"])
      friedman.push_back({{"condition", r["condition"]}, {"mean_rank", r["rank"]}, {"statistic", f["statistic"]},
                          {"df", f["df"]}, {"p_value", f["p_value"]}, {"critical_difference", f["critical_difference"]},
                          {"blocks", f["blocks"].size()}});
  }
  csv("friedman.csv", {"condition", "mean_rank", "statistic", "df", "p_value", "critical_difference", "blocks"}, friedman);
  csv("module_frequency.csv",
      {"condition", "mission", "kind", "flavour", "module", "name", "designs_with", "designs", "fraction"},
      document["module_frequency"]);
  csv("architectures.csv", {"mission", "condition", "fsm", "bt", "nn"}, document["architectures"]);
  csv("wall_time.csv", {"mission", "condition", "designs", "runs", "wall_seconds"}, document["wall_time"]);
  // The reality gap's tables, when the protocol asked for pseudo-realities.
  if (const json& r = document.value("pseudo_reality", json(nullptr)); r.is_object()) {
    json cells = json::array(), runs = json::array(), design_rows = json::array();
    for (const auto& c : r["cells"]) {
      json row{{"mission", c["mission"]}, {"condition", c["condition"]}, {"n", c["n"]},
               {"design_model_median", c["design_model"]["median"]}, {"pseudo_reality_median", c["pseudo_reality"]["median"]},
               {"median_drop", c["median_drop"]}, {"designs_dropping", c["designs_dropping"]},
               {"p_value", c["wilcoxon"].is_null() ? json(nullptr) : c["wilcoxon"]["p_value"]}};
      for (const auto& rank : r["ranks"])
        if (rank["mission"] == c["mission"] && rank["condition"] == c["condition"]) {
          row["design_model_rank"] = rank["design_model_rank"];
          row["pseudo_reality_rank"] = rank["pseudo_reality_rank"];
        }
      cells.push_back(std::move(row));
    }
    for (const auto& d : document["designs"]) {
      const json& p = d["pseudo_reality"];
      if (p.is_null()) continue;
      design_rows.push_back({{"design", d["id"]}, {"mission", d["mission"]}, {"condition", d["condition"]},
                             {"replicate", d["replicate"]}, {"design_model_score", d["score"]},
                             {"pseudo_reality_score", p["score"]}, {"drop", p["drop"]}, {"drop_low", p["drop_ci95"][0]},
                             {"drop_high", p["drop_ci95"][1]}, {"relative_drop", p["relative_drop"]}, {"p_value", p["p_value"]}});
      const std::size_t seeds = d["assessment_seeds"].size();
      for (std::size_t i = 0; seeds > 0 && i < p["scores"].size(); ++i)
        runs.push_back({{"design", d["id"]}, {"mission", d["mission"]}, {"condition", d["condition"]},
                        {"replicate", d["replicate"]}, {"sample", i / seeds + 1}, {"seed", d["assessment_seeds"][i % seeds]},
                        {"score", p["scores"][i]}});
    }
    csv("pseudo_reality.csv",
        {"mission", "condition", "n", "design_model_median", "pseudo_reality_median", "median_drop", "designs_dropping",
         "p_value", "design_model_rank", "pseudo_reality_rank"},
        cells);
    csv("pseudo_reality_designs.csv",
        {"design", "mission", "condition", "replicate", "design_model_score", "pseudo_reality_score", "drop", "drop_low",
         "drop_high", "relative_drop", "p_value"},
        design_rows);
    csv("pseudo_reality_runs.csv", {"design", "mission", "condition", "replicate", "sample", "seed", "score"}, runs);
  }
  return files;
}

std::vector<std::filesystem::path> write_experiment_report(const json& document, const std::filesystem::path& folder,
                                                           const std::filesystem::path& web_root) {
  const std::string html = experiment_report_html(document, web_root);  // first: a missing bundle writes nothing
  std::filesystem::create_directories(folder);
  std::vector<std::filesystem::path> files;
  const auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream out(files.emplace_back(folder / name), std::ios::binary);
    out << content;
    if (!out) throw std::runtime_error("cannot write " + (folder / name).string());
  };
  write("report.html", html);
  for (const ReportFile& f : experiment_report_data_files(document)) write(f.name, f.content);
  return files;
}

}  // namespace sd::app
