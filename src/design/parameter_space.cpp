#include "design/parameter_space.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>

namespace sd::design {

namespace {

constexpr std::size_t npos = static_cast<std::size_t>(-1);

std::optional<double> parse_number(std::string_view s) {
  double v = 0.0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (!s.empty() && s.front() == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec != std::errc() || ptr != last || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::vector<std::string_view> split_whitespace(std::string_view s) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    std::size_t j = i;
    while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
    if (j > i) tokens.push_back(s.substr(i, j - i));
    i = j;
  }
  return tokens;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool switch_takes_separate_token(const std::string& sw) {
  return !sw.empty() && std::isspace(static_cast<unsigned char>(sw.back()));
}

}  // namespace

bool Parameter::is_fixed() const {
  if (type == ParamType::Categorical || type == ParamType::Ordinal) return values.size() == 1;
  return !is_dependent() && lower.constant == upper.constant;
}

bool Configuration::operator==(const Configuration& o) const {
  if (values.size() != o.values.size()) return false;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const bool a = is_na(values[i]), b = is_na(o.values[i]);
    if (a != b || (!a && values[i] != o.values[i])) return false;
  }
  return true;
}

std::string Configuration::key() const {
  std::string k(values.size() * sizeof(double), '\0');
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = is_na(values[i]) ? std::numeric_limits<double>::infinity() : values[i];
    std::memcpy(&k[i * sizeof(double)], &v, sizeof(double));
  }
  return k;
}

std::size_t ParameterSpace::add(Parameter p) {
  if (index_of(p.name)) throw std::invalid_argument("duplicated parameter name '" + p.name + "'");
  if (p.name.empty()) throw std::invalid_argument("parameter name must not be empty");
  if ((p.type == ParamType::Categorical || p.type == ParamType::Ordinal)) {
    if (p.values.empty()) throw std::invalid_argument("parameter '" + p.name + "' has an empty domain");
    for (std::size_t i = 0; i < p.values.size(); ++i)
      for (std::size_t j = i + 1; j < p.values.size(); ++j)
        if (p.values[i] == p.values[j])
          throw std::invalid_argument("duplicated value '" + p.values[i] + "' for parameter '" + p.name + "'");
  } else {
    if (p.type == ParamType::Real) {
      if (!p.lower.is_dependent()) p.lower.constant = round_real(p.lower.constant);
      if (!p.upper.is_dependent()) p.upper.constant = round_real(p.upper.constant);
    }
    if (!p.is_dependent() && p.lower.constant >= p.upper.constant)
      throw std::invalid_argument("lower bound must be smaller than upper bound for parameter '" + p.name + "'");
    if (p.log_scale && (p.is_dependent() || p.lower.constant <= 0.0))
      throw std::invalid_argument("log-scale parameter '" + p.name + "' needs a constant positive domain");
  }
  params_.push_back(std::move(p));
  finalized_ = false;
  return params_.size() - 1;
}

std::optional<std::size_t> ParameterSpace::index_of(std::string_view name) const {
  for (std::size_t i = 0; i < params_.size(); ++i)
    if (params_[i].name == name) return i;
  return std::nullopt;
}

void ParameterSpace::finalize() {
  const std::size_t n = params_.size();
  clause_refs_.assign(n, {});
  bound_refs_.assign(n, {npos, npos});
  std::vector<std::vector<std::size_t>> deps(n);
  auto resolve = [&](std::size_t i, const std::string& name) {
    const auto j = index_of(name);
    if (!j)
      throw std::invalid_argument("parameter '" + params_[i].name + "' depends on '" + name +
                                  "' which is not defined");
    return *j;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Parameter& p = params_[i];
    for (const Clause& c : p.condition) {
      const std::size_t j = resolve(i, c.param);
      clause_refs_[i].push_back(j);
      deps[i].push_back(j);
    }
    if (p.lower.is_dependent()) bound_refs_[i].first = resolve(i, p.lower.param);
    if (p.upper.is_dependent()) bound_refs_[i].second = resolve(i, p.upper.param);
    for (std::size_t j : {bound_refs_[i].first, bound_refs_[i].second}) {
      if (j == npos) continue;
      if (!params_[j].is_numeric())
        throw std::invalid_argument("domain of parameter '" + p.name + "' depends on non-numerical parameter '" +
                                    params_[j].name + "'");
      deps[i].push_back(j);
    }
  }
  // Level = 1 + longest chain of dependencies (irace treeLevel); cycles rejected.
  std::vector<int> level(n, 0);  // 0 unknown, -1 in progress
  std::function<int(std::size_t)> visit = [&](std::size_t i) -> int {
    if (level[i] > 0) return level[i];
    if (level[i] < 0)
      throw std::invalid_argument("a cycle detected in subordinate parameters involving '" + params_[i].name + "'");
    level[i] = -1;
    int deepest = 0;
    for (std::size_t j : deps[i]) deepest = std::max(deepest, visit(j));
    return level[i] = deepest + 1;
  };
  for (std::size_t i = 0; i < n; ++i) visit(i);
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) order_[i] = i;
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return level[a] < level[b]; });
  finalized_ = true;
}

