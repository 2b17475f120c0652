#include "design/model.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/math.hpp"

namespace sd::design {

namespace {

void normalise(std::vector<double>& p) {
  const double s = std::accumulate(p.begin(), p.end(), 0.0);
  for (double& v : p) v /= s;
}

std::vector<double> fresh_entry(const Parameter& p, double value) {
  if (p.is_fixed()) return {};
  switch (p.type) {
    case ParamType::Categorical: return std::vector<double>(p.values.size(), 1.0 / static_cast<double>(p.values.size()));
    case ParamType::Ordinal: return {(static_cast<double>(p.values.size()) - 1) / 2};
    case ParamType::Integer:
    case ParamType::Real: return {initial_sd(p), value};
  }
  return {};
}

double nb_variable_of(const ParameterSpace& space) {
  const auto n = space.nb_variable();
  if (n == 0) throw std::invalid_argument("the parameter space has no variable parameter");
  return static_cast<double>(n);
}

}  // namespace

double initial_sd(const Parameter& p) {
  if (p.is_dependent()) return 0.5;  // fraction of the current width
  if (p.log_scale) return 0.5;       // half of [0, 1] in log space
  return (p.upper.constant - p.lower.constant) / 2;
}

Model initialise_model(const ParameterSpace& space, const std::vector<Elite>& elites, const ConfigurationStore& store) {
  Model m;
  for (const Elite& e : elites) {
    auto& entry = m.entries[e.id];
    entry.resize(space.size());
    for (std::size_t i = 0; i < space.size(); ++i) entry[i] = fresh_entry(space[i], store[e.id].config.values[i]);
  }
  return m;
}

Model update_model(const ParameterSpace& space, const std::vector<Elite>& elites, const ConfigurationStore& store,
                   const Model& old, int iteration, int nb_iterations, int nb_new, bool elitist) {
  const double nb_var = nb_variable_of(space);
  const double step = static_cast<double>(iteration - 1) / static_cast<double>(nb_iterations);
  const double shrink = math::pow(1.0 / static_cast<double>(nb_new), 1.0 / nb_var);
  const double prob_max = math::pow(0.2, 1.0 / nb_var);
  Model m;
  for (const Elite& e : elites) {
    const ConfigRecord& rec = store[e.id];
    std::vector<std::vector<double>> entry;
    if (old.has(e.id)) {
      entry = old.entries.at(e.id);
    } else {
      // A new elite starts from its parent's entry, remembering its own numeric values.
      if (!old.has(rec.parent))
        throw std::logic_error("model update: elite " + std::to_string(e.id) + " has no parent entry");
      entry = old.entries.at(rec.parent);
      for (std::size_t i = 0; i < space.size(); ++i)
        if (space[i].is_numeric() && !space[i].is_fixed() && !is_na(rec.config.values[i]))
          entry[i][1] = rec.config.values[i];
    }
    for (std::size_t i = 0; i < space.size(); ++i) {
      const Parameter& p = space[i];
      if (p.is_fixed()) continue;
      auto& v = entry[i];
      if (p.type == ParamType::Categorical) {
        const double value = rec.config.values[i];
        if (is_na(value)) continue;
        for (double& x : v) x *= 1 - step;
        v[static_cast<std::size_t>(value)] += step;
        if (elitist) {
          normalise(v);
          for (double& x : v) x = std::min(x, prob_max);
        }
        normalise(v);
      } else {
        v[0] *= shrink;
      }
    }
    m.entries[e.id] = std::move(entry);
  }
  return m;
}

void restart_model(Model& model, const ParameterSpace& space, const std::vector<int>& ids, int nb_new) {
  const double nb_var = nb_variable_of(space);
  const double n = static_cast<double>(nb_new);
  for (int id : ids) {
    auto& entry = model.entries.at(id);
    for (std::size_t i = 0; i < space.size(); ++i) {
      const Parameter& p = space[i];
      if (p.is_fixed()) continue;
      auto& v = entry[i];
      if (p.type == ParamType::Categorical) {
        const double mx = *std::max_element(v.begin(), v.end());
        for (double& x : v) x = 0.9 * x + 0.1 * mx;
        normalise(v);
      } else {
        const double init = p.type == ParamType::Ordinal ? (static_cast<double>(p.values.size()) - 1) / 2 : initial_sd(p);
        v[0] = std::min(v[0] * math::pow(n, 2.0 / nb_var), init * math::pow(1.0 / n, 1.0 / nb_var));
      }
    }
  }
}

}  // namespace sd::design
