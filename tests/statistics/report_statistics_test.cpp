// The report's and the calibration's statistics compared with R, live: each test generates its
// data sets in C++, runs one Rscript on them and compares every value R prints
// (sprintf('%.17g')). Tests that need R skip when Rscript is not on the PATH. A few
// hand-checked cases run without R.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "statistics/box_stats.hpp"
#include "statistics/correlation.hpp"
#include "statistics/descriptive.hpp"
#include "statistics/expected_ranks.hpp"
#include "statistics/rank_sum.hpp"
#include "statistics/sign_test.hpp"
#include "statistics/welch.hpp"

using namespace sd::statistics;

namespace {

namespace fs = std::filesystem;
using RResults = std::map<std::string, std::vector<double>>;

bool rscript_on_path() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream dirs(path);
  std::string dir;
  std::error_code ec;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && fs::exists(fs::path(dir) / "Rscript", ec)) return true;
  return false;
}

#define SKIP_WITHOUT_R()                                                                      \
  if (!rscript_on_path()) GTEST_SKIP() << "Rscript is not on the PATH: the comparisons with " \
                                          "R need R (e.g. the r-cran-irace package)"

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// R prints every result as a line "key v1 v2 ...", each value with 17 significant digits.
const char* const kRPrelude =
    "emit <- function(key, v) cat(key, sprintf('%.17g', as.double(v)), '\\n')\n";

// Runs the script with Rscript and parses its lines; on failure returns nothing and says why.
std::optional<RResults> run_r(const std::string& body, std::string& error) {
  static int calls = 0;
  const std::string stem = "swarmdesign_statistics_test_" + std::to_string(::getpid()) + "_" + std::to_string(++calls);
  const fs::path script = fs::temp_directory_path() / (stem + ".R");
  const fs::path errors = fs::temp_directory_path() / (stem + ".err");
  std::ofstream(script) << kRPrelude << body;
  const std::string command = "Rscript --vanilla '" + script.string() + "' 2>'" + errors.string() + "'";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) {
    error = "popen failed: " + command;
    return std::nullopt;
  }
  std::string out;
  char buffer[4096];
  while (std::size_t got = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, got);
  const int status = ::pclose(pipe);
  const std::string r_errors = slurp(errors);
  fs::remove(script);
  fs::remove(errors);
  if (status != 0) {
    error = "Rscript failed (status " + std::to_string(status) + "):\n" + r_errors;
    return std::nullopt;
  }
  RResults results;
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::string key, value;
    if (!(fields >> key)) continue;
    auto& values = results[key];
    while (fields >> value) values.push_back(std::strtod(value.c_str(), nullptr));  // reads NaN, Inf too
  }
  return results;
}

