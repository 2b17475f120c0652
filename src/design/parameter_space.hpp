#pragma once
// The design space as irace sees it (irace 3.5 R/readParameters.R): named parameters of four
// types, each with a command-line switch, a domain, an activation condition on other parameters
// and, for integers and reals, optionally a domain bound that depends on another parameter.
//
// A Configuration stores one double per parameter: the value for integer/real parameters, the
// index into the domain for categorical/ordinal ones, and NaN ("NA") when the parameter is
// inactive. Doubles keep configurations cheap to copy, compare and serialise.
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sd::design {

enum class ParamType { Categorical, Ordinal, Integer, Real };

inline constexpr double kNA = std::numeric_limits<double>::quiet_NaN();
inline bool is_na(double v) { return std::isnan(v); }

/// One clause of an activation condition. Conditions are AND-ed clauses; a clause over an
/// inactive parameter is false (R: NA in a condition makes the parameter inactive).
struct Clause {
  enum class Op { In, NotIn, Eq, Ne, Gt, Ge, Lt, Le };
  std::string param;                 // name of the parameter the clause reads
  Op op = Op::In;
  std::vector<std::string> values;   // In/NotIn: allowed values, as domain strings (or numbers as text)
  double number = 0.0;               // Eq..Le: compared numerically (categorical values via as.numeric)
};
using Condition = std::vector<Clause>;

/// A numeric domain bound: a constant, or `param + offset` (irace 3.5 dependent domains, e.g.
/// the transition target upper bound "NumStates-2").
struct Bound {
  double constant = 0.0;
  std::string param;  // empty => constant
  double offset = 0.0;
  bool is_dependent() const { return !param.empty(); }
  static Bound fixed(double v) { return {v, {}, 0.0}; }
  static Bound of(std::string p, double offset) { return {0.0, std::move(p), offset}; }
};

struct Parameter {
  std::string name;
  std::string switch_;                 // prefix glued to the value on the command line ("--s0 ")
  ParamType type = ParamType::Categorical;
  std::vector<std::string> values;     // categorical / ordinal domain
  Bound lower, upper;                  // integer / real domain (closed)
  bool log_scale = false;              // irace "i,log" / "r,log"
  Condition condition;

  bool is_numeric() const { return type == ParamType::Integer || type == ParamType::Real; }
  bool is_dependent() const { return lower.is_dependent() || upper.is_dependent(); }
  /// irace: a categorical/ordinal with one value, or an i/r with lb == ub, is fixed.
  bool is_fixed() const;
};

struct Configuration {
  std::vector<double> values;
  bool operator==(const Configuration& o) const;  // NA equals NA
  /// Bytes identifying the configuration exactly (NA canonicalised), for hash sets.
  std::string key() const;
};

class ParameterSpace {
 public:
  /// `digits`: reals are rounded to this many decimal places (irace option `digits`;
  /// AutoMoDe scenarios use 2, irace's default is 4).
  explicit ParameterSpace(int digits = 4) : digits_(digits) {}

  /// Adds a parameter; returns its index. Call finalize() after the last one.
  std::size_t add(Parameter p);
  /// Resolves names, rejects cycles and unknown names, computes the sampling order (irace
  /// `treeLevel`: parameters sorted, stably, by the length of their dependency chain).
  void finalize();

  std::size_t size() const { return params_.size(); }
  const Parameter& operator[](std::size_t i) const { return params_[i]; }
  const std::vector<Parameter>& parameters() const { return params_; }
  std::optional<std::size_t> index_of(std::string_view name) const;
  const std::vector<std::size_t>& sampling_order() const { return order_; }
  /// Number of non-fixed parameters (irace `nbVariable`), drives N_iter and the model.
  std::size_t nb_variable() const;
  int digits() const { return digits_; }

  /// Is parameter i active given the (partial) configuration? Dependencies must be set.
  bool is_active(const Configuration& c, std::size_t i) const;
  /// The current numeric domain [lb, ub] of parameter i (dependent bounds evaluated, truncated
  /// to integers for integer parameters); nullopt when a dependency is NA.
  std::optional<std::pair<double, double>> domain(const Configuration& c, std::size_t i) const;

  /// Round a real as irace does (to `digits` decimals) such that printing and reading back
  /// gives the same double.
  double round_real(double v) const;
  /// The textual value of parameter i (domain string, integer, or real with up to `digits`
  /// decimals, trailing zeros removed); "NA" when inactive.
  std::string value_text(const Configuration& c, std::size_t i) const;
  /// irace's command line: switch+value of every active parameter, in file order, separated
  /// by single spaces.
  std::string render(const Configuration& c) const;
  /// Reads a command line back. Throws std::invalid_argument naming the offending token for
  /// unknown switches, values outside the domain, missing or superfluous parameters.
  Configuration parse(std::string_view command_line) const;
  /// Checks domains and activity; returns an empty string when valid, else the problem.
  std::string validate(const Configuration& c) const;

  /// Index of `text` in the domain of categorical/ordinal parameter i, or nullopt.
  std::optional<std::size_t> value_index(std::size_t i, std::string_view text) const;

 private:
  bool clause_holds(const Configuration& c, const Clause& clause, std::size_t ref) const;
  double bound_value(const Configuration& c, const Bound& b, std::size_t ref) const;
  void require_finalized() const;

  int digits_;
  std::vector<Parameter> params_;
  // Indices of the parameters read by each clause / dependent bound, resolved by finalize().
  std::vector<std::vector<std::size_t>> clause_refs_;
  std::vector<std::pair<std::size_t, std::size_t>> bound_refs_;  // (lower, upper); npos if constant
  std::vector<std::size_t> order_;
  bool finalized_ = false;
};

}  // namespace sd::design
