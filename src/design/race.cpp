#include "design/race.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <set>
#include <unordered_set>
#include <stdexcept>

#include "design/batch_plan.hpp"
#include "design/race_test.hpp"

namespace sd::design {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<std::size_t> alive_columns(const RaceState& s) {
  std::vector<std::size_t> cols;
  for (std::size_t c = 0; c < s.alive.size(); ++c)
    if (s.alive[c]) cols.push_back(c);
  return cols;
}

bool any_elite(const RaceState& s) {
  return std::any_of(s.is_elite.begin(), s.is_elite.end(), [](int e) { return e > 0; });
}

// Elitist races may only stop once every previously seen instance has a result for at least
// one alive configuration (irace all_elite_instances_evaluated).
bool all_old_instances_evaluated(const RaceState& s, const RaceSettings& settings) {
  if (!settings.elitist) return true;
  for (std::size_t row = s.n_new; row < s.n_new + s.n_old; ++row) {
    bool seen = false;
    for (std::size_t c = 0; c < s.alive.size() && !seen; ++c)
      if (s.alive[c] && row < s.results.size() && !std::isnan(s.results[row][c])) seen = true;
    if (!seen) return false;
  }
  return true;
}

// Last row holding a result of a configuration that is still protected as elite (irace update.elite.safe).
std::size_t last_elite_row(const RaceState& s) {
  std::size_t last = 0;
  for (std::size_t row = 0; row < s.results.size(); ++row)
    for (std::size_t c = 0; c < s.is_elite.size(); ++c)
      if (s.is_elite[c] > 0 && !std::isnan(s.results[row][c])) last = row + 1;
  return last;
}

CostMatrix submatrix(const std::vector<std::vector<double>>& results, const std::vector<std::size_t>& rows,
                     const std::vector<std::size_t>& cols) {
  CostMatrix m(rows.size(), cols.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < cols.size(); ++j) m.at(i, j) = results[rows[i]][cols[j]];
  return m;
}

void finish(RaceState& s, std::string reason) {
  s.finished = true;
  s.stop_reason = std::move(reason);
}

}  // namespace

std::size_t RaceState::nb_alive() const {
  return static_cast<std::size_t>(std::count(alive.begin(), alive.end(), char{1}));
}

RaceState start_race(const RaceSettings& settings, std::vector<int> config_ids, std::size_t n_elites,
                     std::size_t n_old, std::size_t n_new, std::size_t n_positions, bool sample_instances,
                     const ResultLookup& lookup, Rng& rng) {
  RaceState s;
  const std::size_t n = config_ids.size();
  if (settings.max_experiments > 0 && static_cast<long long>(n) > settings.max_experiments)
    throw std::invalid_argument("race: the budget is smaller than the number of configurations");
  if (static_cast<long long>(n) <= settings.min_survival)
    throw std::invalid_argument("race: not enough configurations for a race");
  s.config_ids = std::move(config_ids);
  if (!settings.elitist) {
    s.future_begin = n_old + 1;  // non-elitist races only use unseen positions
    if (s.future_begin > n_positions) throw std::logic_error("race: no unseen instance left");
    s.n_tasks = n_positions - n_old;
  } else if (n_old == 0) {
    s.n_tasks = n_positions;
  } else {
    // New instances first, then every old one (in random order), then unseen ones.
    if (n_old + n_new > n_positions) throw std::logic_error("race: the instance list is too short");
    for (std::size_t p = n_old + 1; p <= n_old + n_new; ++p) s.head.push_back(p);
    std::vector<std::size_t> past(n_old);
    std::iota(past.begin(), past.end(), std::size_t{1});
    if (sample_instances)
      for (std::size_t i = past.size(); i > 1; --i) std::swap(past[i - 1], past[rng.below(static_cast<std::uint32_t>(i))]);
    s.head.insert(s.head.end(), past.begin(), past.end());
    s.future_begin = n_old + n_new + 1;
    s.n_tasks = n_positions;
    s.n_new = n_new;
    s.n_old = n_old;
  }
  s.alive.assign(n, 1);
  s.rejected.assign(n, 0);
  s.is_elite.assign(n, 0);
  s.has_elite_data = settings.elitist && n_elites > 0 && n_old > 0;
  if (s.has_elite_data) {
    s.elite_safe = n_new + n_old;
    s.results.assign(s.elite_safe, std::vector<double>(n, std::nan("")));
    for (std::size_t row = 0; row < s.elite_safe; ++row)
      for (std::size_t c = 0; c < n_elites; ++c) {
        const double v = lookup(s.position_of(row + 1), s.config_ids[c]);
        s.results[row][c] = v;
        if (!std::isnan(v)) ++s.is_elite[c];
      }
  }
  return s;
}

