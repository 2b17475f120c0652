#include "design/iterated_race.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <unordered_set>

#include "core/fnv.hpp"
#include "core/math.hpp"
#include "design/model.hpp"
#include "design/neighbourhood.hpp"
#include "design/race.hpp"
#include "design/sampling.hpp"

namespace sd::design {

namespace {

long long ceil_div(long long a, long long b) { return (a + b - 1) / b; }

// irace round.to.next.multiple
long long round_to_next_multiple(long long x, long long d) { return x + d - 1 - (x - 1) % d; }

/// The fingerprint's fields: strings, each followed by a separator byte, and numbers as
/// their shortest exact decimal text.
class Fnv {
 public:
  void add(std::string_view s) {
    f_.add(s);
    f_.add(static_cast<unsigned char>(0xff));  // field separator
  }
  void add(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    add(std::string_view(buf));
  }
  std::string hex() const { return f_.hex(); }

 private:
  // This fingerprint has always started from 1469598103934665603, the standard basis with
  // its last digit lost; it is kept so that designs stored by earlier versions still resume.
  Fnv1a f_{1469598103934665603ULL};
};

}  // namespace

int default_nb_iterations(std::size_t nb_variable) {
  if (nb_variable == 0) throw std::invalid_argument("the parameter space has no variable parameter");
  // irace: floor(2 + log2(n)), which is 1 + the bit width of n, computed exactly.
  return 1 + static_cast<int>(std::bit_width(nb_variable));
}

int nb_configurations_for(long long current_budget, int iteration, int mu, int each_test, std::size_t n_elites,
                          std::size_t n_old_instances, int new_instances, int cap) {
  const long long saved = static_cast<long long>(n_elites) * static_cast<long long>(n_old_instances);
  const long long n = std::max<long long>(mu + each_test * std::min(5, iteration),
                                          round_to_next_multiple(static_cast<long long>(n_old_instances) + new_instances, each_test));
  return static_cast<int>(std::min<long long>((current_budget + saved) / n, cap));
}

long long minimum_budget(const IraceOptions& o, int min_survival, int nb_iterations) {
  const long long mu = std::max(o.mu, o.first_test);
  const long long each = o.each_test, t_new = o.elitist_new_instances;
  long long b = static_cast<long long>(min_survival + 1) * nb_iterations;
  if (!o.elitist) return b * (mu + 5 * each);
  if (nb_iterations > 5) return b * (mu + each + (nb_iterations - 5) * t_new + 5 * std::max(each, t_new));
  return b * (mu + each + (nb_iterations - 1) * std::max(each, t_new));
}

namespace {
/// The options as the engine runs them: mu at least firstTest, the soft-restart threshold
/// 10^-digits when not given. The fingerprint is taken of these, with or without an engine.
IraceOptions effective_options(const ParameterSpace& space, IraceOptions o) {
  o.mu = std::max(o.mu, o.first_test);
  if (std::isnan(o.soft_restart_threshold)) o.soft_restart_threshold = math::pow(10.0, -space.digits());
  return o;
}
}  // namespace

IteratedRace::IteratedRace(const ParameterSpace& space, IraceOptions options, ExperimentRunner& runner)
    : space_(space), options_(effective_options(space, std::move(options))), runner_(runner), rng_(options_.seed) {
  if (options_.max_experiments <= 0) throw std::invalid_argument("the budget (maxExperiments) must be positive");
  if (options_.first_test <= 1) throw std::invalid_argument("firstTest must be larger than 1");
  if (options_.each_test < 1 || options_.first_test % options_.each_test != 0)
    throw std::invalid_argument("firstTest must be a multiple of eachTest");
  if (options_.n_instances == 0) throw std::invalid_argument("at least one instance is needed");
  if (!(options_.confidence > 0 && options_.confidence < 1)) throw std::invalid_argument("confidence must be in (0, 1)");
}

std::string IteratedRace::fingerprint() const { return design::fingerprint(space_, options_); }

std::string fingerprint(const ParameterSpace& space, const IraceOptions& options) {
  const IraceOptions o = effective_options(space, options);
  Fnv f;
  f.add(static_cast<double>(space.digits()));
  for (const Parameter& p : space.parameters()) {
    f.add(p.name);
    f.add(p.switch_);
    f.add(static_cast<double>(static_cast<int>(p.type)));
    for (const auto& v : p.values) f.add(v);
    for (const Bound* b : {&p.lower, &p.upper}) {
      f.add(b->constant);
      f.add(b->param);
      f.add(b->offset);
    }
    f.add(p.log_scale ? "log" : "lin");
    for (const Clause& c : p.condition) {
      f.add(c.param);
      f.add(static_cast<double>(static_cast<int>(c.op)));
      for (const auto& v : c.values) f.add(v);
      f.add(c.number);
    }
  }
  for (double v : {static_cast<double>(o.max_experiments), static_cast<double>(o.n_instances),
                   static_cast<double>(o.seed), static_cast<double>(o.nb_iterations),
                   static_cast<double>(o.nb_experiments_per_iteration), static_cast<double>(o.nb_configurations),
                   static_cast<double>(o.min_nb_survival), static_cast<double>(o.mu), static_cast<double>(o.first_test),
                   static_cast<double>(o.each_test), o.confidence, static_cast<double>(o.elitist),
                   static_cast<double>(o.elitist_new_instances), static_cast<double>(o.elitist_limit),
                   static_cast<double>(o.soft_restart), o.soft_restart_threshold,
                   static_cast<double>(o.sample_instances), static_cast<double>(o.unique_new_configurations)})
    f.add(v);
  for (const auto& c : o.initial_configurations) f.add(space.render(c));
  // Only another sampler adds to the fingerprint: designs made before it existed resume.
  if (o.sampler != Sampler::Model) f.add(static_cast<double>(static_cast<int>(o.sampler)));
  return f.hex();
}

void IteratedRace::initialise() {
  DesignState& s = state_;
  s = DesignState{};
  s.fingerprint = fingerprint();
  const std::size_t nb_var = space_.nb_variable();
  s.nb_iterations = options_.nb_iterations > 0 ? options_.nb_iterations : default_nb_iterations(nb_var);
  s.min_survival = options_.min_nb_survival > 0 ? options_.min_nb_survival : default_nb_iterations(nb_var);
  s.budget = s.remaining_budget = options_.max_experiments;
  const long long needed = minimum_budget(options_, s.min_survival, s.nb_iterations);
  if (s.budget < needed)
    throw std::invalid_argument("insufficient budget: with the current settings the design needs a budget of at least " +
                                std::to_string(needed) + " evaluations");
  s.instances = InstanceList(options_.n_instances, rng_.next(), options_.sample_instances);
  s.instances.append(static_cast<std::size_t>(ceil_div(s.budget, s.min_survival)));
  std::unordered_set<std::string> seen;
  for (const Configuration& c : options_.initial_configurations) {
    const std::string problem = space_.validate(c);
    if (!problem.empty()) throw std::invalid_argument("initial configuration: " + problem);
    if (!seen.insert(c.key()).second) throw std::invalid_argument("duplicated initial configuration");
    s.configurations.add(c, 0);
  }
  s.phase = Phase::StartIteration;
  initialised_ = true;
}

void IteratedRace::restore(DesignState state) {
  if (state.fingerprint != fingerprint())
    throw std::runtime_error("the checkpoint belongs to a design with another parameter space or other options");
  state_ = std::move(state);
  rng_.set_state(state_.rng);
  results_.clear();
  for (const ExperimentRecord& e : state_.experiments) results_[e.configuration_id][e.position] = e.cost;
  if (state_.race) rebuild_results(*state_.race, state_.race->results.size(), [this](std::size_t p, int id) { return lookup(p, id); });
  checkpointed_configurations_ = state_.configurations.size();
  checkpointed_experiments_ = state_.experiments.size();
  initialised_ = true;
}

double IteratedRace::lookup(std::size_t position, int id) const {
  const auto it = results_.find(id);
  if (it == results_.end()) return std::nan("");
  const auto jt = it->second.find(position);
  return jt == it->second.end() ? std::nan("") : jt->second;
}

void IteratedRace::record(std::size_t position, int id, double cost) {
  state_.experiments.push_back({state_.iteration, position, id, cost});
  results_[id][position] = cost;
  state_.positions_seen = std::max(state_.positions_seen, position);
}

RaceSettings IteratedRace::race_settings() const {
  RaceSettings r;
  r.first_test = options_.first_test;
  r.each_test = options_.each_test;
  r.confidence = options_.confidence;
  r.elitist = options_.elitist;
  r.elitist_limit = options_.elitist_limit;
  r.min_survival = state_.min_survival;
  r.max_experiments = state_.current_budget;
  return r;
}

void IteratedRace::finish(std::string reason) {
  state_.phase = Phase::Finished;
  state_.finish_reason = std::move(reason);
  state_.race.reset();
}

std::vector<int> IteratedRace::sample_new(std::size_t n, const std::vector<int>& elite_ids, bool uniform) {
  DesignState& s = state_;
  std::unordered_set<std::string> rejected, in_race;
  for (int id : s.rejected_ids) rejected.insert(s.configurations[id].config.key());
  for (int id : elite_ids) in_race.insert(s.configurations[id].config.key());
  int duplicate_tries = 0;
  const Acceptable acceptable = [&](const Configuration& c) {
    const std::string k = c.key();
    if (rejected.count(k)) return false;
    if (options_.unique_new_configurations && in_race.count(k) && ++duplicate_tries < 50) return false;
    duplicate_tries = 0;
    in_race.insert(k);
    return true;
  };
  std::vector<SampledConfiguration> fresh;
  if (uniform || options_.sampler == Sampler::Uniform) {
    for (auto& c : sample_uniform(space_, n, rng_, acceptable)) fresh.push_back({std::move(c), 0});
  } else if (options_.sampler == Sampler::Neighbourhood) {
    fresh = sample_neighbours(space_, s.elites, s.configurations, n, rng_, acceptable);
  } else if (!options_.soft_restart) {
    fresh = sample_model(space_, s.elites, s.configurations, s.model, n, rng_, acceptable);
  } else {
    // First draw as irace does, twins allowed: a new configuration equal to an elite or to
    // another new one is exactly what irace's similarConfigurations detects, and the soft
    // restart it triggers (the usual case in early iterations) must not be hidden by the
    // redraw of twins. Without similar configurations there are no twins, so this draw is
    // kept as it is; otherwise the draw after the restart redraws twins as usual.
    const Acceptable not_rejected = [&](const Configuration& c) { return rejected.count(c.key()) == 0; };
    fresh = sample_model(space_, s.elites, s.configurations, s.model, n, rng_, not_rejected);
    {
      std::vector<ConfigRecord> race_set;
      race_set.reserve(race_set.size() + elite_ids.size());
      for (int id : elite_ids) race_set.push_back(s.configurations[id]);
      int next = s.configurations.next_id();
      for (const auto& f : fresh) race_set.push_back({next++, f.parent, f.config});
      const std::vector<int> similar = similar_configurations(space_, race_set, options_.soft_restart_threshold);
      if (!similar.empty()) {
        std::vector<int> model_ids;
        for (int id : similar) {
          const auto rec = std::find_if(race_set.begin(), race_set.end(), [&](const ConfigRecord& r) { return r.id == id; });
          const int model_id = s.model.has(id) ? id : rec->parent;
          if (std::find(model_ids.begin(), model_ids.end(), model_id) == model_ids.end()) model_ids.push_back(model_id);
        }
        restart_model(s.model, space_, model_ids, static_cast<int>(n));
        s.soft_restarts.back() = 1;
        in_race.clear();
        for (int id : elite_ids) in_race.insert(s.configurations[id].config.key());
        fresh = sample_model(space_, s.elites, s.configurations, s.model, n, rng_, acceptable);
      }
    }
  }
  std::vector<int> ids;
  ids.reserve(ids.size() + fresh.size());
  for (auto& f : fresh) ids.push_back(s.configurations.add(std::move(f.config), f.parent));
  return ids;
}

void IteratedRace::start_iteration() {
  DesignState& s = state_;
  if (s.remaining_budget <= 0) return finish("Budget exhausted");
  if (s.iteration > s.nb_iterations) {
    if (options_.nb_iterations == 0) s.nb_iterations = s.iteration;  // keep going while budget lasts
    else return finish("Limit of iterations reached");
  }
  s.current_budget = options_.nb_experiments_per_iteration > 0
                         ? std::min(options_.nb_experiments_per_iteration, s.remaining_budget)  // never beyond the budget
                         : s.remaining_budget / (s.nb_iterations - s.iteration + 1);
  const bool elitist_saving = options_.elitist && !s.first_race;
  s.nb_configurations = nb_configurations_for(
      s.current_budget, s.iteration, options_.mu, options_.each_test, elitist_saving ? s.elites.size() : 0,
      elitist_saving ? s.positions_seen : 0, elitist_saving ? options_.elitist_new_instances : 0);
  if (options_.nb_configurations > 0) {
    if (options_.nb_configurations <= s.nb_configurations) {
      s.nb_configurations = options_.nb_configurations;
    } else if (s.current_budget < s.remaining_budget && options_.nb_iterations > 0) {
      ++s.iteration;  // not enough budget for this iteration: skip to the next one (with a last one to come)
      return;
    } else {
      return finish("Not enough budget to enforce the value of nbConfigurations");
    }
  }
  const auto n_elites = static_cast<int>(s.elites.size());
  if (s.nb_configurations <= s.min_survival)
    return finish("Not enough budget to race more than the minimum configurations");
  if (!s.first_race && s.nb_configurations <= n_elites)
    return finish("Not enough budget left to race newly sampled configurations");
  const long long first_test_cost =
      options_.elitist ? static_cast<long long>(s.nb_configurations - n_elites) * options_.mu +
                             static_cast<long long>(n_elites) * std::min(options_.elitist_new_instances, options_.mu)
                       : static_cast<long long>(s.nb_configurations) * options_.mu;
  if (first_test_cost > s.current_budget)
    return finish("Not enough budget to race all configurations up to the first test (or mu)");

  s.soft_restarts.resize(static_cast<std::size_t>(s.iteration), 0);
  std::vector<int> race_ids;
  if (s.first_race) {
    for (const ConfigRecord& r : s.configurations.all())
      if (std::find(s.rejected_ids.begin(), s.rejected_ids.end(), r.id) == s.rejected_ids.end()) race_ids.push_back(r.id);
    const int n_new = s.nb_configurations - static_cast<int>(race_ids.size());
    if (n_new > 0) {
      for (int id : sample_new(static_cast<std::size_t>(n_new), race_ids, true)) race_ids.push_back(id);
    } else {
      race_ids.resize(static_cast<std::size_t>(s.nb_configurations));
    }
  } else {
    const int n_new = s.nb_configurations - n_elites;
    if (options_.sampler == Sampler::Model)  // the other samplers draw without it
      s.model = update_model(space_, s.elites, s.configurations, s.model, s.iteration, s.nb_iterations, n_new,
                             options_.elitist);
    for (const Elite& e : s.elites) race_ids.push_back(e.id);
    const std::vector<int> elite_ids = race_ids;
    for (int id : sample_new(static_cast<std::size_t>(n_new), elite_ids, false)) race_ids.push_back(id);
  }

  const long long wanted = ceil_div(s.remaining_budget, s.min_survival);
  if (static_cast<long long>(s.instances.size() - s.positions_seen) < wanted)
    s.instances.append(static_cast<std::size_t>(wanted));
  const std::size_t elites_in_race = options_.elitist && !s.first_race ? s.elites.size() : 0;
  s.race = start_race(race_settings(), race_ids, elites_in_race, s.positions_seen,
                      s.first_race ? 0 : static_cast<std::size_t>(options_.elitist_new_instances), s.instances.size(),
                      options_.sample_instances, [this](std::size_t p, int id) { return lookup(p, id); }, rng_);
  s.phase = Phase::Racing;
}

void IteratedRace::finish_race_and_iteration() {
  DesignState& s = state_;
  const RaceResult result = finish_race(*s.race);
  for (int id : result.rejected_ids) s.rejected_ids.push_back(id);
  s.experiments_used += result.experiments_used;
  s.remaining_budget -= result.experiments_used;
  s.elites = extract_elites(result, s.configurations,
                            std::min<std::size_t>(result.nb_alive, static_cast<std::size_t>(s.min_survival)));
  std::vector<int> ids;
  for (const Elite& e : s.elites) ids.push_back(e.id);
  s.all_elites.push_back(ids);
  if (s.first_race) s.model = initialise_model(space_, s.elites, s.configurations);
  ++s.iteration;
  s.first_race = false;
  s.race.reset();
  s.phase = Phase::StartIteration;
}

bool IteratedRace::advance() {
  if (!initialised_) initialise();
  switch (state_.phase) {
    case Phase::Finished: return false;
    case Phase::StartIteration: start_iteration(); break;
    case Phase::Racing: {
      RaceEnvironment env{state_.configurations, state_.instances, runner_,
                          [this](std::size_t p, int id, double cost) { record(p, id, cost); }};
      race_step(*state_.race, race_settings(), env);
      emit_progress();
      if (state_.race->finished) finish_race_and_iteration();
      break;
    }
  }
  emit_checkpoint();
  return state_.phase != Phase::Finished;
}

DesignResult IteratedRace::run() {
  while (advance()) {
  }
  return result();
}

void IteratedRace::emit_checkpoint() {
  state_.rng = rng_.state();
  if (checkpoint_) checkpoint_(Checkpoint{state_, checkpointed_configurations_, checkpointed_experiments_});
  checkpointed_configurations_ = state_.configurations.size();
  checkpointed_experiments_ = state_.experiments.size();
}

void IteratedRace::emit_progress() {
  if (!progress_ || !state_.race) return;
  const RaceState& r = *state_.race;
  Progress p;
  p.iteration = state_.iteration;
  p.nb_iterations = state_.nb_iterations;
  p.experiments_used = state_.experiments_used + r.experiments_used;
  p.budget = state_.budget;
  p.alive = r.nb_alive();
  p.race_configurations = r.config_ids.size();
  p.task = r.next_task - 1;
  if (!r.results.empty() && r.best < r.config_ids.size()) {
    p.best_id = r.config_ids[r.best];
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t row = 0; row < std::min(p.task, r.results.size()); ++row)
      if (!std::isnan(r.results[row][r.best])) {
        sum += r.results[row][r.best];
        ++n;
      }
    p.best_mean = n ? sum / static_cast<double>(n) : 0.0;
  }
  progress_(p);
}

DesignResult IteratedRace::result() const {
  DesignResult out;
  out.finish_reason = state_.finish_reason;
  out.experiments_used = state_.experiments_used;
  out.iterations = static_cast<int>(state_.all_elites.size());
  for (const Elite& e : state_.elites) {
    EliteSummary es;
    es.id = e.id;
    es.configuration = state_.configurations[e.id].config;
    const auto it = results_.find(e.id);
    if (it != results_.end()) {
      for (const auto& [pos, cost] : it->second) es.mean_cost += cost;
      es.evaluations = it->second.size();
      if (es.evaluations) es.mean_cost /= static_cast<double>(es.evaluations);
    }
    out.elites.push_back(std::move(es));
  }
  return out;
}

}  // namespace sd::design