void ParameterSpace::require_finalized() const {
  if (!finalized_) throw std::logic_error("ParameterSpace used before finalize()");
}

std::size_t ParameterSpace::nb_variable() const {
  return static_cast<std::size_t>(
      std::count_if(params_.begin(), params_.end(), [](const Parameter& p) { return !p.is_fixed(); }));
}

bool ParameterSpace::clause_holds(const Configuration& c, const Clause& clause, std::size_t ref) const {
  const double v = c.values[ref];
  if (is_na(v)) return false;
  const Parameter& rp = params_[ref];
  const bool categorical = !rp.is_numeric();
  if (clause.op == Clause::Op::In || clause.op == Clause::Op::NotIn) {
    bool found = false;
    if (categorical) {
      const std::string& text = rp.values[static_cast<std::size_t>(v)];
      found = std::find(clause.values.begin(), clause.values.end(), text) != clause.values.end();
    } else {
      for (const std::string& s : clause.values) {
        const auto x = parse_number(s);
        if (x && *x == v) found = true;
      }
    }
    return clause.op == Clause::Op::In ? found : !found;
  }
  double x = v;
  if (categorical) {  // R: as.numeric(value); a non-number gives NA, hence false
    const auto num = parse_number(rp.values[static_cast<std::size_t>(v)]);
    if (!num) return false;
    x = *num;
  }
  switch (clause.op) {
    case Clause::Op::Eq: return x == clause.number;
    case Clause::Op::Ne: return x != clause.number;
    case Clause::Op::Gt: return x > clause.number;
    case Clause::Op::Ge: return x >= clause.number;
    case Clause::Op::Lt: return x < clause.number;
    case Clause::Op::Le: return x <= clause.number;
    default: return false;
  }
}

bool ParameterSpace::is_active(const Configuration& c, std::size_t i) const {
  require_finalized();
  const auto& clauses = params_[i].condition;
  for (std::size_t k = 0; k < clauses.size(); ++k)
    if (!clause_holds(c, clauses[k], clause_refs_[i][k])) return false;
  return true;
}

double ParameterSpace::bound_value(const Configuration& c, const Bound& b, std::size_t ref) const {
  if (!b.is_dependent()) return b.constant;
  const double v = c.values[ref];
  return is_na(v) ? kNA : v + b.offset;
}

std::optional<std::pair<double, double>> ParameterSpace::domain(const Configuration& c, std::size_t i) const {
  require_finalized();
  const Parameter& p = params_[i];
  double lb = bound_value(c, p.lower, bound_refs_[i].first);
  double ub = bound_value(c, p.upper, bound_refs_[i].second);
  if (is_na(lb) || is_na(ub)) return std::nullopt;
  if (p.type == ParamType::Integer && p.is_dependent()) {  // R as.integer truncates
    lb = std::trunc(lb);
    ub = std::trunc(ub);
  }
  if (lb > ub)
    throw std::runtime_error("invalid domain generated for parameter '" + p.name + "' (lower bound above upper bound)");
  return std::make_pair(lb, ub);
}

double ParameterSpace::round_real(double v) const {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits_, v);
  return std::strtod(buf, nullptr);
}

std::string ParameterSpace::value_text(const Configuration& c, std::size_t i) const {
  const double v = c.values[i];
  if (is_na(v)) return "NA";
  const Parameter& p = params_[i];
  char buf[64];
  switch (p.type) {
    case ParamType::Categorical:
    case ParamType::Ordinal: return p.values[static_cast<std::size_t>(v)];
    case ParamType::Integer: std::snprintf(buf, sizeof buf, "%.0f", v); return buf;
    case ParamType::Real: {
      std::snprintf(buf, sizeof buf, "%.*f", digits_, v);
      std::string s = buf;
      if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
      }
      if (s == "-0") s = "0";
      return s;
    }
  }
  return {};
}

std::string ParameterSpace::render(const Configuration& c) const {
  std::string out;
  for (std::size_t i = 0; i < params_.size(); ++i) {
    if (is_na(c.values[i])) continue;
    if (!out.empty()) out += ' ';
    out += params_[i].switch_;
    out += value_text(c, i);
  }
  return out;
}

