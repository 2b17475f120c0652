#include "design/neighbourhood.hpp"

#include <stdexcept>

namespace sd::design {

namespace {

constexpr int kMaxRetries = 100;  // as sampling.cpp: a space whose every neighbour is rejected is too strict

bool has_choice(const ParameterSpace& space, const Configuration& c, std::size_t i) {
  const Parameter& p = space[i];
  if (p.is_fixed()) return false;
  if (!p.is_numeric()) return p.values.size() > 1;
  const auto dom = space.domain(c, i);
  return dom && dom->second > dom->first;
}

/// Another value for parameter i; its dependencies in `c` are set.
double other_value(const ParameterSpace& space, const Configuration& c, std::size_t i, Rng& rng) {
  const Parameter& p = space[i];
  const double current = c.values[i];
  if (!p.is_numeric()) {
    const auto k = static_cast<double>(rng.below(static_cast<std::uint32_t>(p.values.size() - 1)));
    return k >= current ? k + 1 : k;
  }
  const auto [lb, ub] = *space.domain(c, i);
  for (int tries = 0; tries < kMaxRetries; ++tries) {
    const bool local = !p.log_scale && rng.bernoulli(0.5);
    const double v = local ? sample_normal_value(space, c, i, current, (ub - lb) / 10, rng)
                           : sample_uniform_value(space, c, i, rng);
    if (v != current) return v;
  }
  return current == lb ? ub : lb;  // a two-value domain drawn unluckily: the other end
}

/// Makes `c` valid again after parameter `changed` moved: in sampling order, a parameter now
/// inactive is cleared, one newly active or outside its (dependent) domain is drawn anew.
void repair(const ParameterSpace& space, Configuration& c, Rng& rng) {
  for (std::size_t i : space.sampling_order()) {
    if (!space.is_active(c, i)) {
      c.values[i] = kNA;
      continue;
    }
    bool redraw = is_na(c.values[i]);
    if (!redraw && space[i].is_numeric()) {
      const auto dom = space.domain(c, i);
      redraw = !dom || c.values[i] < dom->first || c.values[i] > dom->second;
    }
    if (redraw) c.values[i] = sample_uniform_value(space, c, i, rng);
  }
}

}  // namespace

std::vector<std::size_t> movable_parameters(const ParameterSpace& space, const Configuration& c) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < space.size(); ++i)
    if (!is_na(c.values[i]) && has_choice(space, c, i)) out.push_back(i);
  return out;
}

Configuration moved(const ParameterSpace& space, Configuration c, std::size_t i, Rng& rng) {
  c.values[i] = other_value(space, c, i, rng);
  repair(space, c, rng);
  return c;
}

Configuration neighbour(const ParameterSpace& space, Configuration c, Rng& rng, int moves) {
  for (int m = 0; m < moves; ++m) {
    const std::vector<std::size_t> movable = movable_parameters(space, c);
    if (movable.empty()) break;
    c = moved(space, std::move(c), movable[rng.below(static_cast<std::uint32_t>(movable.size()))], rng);
  }
  return c;
}

std::vector<SampledConfiguration> sample_neighbours(const ParameterSpace& space, const std::vector<Elite>& elites,
                                                    const ConfigurationStore& store, std::size_t n, Rng& rng,
                                                    const Acceptable& acceptable) {
  if (elites.empty()) throw std::invalid_argument("sample_neighbours needs at least one elite");
  std::vector<SampledConfiguration> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int tries = 0;; ++tries) {
      if (tries >= kMaxRetries)
        throw std::runtime_error("tried 100 times to draw a new neighbour of the elites without success");
      double u = rng.uniform();
      const Elite* parent = &elites.back();
      for (const Elite& e : elites) {
        if (u < e.weight) {
          parent = &e;
          break;
        }
        u -= e.weight;
      }
      int moves = 1;
      while (moves < 3 && rng.bernoulli(0.5)) ++moves;
      Configuration c = neighbour(space, store[parent->id].config, rng, moves);
      if (!acceptable || acceptable(c)) {
        out.push_back({std::move(c), parent->id});
        break;
      }
    }
  }
  return out;
}

}  // namespace sd::design