std::string r_vector(const std::vector<double>& v) {
  if (v.empty()) return "numeric(0)";
  std::ostringstream s;
  s << std::setprecision(17) << "c(";
  for (std::size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
  s << ")";
  return s.str();
}

std::string show(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

// Counts and checks the comparisons of one test; failures name the value and show both sides.
class Compare {
 public:
  explicit Compare(const RResults& r) : r_(r) {}
  ~Compare() { std::cout << "[ compared  ] " << count_ << " values with R\n"; }

  const std::vector<double>& r(const std::string& key) const {
    static const std::vector<double> none;
    const auto it = r_.find(key);
    if (it != r_.end()) return it->second;
    ADD_FAILURE() << "R printed no " << key;
    return none;
  }
  // First value of an R line, NaN if missing (the failure is already recorded).
  double r1(const std::string& key) const {
    const auto& v = r(key);
    if (v.empty()) {
      ADD_FAILURE() << "R printed no value for " << key;
      return std::nan("");
    }
    return v.front();
  }

  void absolute(const std::string& what, double ours, double theirs, double tol = 1e-9) {
    check(what, ours, theirs, std::fabs(ours - theirs) <= tol);
  }
  void relative(const std::string& what, double ours, double theirs, double tol = 1e-9) {
    check(what, ours, theirs, ours == theirs || std::fabs(ours - theirs) <= tol * std::fabs(theirs));
  }
  void relative(const std::string& what, const std::vector<double>& ours, const std::vector<double>& theirs) {
    if (ours.size() != theirs.size()) {
      ADD_FAILURE() << what << ": ours has " << ours.size() << " values, R " << theirs.size();
      return;
    }
    for (std::size_t i = 0; i < ours.size(); ++i) relative(what + "[" + std::to_string(i) + "]", ours[i], theirs[i]);
  }

 private:
  void check(const std::string& what, double ours, double theirs, bool close) {
    ++count_;
    const bool both_nan = std::isnan(ours) && std::isnan(theirs);
    if (!close && !both_nan) ADD_FAILURE() << what << ": ours " << show(ours) << ", R " << show(theirs);
  }
  const RResults& r_;
  int count_ = 0;
};

// Deterministic normal samples, rounded to `decimals` (negative: not rounded) so that some data
// sets have ties. The same numbers are sent to R, so the generator need not match R's.
class Data {
 public:
  explicit Data(std::uint64_t seed) : rng_(seed) {}
  std::vector<double> normal(std::size_t n, double mean = 0, double sd = 1, int decimals = -1) {
    std::normal_distribution<double> dist(mean, sd);
    std::vector<double> v(n);
    for (auto& x : v) x = round_to(dist(rng_), decimals);
    return v;
  }

 private:
  static double round_to(double x, int decimals) {
    if (decimals < 0) return x;
    const double scale = std::pow(10.0, decimals);
    return std::round(x * scale) / scale;
  }
  std::mt19937_64 rng_;
};

struct TwoSamples {
  std::string name;
  std::vector<double> x, y;
};

std::vector<TwoSamples> rank_sum_data() {
  Data d(20240501);
  std::vector<TwoSamples> sets{
      {"2v2", d.normal(2), d.normal(2)},
      {"2v2_apart", {1, 2}, {3, 4}},
      {"3v3", d.normal(3), d.normal(3, 1)},
      {"3v5", d.normal(3), d.normal(5)},
      {"1v1", {0.5}, {1.5}},
      {"1v4", d.normal(1, 2), d.normal(4)},
      {"10v10", d.normal(10), d.normal(10, 0.5)},
      {"10v10_apart", d.normal(10, 5), d.normal(10)},  // W = 100: the smallest exact p
      {"12v9", d.normal(12), d.normal(9, -0.8)},
      {"5v5_one_tie", {1.5, 2.25, 3, 4, 5}, {0.5, 2.25, 6, 7, 8}},
      {"10v10_ties", d.normal(10, 0, 2, 0), d.normal(10, 0.5, 2, 0)},
      {"15v12_ties", d.normal(15, 0, 1, 1), d.normal(12, 0.3, 1, 1)},
      {"8v8_ties_apart", d.normal(8, 3, 1, 0), d.normal(8, 0, 1, 0)},
      {"30v30_ties", d.normal(30, 0, 1, 1), d.normal(30, 0.6, 1, 1)},
      {"20v3_integers", d.normal(20, 2, 1.5, 0), d.normal(3, 4, 1.5, 0)},
      {"60v55", d.normal(60), d.normal(55, 0.2)},
      {"60v55_apart", d.normal(60, 1), d.normal(55)},
      {"49v49", d.normal(49), d.normal(49, 0.4)},  // the largest exact case
      {"49v50", d.normal(49), d.normal(50, 0.4)},
  };
  const auto same = d.normal(6, 0, 1, 2);
  sets.push_back({"identical", same, same});
  sets.push_back({"constant", {2, 2, 2}, {2, 2}});  // no spread: R's p-value is NaN
  return sets;
}

struct Matrix {
  std::string name;
  std::vector<std::vector<double>> values;
  std::vector<bool> higher_is_better;
  double confidence = 0.95;
};

// Condition j's value on a block: effect[j] in the block's better direction plus noise.
Matrix friedman_matrix(const std::string& name, Data& d, std::size_t blocks, const std::vector<double>& effect,
                       double noise, int decimals, double confidence = 0.95) {
  Matrix m{name, {}, {}, confidence};
  for (std::size_t b = 0; b < blocks; ++b) {
    const bool maximise = b % 2 == 0 || b == 3;
    auto row = d.normal(effect.size(), 0, noise, -1);
    for (std::size_t j = 0; j < effect.size(); ++j) {
      const double v = (maximise ? effect[j] : -effect[j]) + row[j];
      row[j] = std::round(v * std::pow(10.0, decimals)) / std::pow(10.0, decimals);
    }
    m.values.push_back(row);
    m.higher_is_better.push_back(maximise);
  }
  return m;
}

std::vector<Matrix> friedman_data() {
  Data d(77);
  std::vector<Matrix> sets{
      friedman_matrix("k2_null", d, 5, {0, 0}, 1, 2),
      friedman_matrix("k2_effect", d, 5, {3, 0}, 0.5, 2),
      friedman_matrix("k3_ties", d, 5, {0, 0.5, 1}, 1, 0),
      friedman_matrix("k3_effect", d, 5, {6, 3, 0}, 0.5, 1),  // perfect agreement: CD 0
      friedman_matrix("k3_noisy_effect", d, 5, {3, 1.5, 0}, 2, 1),
      friedman_matrix("k4_null", d, 5, {0, 0, 0, 0}, 1, 2),
      friedman_matrix("k4_effect", d, 5, {0, 2, 4, 6}, 0.7, 1),
      friedman_matrix("k4_effect_90", d, 5, {0, 1.5, 3, 4.5}, 1.2, 1, 0.90),
      friedman_matrix("k3_10blocks", d, 10, {0, 0.8, 1.6}, 1, 1),
  };
  Matrix tied_row = friedman_matrix("k4_tied_row", d, 5, {0, 2, 4, 6}, 0.5, 1);
  tied_row.values[2] = {1, 1, 1, 1};
  sets.push_back(tied_row);
  sets.push_back(
      {"k3_all_tied", {{1, 1, 1}, {2, 2, 2}, {0, 0, 0}, {5, 5, 5}, {3, 3, 3}}, {true, false, true, true, false}});
  sets.push_back({"k2_ties", {{1, 2}, {2, 2}, {3, 1}, {4, 4}, {0, 1}}, {true, false, false, true, true}});
  return sets;
}

}  // namespace

TEST(statistics_Report, RankSumHandExamples) {
  // x entirely below y: W = 0 and P(W <= 0) = 1 / choose(5, 2).
  const RankSumTest below = wilcoxon_rank_sum(std::vector<double>{1, 2, 3}, std::vector<double>{4, 5});
  EXPECT_EQ(below.statistic, 0.0);
  EXPECT_TRUE(below.exact);
  EXPECT_NEAR(below.p_value, 0.2, 1e-15);
  const RankSumTest above = wilcoxon_rank_sum(std::vector<double>{4, 5}, std::vector<double>{1, 2, 3});
  EXPECT_EQ(above.statistic, 6.0);
  EXPECT_NEAR(above.p_value, 0.2, 1e-15);
  // A tie forces the normal approximation.
  EXPECT_FALSE(wilcoxon_rank_sum(std::vector<double>{1, 2, 3}, std::vector<double>{3, 4}).exact);
  EXPECT_THROW(wilcoxon_rank_sum(std::vector<double>{}, std::vector<double>{1}), std::invalid_argument);
  EXPECT_THROW(wilcoxon_rank_sum(std::vector<double>{1}, std::vector<double>{std::nan("")}), std::invalid_argument);
  EXPECT_NEAR(pwilcox(0, 2, 2), 1.0 / 6, 1e-15);
  EXPECT_EQ(pwilcox(-1, 3, 3), 0.0);
  EXPECT_EQ(pwilcox(9, 3, 3), 1.0);
}

TEST(statistics_Report, BoxStatsHandExamples) {
  const BoxStats b = box_stats(std::vector<double>{4, 100, 2, 1, 3});
  EXPECT_EQ(b.n, 5u);
  EXPECT_EQ(b.min, 1.0);
  EXPECT_EQ(b.q1, 2.0);
  EXPECT_EQ(b.median, 3.0);
  EXPECT_EQ(b.q3, 4.0);
  EXPECT_EQ(b.max, 100.0);
  EXPECT_EQ(b.whisker_low, 1.0);
  EXPECT_EQ(b.whisker_high, 4.0);  // 100 > 4 + 1.5 * 2
  EXPECT_EQ(b.outliers, std::vector<double>{100});
  EXPECT_EQ(median(std::vector<double>{4, 1, 3, 2}), 2.5);
  EXPECT_THROW(box_stats(std::vector<double>{}), std::invalid_argument);
  EXPECT_THROW(median(std::vector<double>{}), std::invalid_argument);
}

TEST(statistics_Report, ExpectedRanksHandExamples) {
  // Block 0 maximised, block 1 minimised: condition 1 is best in both.
  const ExpectedRanks e = expected_ranks({{1, 5}, {7, 2}}, {true, false});
  EXPECT_EQ(e.mean_ranks, (std::vector<double>{2, 1}));
  EXPECT_EQ(e.df, 1);
  EXPECT_FALSE(e.critical_difference.has_value());  // p = 0.157 with two blocks
  // Five blocks that all agree: p = 0.025 rejects, and without any disagreement the CD is 0.
  const ExpectedRanks agree =
      expected_ranks({{1, 2}, {1, 2}, {2, 1}, {1, 2}, {2, 1}}, {false, false, true, false, true});
  EXPECT_EQ(agree.mean_ranks, (std::vector<double>{1, 2}));
  ASSERT_TRUE(agree.critical_difference.has_value());
  EXPECT_EQ(*agree.critical_difference, 0.0);
  EXPECT_THROW(expected_ranks({{1, 2}, {3}}, {true, true}), std::invalid_argument);
  EXPECT_THROW(expected_ranks({{1, 2}}, {true, false}), std::invalid_argument);
  EXPECT_THROW(expected_ranks({{1}, {2}}, {true, true}), std::invalid_argument);
}

TEST(statistics_Report, RankSumMatchesR) {
  SKIP_WITHOUT_R();
  const auto sets = rank_sum_data();
  std::string script;
  for (const auto& s : sets) {
    script += "t <- suppressWarnings(wilcox.test(" + r_vector(s.x) + ", " + r_vector(s.y) + "))\n";
    script += "emit('" + s.name + ".W', t$statistic); emit('" + s.name + ".p', t$p.value); emit('" + s.name +
              ".exact', grepl('exact', t$method))\n";
  }
  std::string error;
  const auto r = run_r(script, error);
  ASSERT_TRUE(r) << error;
  Compare cmp(*r);
  for (const auto& s : sets) {
    const RankSumTest ours = wilcoxon_rank_sum(s.x, s.y);
    cmp.relative(s.name + " W", ours.statistic, cmp.r1(s.name + ".W"));
    cmp.absolute(s.name + " p", ours.p_value, cmp.r1(s.name + ".p"));
    cmp.absolute(s.name + " exact", ours.exact ? 1 : 0, cmp.r1(s.name + ".exact"), 0);
  }
}

TEST(statistics_Report, PwilcoxMatchesR) {
  SKIP_WITHOUT_R();
  struct Case {
    double q;
    int m, n;
  };
  const std::vector<Case> cases{{0, 1, 1},     {0.5, 1, 1},     {3, 2, 2},       {2.99999999, 2, 2}, {5, 3, 5},
                                {-1, 4, 4},    {16, 4, 4},      {7.5, 4, 4},     {3, 7, 3},          {30, 10, 10},
                                {50, 10, 10},  {70, 10, 10},    {100, 20, 15},   {150, 30, 20},      {0, 49, 49},
                                {600, 49, 49}, {1200, 49, 49},  {2000, 49, 49},  {2400, 49, 49},     {40, 3, 45}};
  std::string script;
  for (std::size_t i = 0; i < cases.size(); ++i)
    script += "emit('p" + std::to_string(i) + "', pwilcox(" + show(cases[i].q) + ", " + std::to_string(cases[i].m) +
              ", " + std::to_string(cases[i].n) + "))\n";
  std::string error;
  const auto r = run_r(script, error);
  ASSERT_TRUE(r) << error;
  Compare cmp(*r);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    const std::string what = "pwilcox(" + show(c.q) + ", " + std::to_string(c.m) + ", " + std::to_string(c.n) + ")";
    const double theirs = cmp.r1("p" + std::to_string(i)), ours = pwilcox(c.q, c.m, c.n);
    cmp.absolute(what, ours, theirs);
    cmp.relative(what + " (relative)", ours, theirs);  // the far tails too
  }
}