namespace {

/// Why the race stops before task k, or nothing (irace's stop rules, checked before a step's
/// runs): too few survivors, the budget of the next test, tests without elimination. An
/// elitist race never stops before every old instance has a result of a survivor.
std::optional<std::string> stop_reason(const RaceState& s, const RaceSettings& settings, std::size_t k,
                                       std::size_t runs_needed) {
  const auto first_test = static_cast<std::size_t>(settings.first_test);
  const auto each_test = static_cast<std::size_t>(settings.each_test);
  if (k > first_test) {
    if (static_cast<long long>(s.nb_alive()) <= settings.min_survival && all_old_instances_evaluated(s, settings))
      return "number of alive configurations (" + std::to_string(s.nb_alive()) +
             ") <= minimum number of configurations (" + std::to_string(settings.min_survival) + ")";
    const long long next_test_cost = s.experiments_used + static_cast<long long>(runs_needed * each_test);
    if (settings.max_experiments > 0 && (k - 1) % each_test == 0 && next_test_cost > settings.max_experiments &&
        all_old_instances_evaluated(s, settings))
      return "experiments for next test (" + std::to_string(next_test_cost) + ") > max experiments (" +
             std::to_string(settings.max_experiments) + ")";
  }
  if (settings.elitist && settings.elitist_limit != 0 && s.no_elimination >= settings.elitist_limit &&
      all_old_instances_evaluated(s, settings))
    return "tests without elimination (" + std::to_string(s.no_elimination) + ") >= elitistLimit (" +
           std::to_string(settings.elitist_limit) + ")";
  return std::nullopt;
}

/// Stores task k's costs, in column order, and passes them on to env.record.
void record_results(RaceState& s, RaceEnvironment& env, std::span<const std::size_t> columns,
                    std::span<const double> costs, std::size_t k) {
  const std::size_t position = s.position_of(k);
  for (std::size_t e = 0; e < columns.size(); ++e) {
    const int id = s.config_ids[columns[e]];
    if (std::isnan(costs[e]))
      throw std::runtime_error("the cost of configuration " + std::to_string(id) + " is not a number");
    s.results[k - 1][columns[e]] = costs[e];
    if (env.record) env.record(position, id, costs[e]);
  }
  s.experiments_used += static_cast<long long>(columns.size());
}

/// Who is eliminated after task k (irace's step after the runs): Inf costs at once, then the
/// statistical test on the first k tasks; elites stay until they have seen their old
/// instances. Updates the leader and the count of tests without elimination.
void eliminate(RaceState& s, const RaceSettings& settings, std::span<const std::size_t> ran, std::size_t k) {
  const std::size_t ncols = s.config_ids.size();
  const auto first_test = static_cast<std::size_t>(settings.first_test);
  const auto each_test = static_cast<std::size_t>(settings.each_test);
  // Elites that already had this instance count down their protection.
  for (std::size_t c = 0; c < ncols; ++c)
    if (s.is_elite[c] > 0 && std::find(ran.begin(), ran.end(), c) == ran.end()) --s.is_elite[c];

  // Inf = immediate rejection.
  bool any_rejected = false;
  for (std::size_t c : ran)
    if (std::isinf(s.results[k - 1][c])) {
      s.rejected[c] = 1;
      s.is_elite[c] = 0;
      s.alive[c] = 0;
      any_rejected = true;
    }
  if (any_rejected) {
    if (s.nb_alive() == 0) throw std::runtime_error("all configurations have been immediately rejected (cost Inf)");
    s.elite_safe = last_elite_row(s);
  }

  const std::vector<std::size_t> which_alive = alive_columns(s);
  std::vector<std::size_t> rows(k);
  std::iota(rows.begin(), rows.end(), std::size_t{0});
  std::vector<char> keep = s.alive;
  if (k >= first_test && k % each_test == 0 && which_alive.size() > 1) {
    const RaceTestOutcome t = race_test(submatrix(s.results, rows, which_alive), settings.confidence);
    for (std::size_t j = 0; j < which_alive.size(); ++j) keep[which_alive[j]] = t.keep[j] ? 1 : 0;
  }
  const std::size_t alive_before = which_alive.size();
  s.alive = keep;
  if (s.has_elite_data)
    for (std::size_t c = 0; c < ncols; ++c)
      if (s.is_elite[c] > 0) s.alive[c] = 1;  // elites are protected until they have seen their old instances

  if (which_alive.size() == 1) {
    s.best = which_alive[0];
  } else {
    const auto sums = friedman_rank_sums(submatrix(s.results, rows, which_alive));
    s.best = which_alive[static_cast<std::size_t>(std::min_element(sums.begin(), sums.end()) - sums.begin())];
  }
  if (settings.elitist && !any_elite(s) && k > first_test && k % each_test == 0)
    s.no_elimination = s.nb_alive() == alive_before ? s.no_elimination + 1 : 0;
}

}  // namespace

