#include "design/sampling.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>

#include "core/math.hpp"

namespace sd::design {

namespace {

constexpr int kMaxRetries = 100;  // irace: "tried 100 times ... perhaps your constraints are too strict?"

double exponential(Rng& rng, double rate) { return -math::log(1.0 - rng.uniform()) / rate; }

// irace numeric_value_round: integers floored (ub + 1 folds back to ub), reals to `digits`.
double round_value(const ParameterSpace& space, const Parameter& p, double v, double upper) {
  if (p.type == ParamType::Integer) {
    v = std::floor(v);
    if (v == upper + 1) v = upper;
    return v;
  }
  return space.round_real(v);
}

// Log transform limits (irace transform.domain): log(lb), log(ub) or log(ub + 1) for integers.
std::pair<double, double> log_limits(const Parameter& p) {
  const double lo = math::log(p.lower.constant);
  const double hi = math::log(p.type == ParamType::Integer ? p.upper.constant + 1 : p.upper.constant);
  return {lo, hi};
}

double sample_unif_numeric(const ParameterSpace& space, const Parameter& p, std::pair<double, double> dom, Rng& rng) {
  const double lb = dom.first;
  const double ub = p.type == ParamType::Integer ? dom.second + 1 : dom.second;
  double v;
  if (p.log_scale) {
    const auto [lo, hi] = log_limits(p);
    v = math::exp(lo + (hi - lo) * rng.uniform());
  } else {
    v = rng.uniform(lb, ub);
  }
  return round_value(space, p, v, dom.second);
}

double sample_norm_numeric(const ParameterSpace& space, const Parameter& p, double mean, double sd,
                           std::pair<double, double> dom, Rng& rng) {
  const double lb = dom.first;
  double ub = dom.second;
  if (p.type == ParamType::Integer) {  // draw on [lb, ub + 1) around mean + 0.5, then floor
    ub += 1;
    mean += 0.5;
  }
  double v;
  if (p.log_scale) {
    const auto [lo, hi] = log_limits(p);
    const double tr_mean = (math::log(mean) - lo) / (hi - lo);
    v = math::exp(lo + (hi - lo) * truncated_normal(rng, tr_mean, sd, 0.0, 1.0));
  } else {
    v = truncated_normal(rng, mean, sd, lb, ub);
  }
  return round_value(space, p, v, dom.second);
}

std::size_t draw_index(Rng& rng, const std::vector<double>& weights) {
  double total = 0.0;
  for (double w : weights) total += w;
  double u = rng.uniform() * total;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (u < weights[i]) return i;
    u -= weights[i];
  }
  // Rounding left u just above the last weight: take the last non-zero one.
  for (std::size_t i = weights.size(); i-- > 0;)
    if (weights[i] > 0) return i;
  return weights.size() - 1;
}

std::runtime_error too_strict() {
  return std::runtime_error(
      "tried 100 times to sample a configuration that is not forbidden without success, perhaps the constraints "
      "are too strict?");
}

}  // namespace

double truncated_normal(Rng& rng, double mean, double sd, double lower, double upper) {
  if (!(sd > 0)) return std::clamp(mean, lower, upper);  // degenerate: all mass at the mean
  const double l = (lower - mean) / sd;
  const double u = (upper - mean) / sd;
  if (l > u) throw std::invalid_argument("truncated_normal: lower bound above upper bound");
  const double inf = std::numeric_limits<double>::infinity();
  const double two_sqrt_e = 2 * std::sqrt(std::numbers::e);
  double z;
  if ((l < 0 && u == inf) || (l == -inf && u > 0) ||
      (std::isfinite(l) && std::isfinite(u) && l < 0 && u > 0 && u - l > std::sqrt(2 * std::numbers::pi))) {
    do z = rng.normal();
    while (z < l || z > u);
  } else if (l >= 0 && u > l + two_sqrt_e / (l + std::sqrt(l * l + 4)) * math::exp((l * 2 - l * std::sqrt(l * l + 4)) / 4)) {
    const double a = (l + std::sqrt(l * l + 4)) / 2;
    for (;;) {
      z = exponential(rng, a) + l;
      const double w = rng.uniform();
      if (w <= math::exp(-(z - a) * (z - a) / 2) && z <= u) break;
    }
  } else if (u <= 0 &&
             -l > -u + two_sqrt_e / (-u + std::sqrt(u * u + 4)) * math::exp((u * 2 - -u * std::sqrt(u * u + 4)) / 4)) {
    const double a = (-u + std::sqrt(u * u + 4)) / 2;
    for (;;) {
      z = exponential(rng, a) - u;
      const double w = rng.uniform();
      if (w <= math::exp(-(z - a) * (z - a) / 2) && z <= -l) break;
    }
    z = -z;
  } else {
    for (;;) {
      z = rng.uniform(l, u);
      const double rho = l > 0 ? math::exp((l * l - z * z) / 2) : (u < 0 ? math::exp((u * u - z * z) / 2) : math::exp(-z * z / 2));
      if (rng.uniform() <= rho) break;
    }
  }
  return z * sd + mean;
}

double sample_uniform_value(const ParameterSpace& space, const Configuration& c, std::size_t i, Rng& rng) {
  const Parameter& p = space[i];
  if (p.is_fixed()) return 0.0;
  if (p.is_numeric()) {
    const auto dom = space.domain(c, i);
    return dom ? sample_unif_numeric(space, p, *dom, rng) : kNA;
  }
  return static_cast<double>(rng.below(static_cast<std::uint32_t>(p.values.size())));
}

double sample_normal_value(const ParameterSpace& space, const Configuration& c, std::size_t i, double mean, double sd,
                           Rng& rng) {
  const auto dom = space.domain(c, i);
  return dom ? sample_norm_numeric(space, space[i], mean, sd, *dom, rng) : kNA;
}