TEST(statistics_Report, BoxStatsMatchR) {
  SKIP_WITHOUT_R();
  Data d(4242);
  std::vector<std::pair<std::string, std::vector<double>>> sets{
      {"n1", {3.5}},
      {"n2", {4, 1}},
      {"n3", {5, 1, 3}},
      {"n4", d.normal(4)},
      {"n5_outlier", {4, 100, 2, 1, 3}},
      {"n20", d.normal(20, 10, 2, 2)},
      {"n11_ties", {3, 1, 1, 2, 2, 2, 3, 1, 3, 3, 10}},
      {"constant", {2, 2, 2, 2}},
      {"n7_low_outliers", {-50, 10, 11, 12, 13, 14, -40}},
  };
  auto with_outliers = d.normal(30, 0, 1, 3);
  with_outliers.insert(with_outliers.begin() + 5, {-8.5, 9.25, 12});
  sets.push_back({"n33_outliers", with_outliers});
  auto heavy = d.normal(50, 0, 1, -1);
  for (std::size_t i = 0; i < heavy.size(); i += 7) heavy[i] *= 25;  // heavy tails on both sides
  sets.push_back({"n50_heavy", heavy});

  std::string script;
  for (const auto& [name, x] : sets) {
    script += "x <- " + r_vector(x) + "; b <- boxplot.stats(x)\n";
    script += "emit('" + name + ".n', b$n); emit('" + name + ".fivenum', fivenum(x)); emit('" + name +
              ".stats', b$stats); emit('" + name + ".conf', b$conf); emit('" + name + ".out', sort(b$out)); emit('" +
              name + ".median', median(x))\n";
  }
  std::string error;
  const auto r = run_r(script, error);
  ASSERT_TRUE(r) << error;
  Compare cmp(*r);
  for (const auto& [name, x] : sets) {
    const BoxStats b = box_stats(x);
    cmp.relative(name + " n", static_cast<double>(b.n), cmp.r1(name + ".n"));
    cmp.relative(name + " fivenum", {b.min, b.q1, b.median, b.q3, b.max}, cmp.r(name + ".fivenum"));
    cmp.relative(name + " stats", {b.whisker_low, b.q1, b.median, b.q3, b.whisker_high}, cmp.r(name + ".stats"));
    cmp.relative(name + " conf", {b.notch_low, b.notch_high}, cmp.r(name + ".conf"));
    cmp.relative(name + " out", b.outliers, cmp.r(name + ".out"));
    cmp.relative(name + " median", median(x), cmp.r1(name + ".median"));
  }
}