std::size_t race_step(RaceState& s, const RaceSettings& settings, RaceEnvironment& env) {
  if (s.finished) return 0;
  const std::size_t k = s.next_task;
  if (k > s.n_tasks) {
    finish(s, "all instances (" + std::to_string(s.n_tasks) + ") evaluated");
    return 0;
  }
  // Which configurations: the alive ones; elites do not rerun instances they have already seen.
  std::vector<std::size_t> which_exe = alive_columns(s);
  if (settings.elitist && any_elite(s)) {
    std::erase_if(which_exe, [&](std::size_t c) { return !std::isnan(s.results[k - 1][c]); });
    if (which_exe.empty()) {
      for (int& e : s.is_elite)
        if (e > 0) --e;
      ++s.next_task;
      return 0;
    }
  }
  if (auto reason = stop_reason(s, settings, k, which_exe.size())) {
    finish(s, std::move(*reason));
    return 0;
  }
  while (s.results.size() < k) s.results.emplace_back(s.config_ids.size(), std::nan(""));
  BatchPlan batch = plan_batch(s, which_exe, k, static_cast<std::size_t>(settings.first_test), env);
  run_batch(batch, s, env);
  record_results(s, env, which_exe, batch.costs, k);
  eliminate(s, settings, which_exe, k);
  ++s.next_task;
  return which_exe.size();
}

void rebuild_results(RaceState& s, std::size_t rows, const ResultLookup& lookup) {
  s.results.assign(rows, std::vector<double>(s.config_ids.size(), std::nan("")));
  for (std::size_t row = 0; row < rows; ++row)
    for (std::size_t c = 0; c < s.config_ids.size(); ++c) s.results[row][c] = lookup(s.position_of(row + 1), s.config_ids[c]);
}

std::vector<double> overall_ranks(const std::vector<std::vector<double>>& results, const std::vector<std::size_t>& cols) {
  if (cols.size() == 1) return {1.0};
  std::vector<std::size_t> count(cols.size(), 0);
  for (const auto& row : results)
    for (std::size_t j = 0; j < cols.size(); ++j)
      if (!std::isnan(row[cols[j]])) ++count[j];
  const std::set<std::size_t, std::greater<>> distinct(count.begin(), count.end());
  std::vector<double> ranks(cols.size(), kInf);
  double last = 0.0;
  for (std::size_t n : distinct) {
    std::vector<std::size_t> group;  // indices into cols
    for (std::size_t j = 0; j < cols.size(); ++j)
      if (count[j] == n) group.push_back(j);
    std::vector<double> r(group.size(), 1.0);
    if (group.size() > 1) {
      std::vector<std::size_t> rows, gcols;
      for (std::size_t j : group) gcols.push_back(cols[j]);
      for (std::size_t i = 0; i < results.size(); ++i)
        if (std::all_of(gcols.begin(), gcols.end(), [&](std::size_t c) { return !std::isnan(results[i][c]); }))
          rows.push_back(i);
      r = rows.empty() ? std::vector<double>(group.size(), 0.0) : friedman_rank_sums(submatrix(results, rows, gcols));
    }
    double mx = -kInf;
    for (std::size_t g = 0; g < group.size(); ++g) {
      ranks[group[g]] = r[g] + last;
      mx = std::max(mx, ranks[group[g]]);
    }
    last = mx;
  }
  return ranks;
}

RaceResult finish_race(const RaceState& s) {
  std::vector<std::vector<double>> kept;
  for (const auto& row : s.results)
    if (std::any_of(row.begin(), row.end(), [](double v) { return !std::isnan(v); })) kept.push_back(row);
  const std::vector<std::size_t> cols = alive_columns(s);
  const std::size_t n = s.config_ids.size();
  std::vector<double> rank(n, kInf);
  if (!cols.empty()) {
    const auto r = overall_ranks(kept, cols);
    for (std::size_t j = 0; j < cols.size(); ++j) rank[cols[j]] = r[j];
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank[a] < rank[b]; });
  RaceResult out;
  for (std::size_t c : order) {
    out.ids.push_back(s.config_ids[c]);
    out.ranks.push_back(rank[c]);
    out.alive.push_back(s.alive[c]);
  }
  out.nb_alive = cols.size();
  for (std::size_t c = 0; c < n; ++c)
    if (s.rejected[c]) out.rejected_ids.push_back(s.config_ids[c]);
  out.experiments_used = s.experiments_used;
  return out;
}

std::vector<Elite> extract_elites(const RaceResult& result, const ConfigurationStore& store, std::size_t nb_elites) {
  if (nb_elites < 1) throw std::logic_error("extract_elites: nb_elites < 1");
  struct Candidate {
    int id;
    double rank;
  };
  std::vector<Candidate> alive;
  for (std::size_t i = 0; i < result.ids.size(); ++i)
    if (result.alive[i]) alive.push_back({result.ids[i], result.ranks[i]});
  std::sort(alive.begin(), alive.end(), [](const Candidate& a, const Candidate& b) { return a.id < b.id; });
  std::vector<Candidate> unique;
  std::unordered_set<std::string> seen;
  for (const Candidate& c : alive)
    if (seen.insert(store[c.id].config.key()).second) unique.push_back(c);
  std::stable_sort(unique.begin(), unique.end(), [](const Candidate& a, const Candidate& b) { return a.rank < b.rank; });
  const std::size_t n = std::min(unique.size(), nb_elites);
  std::vector<Elite> elites;
  const double total = static_cast<double>(n * (n + 1)) / 2;
  for (std::size_t r = 1; r <= n; ++r) elites.push_back({unique[r - 1].id, static_cast<double>(n - r + 1) / total});
  return elites;
}

}  // namespace sd::design