Configuration sample_uniform(const ParameterSpace& space, Rng& rng) {
  Configuration c;
  c.values.assign(space.size(), kNA);
  for (std::size_t i : space.sampling_order())
    if (space.is_active(c, i)) c.values[i] = sample_uniform_value(space, c, i, rng);
  return c;
}

std::vector<Configuration> sample_uniform(const ParameterSpace& space, std::size_t n, Rng& rng,
                                          const Acceptable& acceptable) {
  std::vector<Configuration> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    int tries = 0;
    for (;;) {
      Configuration c = sample_uniform(space, rng);
      if (!acceptable || acceptable(c)) {
        out.push_back(std::move(c));
        break;
      }
      if (++tries >= kMaxRetries) throw too_strict();
    }
  }
  return out;
}

std::vector<SampledConfiguration> sample_model(const ParameterSpace& space, const std::vector<Elite>& elites,
                                               const ConfigurationStore& store, const Model& model, std::size_t n,
                                               Rng& rng, const Acceptable& acceptable) {
  if (elites.empty()) throw std::invalid_argument("sample_model needs at least one elite");
  std::vector<double> weights;
  weights.reserve(weights.size() + elites.size());
  for (const Elite& e : elites) weights.push_back(e.weight);
  std::vector<SampledConfiguration> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    int tries = 0;
    for (;;) {
      const Elite& parent = elites[draw_index(rng, weights)];
      const Configuration& pc = store[parent.id].config;
      const auto& entry = model.entries.at(parent.id);
      Configuration c;
      c.values.assign(space.size(), kNA);
      for (std::size_t i : space.sampling_order()) {
        const Parameter& p = space[i];
        if (!space.is_active(c, i)) continue;
        if (p.is_fixed()) {
          c.values[i] = 0.0;
        } else if (p.is_numeric()) {
          const auto dom = space.domain(c, i);
          if (!dom) continue;
          double mean = pc.values[i];
          if (is_na(mean)) mean = entry[i][1];  // last value the parent's line had (irace 3.0+)
          if (is_na(mean) || mean < dom->first || mean > dom->second) {
            c.values[i] = sample_unif_numeric(space, p, *dom, rng);
          } else {
            double sd = entry[i][0];
            if (p.is_dependent()) sd *= dom->second - dom->first;
            c.values[i] = sample_norm_numeric(space, p, mean, sd, *dom, rng);
          }
        } else if (p.type == ParamType::Ordinal) {
          const double k_values = static_cast<double>(p.values.size());
          if (is_na(pc.values[i])) {
            c.values[i] = static_cast<double>(rng.below(static_cast<std::uint32_t>(p.values.size())));
          } else {
            const double mean = pc.values[i] + 1;  // 1-based index, as irace
            double idx = std::floor(truncated_normal(rng, mean + 0.5, entry[i][0], 1, k_values + 1));
            if (idx == k_values + 1) idx = k_values;
            c.values[i] = idx - 1;
          }
        } else {
          c.values[i] = static_cast<double>(draw_index(rng, entry[i]));
        }
      }
      if (!acceptable || acceptable(c)) {
        out.push_back({std::move(c), parent.id});
        break;
      }
      if (++tries >= kMaxRetries) throw too_strict();
    }
  }
  return out;
}

std::vector<int> similar_configurations(const ParameterSpace& space, const std::vector<ConfigRecord>& configs,
                                        double threshold) {
  std::vector<std::size_t> categorical, numeric;
  for (std::size_t i = 0; i < space.size(); ++i) {
    if (space[i].is_fixed()) continue;
    (space[i].is_numeric() ? numeric : categorical).push_back(i);
  }
  // Group by the categorical values (as text, NA included), keeping race order inside a group.
  std::map<std::string, std::vector<std::size_t>> groups;
  for (std::size_t k = 0; k < configs.size(); ++k) {
    std::string key;
    for (std::size_t i : categorical) key += space.value_text(configs[k].config, i) + " ; ";
    groups[key].push_back(k);
  }
  std::set<int> similar;
  for (const auto& [key, members] : groups) {
    if (members.size() < 2) continue;
    if (numeric.empty()) {
      for (std::size_t k : members) similar.insert(configs[k].id);
      continue;
    }
    for (std::size_t a = 0; a + 1 < members.size(); ++a) {
      const Configuration& x = configs[members[a]].config;
      for (std::size_t b = a + 1; b < members.size(); ++b) {
        const Configuration& y = configs[members[b]].config;
        bool alike = true;
        for (std::size_t i : numeric) {
          const double X = x.values[i], Y = y.values[i];
          if (is_na(X) && is_na(Y)) continue;
          if (is_na(X) != is_na(Y)) {
            alike = false;
            break;
          }
          const Parameter& p = space[i];
          double d;
          if (p.is_dependent()) {
            // irace measures both against x's current width (y.range <- diff(x.domain)).
            const auto xd = space.domain(x, i);
            const auto yd = space.domain(y, i);
            const double range = xd->second - xd->first;
            const double dx = range == 0 ? 0 : (X - xd->first) / range;
            const double dy = range == 0 ? 0 : (Y - yd->first) / range;
            d = std::fabs(dx - dy);
          } else {
            d = std::fabs((X - Y) / (p.upper.constant - p.lower.constant));
          }
          if (d > threshold) {
            alike = false;
            break;
          }
        }
        if (alike) {
          similar.insert(configs[members[a]].id);
          similar.insert(configs[members[b]].id);
        }
      }
    }
  }
  return {similar.begin(), similar.end()};
}

}  // namespace sd::design