TEST(statistics_Report, ExpectedRanksMatchR) {
  SKIP_WITHOUT_R();
  const auto sets = friedman_data();
  std::string script;
  for (const auto& s : sets) {
    std::vector<double> flat;
    std::string hib;
    for (std::size_t b = 0; b < s.values.size(); ++b) {
      flat.insert(flat.end(), s.values[b].begin(), s.values[b].end());
      hib += std::string(b ? ", " : "") + (s.higher_is_better[b] ? "TRUE" : "FALSE");
    }
    const std::string k = "'" + s.name + ".";
    script += "m <- matrix(" + r_vector(flat) + ", nrow = " + std::to_string(s.values.size()) + ", byrow = TRUE)\n";
    script += "m <- m * ifelse(c(" + hib + "), -1, 1); conf <- " + show(s.confidence) + "\n";
    script += "f <- friedman.test(m); r <- t(apply(m, 1, rank)); b <- nrow(m); k <- ncol(m)\n";
    script += "A <- sum(r^2); R <- colSums(r); df <- (b - 1) * (k - 1)\n";
    script += "emit(" + k + "stat', f$statistic); emit(" + k + "p', f$p.value); emit(" + k +
              "df', f$parameter); emit(" + k + "mean_ranks', colMeans(r))\n";
    script += "has_cd <- !is.na(f$p.value) && f$p.value < 1 - conf; emit(" + k +
              "has_cd', has_cd)\n";
    script += "if (has_cd) emit(" + k + "cd', qt(1 - (1 - conf) / 2, df) * sqrt(2 * (b * A - sum(R^2)) / df) / b)\n";
  }
  std::string error;
  const auto r = run_r(script, error);
  ASSERT_TRUE(r) << error;
  Compare cmp(*r);
  int with_cd = 0;
  for (const auto& s : sets) {
    const ExpectedRanks e = expected_ranks(s.values, s.higher_is_better, s.confidence);
    const std::string k = s.name + ".";
    cmp.relative(s.name + " statistic", e.statistic, cmp.r1(k + "stat"));
    cmp.absolute(s.name + " p", e.p_value, cmp.r1(k + "p"));
    cmp.relative(s.name + " df", e.df, cmp.r1(k + "df"));
    cmp.relative(s.name + " mean ranks", e.mean_ranks, cmp.r(k + "mean_ranks"));
    cmp.absolute(s.name + " has CD", e.critical_difference ? 1 : 0, cmp.r1(k + "has_cd"), 0);
    if (e.critical_difference && cmp.r1(k + "has_cd") == 1) {
      cmp.relative(s.name + " CD", *e.critical_difference, cmp.r1(k + "cd"));
      ++with_cd;
    }
  }
  EXPECT_GE(with_cd, 5) << "the data sets should exercise the critical difference";
}