std::optional<std::size_t> ParameterSpace::value_index(std::size_t i, std::string_view text) const {
  const auto& vals = params_[i].values;
  for (std::size_t k = 0; k < vals.size(); ++k)
    if (vals[k] == text) return k;
  return std::nullopt;
}

Configuration ParameterSpace::parse(std::string_view command_line) const {
  require_finalized();
  // 1. Split the line into (switch, value) pairs. A switch ending in whitespace takes the
  //    next token as value; a glued switch ("--" + "fsm-config") takes the token's rest,
  //    accepted only when that rest is a valid value of a parameter with that switch.
  struct Given {
    std::string value;
    bool used = false;
  };
  std::map<std::string, Given> given;
  const auto tokens = split_whitespace(command_line);
  for (std::size_t t = 0; t < tokens.size(); ++t) {
    const std::string_view tok = tokens[t];
    std::string key;
    std::string value;
    for (const Parameter& p : params_) {
      if (!switch_takes_separate_token(p.switch_) || trim(p.switch_) != tok) continue;
      if (t + 1 >= tokens.size()) throw std::invalid_argument("missing value after token '" + std::string(tok) + "'");
      key = p.switch_;
      value = std::string(tokens[++t]);
      break;
    }
    if (key.empty()) {
      for (std::size_t i = 0; i < params_.size() && key.empty(); ++i) {
        const Parameter& p = params_[i];
        if (switch_takes_separate_token(p.switch_) || !tok.starts_with(p.switch_)) continue;
        const std::string_view rest = tok.substr(p.switch_.size());
        const bool ok = p.is_numeric() ? parse_number(rest).has_value() : value_index(i, rest).has_value();
        if (ok) {
          key = p.switch_;
          value = std::string(rest);
        }
      }
    }
    if (key.empty()) throw std::invalid_argument("unknown token '" + std::string(tok) + "'");
    if (given.count(key)) throw std::invalid_argument("repeated token '" + std::string(tok) + "'");
    given[key] = Given{value, false};
  }
  // 2. Assign values in sampling order so that conditions and dependent domains see their
  //    dependencies; parameters sharing a switch are told apart by their conditions.
  Configuration c;
  c.values.assign(params_.size(), kNA);
  for (std::size_t i : order_) {
    const Parameter& p = params_[i];
    if (!is_active(c, i)) continue;
    auto it = given.find(p.switch_);
    if (it == given.end()) {
      if (p.is_fixed() && !p.is_numeric()) {
        c.values[i] = 0.0;
        continue;
      }
      throw std::invalid_argument("missing value for parameter '" + p.name + "' (token '" +
                                  std::string(trim(p.switch_)) + "')");
    }
    it->second.used = true;
    const std::string& text = it->second.value;
    const std::string where = "value '" + text + "' of token '" + std::string(trim(p.switch_)) + "'";
    if (!p.is_numeric()) {
      const auto k = value_index(i, text);
      if (!k) throw std::invalid_argument(where + " is not in the domain of '" + p.name + "'");
      c.values[i] = static_cast<double>(*k);
      continue;
    }
    const auto x = parse_number(text);
    if (!x) throw std::invalid_argument(where + " is not a number");
    double v = *x;
    if (p.type == ParamType::Integer && v != std::floor(v))
      throw std::invalid_argument(where + " is not an integer");
    if (p.type == ParamType::Real) v = round_real(v);
    const auto d = domain(c, i);
    if (!d || v < d->first || v > d->second)
      throw std::invalid_argument(where + " is outside the domain of '" + p.name + "'");
    c.values[i] = v;
  }
  for (const auto& [key, g] : given)
    if (!g.used)
      throw std::invalid_argument("token '" + std::string(trim(key)) + "' does not apply to this control software");
  return c;
}

std::string ParameterSpace::validate(const Configuration& c) const {
  require_finalized();
  if (c.values.size() != params_.size()) return "wrong number of values";
  for (std::size_t i : order_) {
    const Parameter& p = params_[i];
    const double v = c.values[i];
    const bool active = is_active(c, i);
    if (!active) {
      if (!is_na(v)) return "parameter '" + p.name + "' is inactive but has a value";
      continue;
    }
    if (is_na(v)) return "parameter '" + p.name + "' is active but has no value";
    if (!p.is_numeric()) {
      if (v < 0 || v >= static_cast<double>(p.values.size()) || v != std::floor(v))
        return "parameter '" + p.name + "' has an invalid value index";
      continue;
    }
    const auto d = domain(c, i);
    if (!d || v < d->first || v > d->second) return "parameter '" + p.name + "' is outside its domain";
    if (p.type == ParamType::Integer && v != std::floor(v)) return "parameter '" + p.name + "' is not an integer";
  }
  return {};
}

}  // namespace sd::design