// Reference values from R 4.2 (t.test, binom.test, cor(method = "spearman")).
TEST(statistics_Report, WelchTestMatchesR) {
  const std::vector<double> x{3.1, 4.5, 2.2, 8.9, 5.0, 6.1}, y{7.2, 6.6, 9.1, 8.0, 10.5};
  const WelchTest t = welch_t_test(x, y);
  EXPECT_NEAR(t.statistic, -2.7799873014646894, 1e-12);
  EXPECT_NEAR(t.df, 8.6212964194514115, 1e-10);
  EXPECT_NEAR(t.p_value, 0.0222775570094685, 1e-10);
  const std::vector<double> a{1, 2, 3, 4, 5.5}, b{2, 4, 6, 8, 9, 11};
  EXPECT_NEAR(welch_t_test(a, b).p_value, 0.0532107998388449, 1e-10);
}

TEST(statistics_Report, WelchTestOnConstantSamplesPassesOnlyWhenEqual) {
  const std::vector<double> zeros(20, 0.0), ones(20, 1.0);
  EXPECT_EQ(welch_t_test(zeros, zeros).p_value, 1.0);
  EXPECT_EQ(welch_t_test(zeros, ones).p_value, 0.0);
  EXPECT_THROW(welch_t_test(std::vector<double>{1.0}, zeros), std::invalid_argument);
}

TEST(statistics_Report, SignTestMatchesR) {
  EXPECT_NEAR(sign_test_p_value(3, 15), 0.03515625, 1e-12);
  EXPECT_NEAR(sign_test_p_value(12, 15), 0.03515625, 1e-12);
  EXPECT_NEAR(sign_test_p_value(7, 15), 1.0, 1e-12);
  EXPECT_NEAR(sign_test_p_value(0, 5), 0.0625, 1e-12);
  EXPECT_NEAR(sign_test_p_value(12, 14), 0.012939453125, 1e-12);
  EXPECT_EQ(sign_test_p_value(0, 0), 1.0);
}

TEST(statistics_Report, SpearmanMatchesR) {
  EXPECT_NEAR(spearman_rho(std::vector<double>{1, 2, 3, 4, 5}, std::vector<double>{2, 1, 4, 3, 5}), 0.8, 1e-12);
  EXPECT_NEAR(spearman_rho(std::vector<double>{1, 2, 2, 4, 5}, std::vector<double>{2, 1, 4, 4, 5}), 0.763157894736842, 1e-12);
  EXPECT_NEAR(spearman_rho(std::vector<double>{10, 20, 30, 40}, std::vector<double>{4, 3, 2, 1}), -1.0, 1e-12);
  EXPECT_TRUE(std::isnan(spearman_rho(std::vector<double>{1, 1, 1}, std::vector<double>{1, 2, 3})));
}
