#include "control/config_tokens.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>

namespace sd::config {

namespace {
std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}
}  // namespace

bool split_name(const std::string& token, std::string& stem, std::string& index) {
  if (token.size() < 3 || token[0] != '-' || token[1] != '-') return false;
  std::size_t pos = 2;
  while (pos < token.size() && std::isalpha(static_cast<unsigned char>(token[pos]))) ++pos;
  if (pos == 2) return false;
  stem = token.substr(2, pos - 2);
  index = token.substr(pos);
  return true;
}

TokenReader::TokenReader(std::span<const std::string> tokens, std::string grammar,
                         const std::function<bool(const std::string&)>& valid_name)
    : grammar_(std::move(grammar)) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& token = tokens[i];
    if (!valid_name(token)) throw ConfigError("unexpected token '" + token + "' in " + grammar_);
    if (i + 1 >= tokens.size()) throw ConfigError("missing value after '" + token + "'");
    const std::string& value_text = tokens[++i];
    const auto value = parse_number(value_text);
    if (!value && valid_name(value_text)) throw ConfigError("missing value after '" + token + "'");
    if (!value) throw ConfigError("'" + token + " " + value_text + "': the value is not a number");
    const auto [it, inserted] = entries_.emplace(token, Entry{token + " " + value_text, *value, false});
    if (!inserted) throw ConfigError("duplicate token '" + token + "'");
  }
}

Entry* TokenReader::find(const std::string& name) {
  const auto it = entries_.find(name);
  if (it == entries_.end()) return nullptr;
  it->second.used = true;
  return &it->second;
}

Entry& TokenReader::require(const std::string& name, const std::string& why) {
  Entry* e = find(name);
  if (!e) throw ConfigError("missing " + name + " (" + why + ")");
  return *e;
}

void TokenReader::reject_unused(const std::function<std::string(const std::string&)>& explain) const {
  for (const auto& [name, entry] : entries_)
    if (!entry.used) throw ConfigError("unexpected token '" + entry.text + "' (" + explain(name) + ")");
}

std::vector<double> TokenReader::values_where(const std::function<bool(const std::string&)>& is_module_id) const {
  std::vector<double> values;
  for (const auto& [name, entry] : entries_)
    if (is_module_id(name)) values.push_back(entry.value);
  return values;
}

int integer_value(const Entry& e, int lo, int hi, const std::string& what) {
  if (e.value != std::floor(e.value) || e.value < lo || e.value > hi)
    throw ConfigError("'" + e.text + "': " + what + " must be an integer in [" + std::to_string(lo) + ", " +
                      std::to_string(hi) + "]");
  return static_cast<int>(e.value);
}

ModuleInstance read_module(TokenReader& reader, ModuleKind kind, const Entry& id_entry, int id, const std::string& suffix) {
  const ModuleSpec* spec = find_module(kind, id);
  const char* kind_name = kind == ModuleKind::Behaviour ? "behaviour" : "condition";
  if (!spec) throw ConfigError("'" + id_entry.text + "': unknown " + std::string(kind_name) + " id " + std::to_string(id));
  ModuleInstance instance;
  instance.id = id;
  for (std::size_t p = 0; p < spec->parameters.size(); ++p) {
    const ParameterSpec& param = spec->parameters[p];
    if (!spec->parameter_active(p, instance.parameters)) continue;  // e.g. rwm without exp 1
    const Entry& e = reader.require("--" + param.token + suffix, spec->name + " needs it");
    if (!param.accepts(e.value))
      throw ConfigError("'" + e.text + "': " + param.token + " of " + spec->name + " must be " + param.domain_text());
    instance.parameters[p] = e.value;
  }
  return instance;
}

void append_parameters(std::string& out, const ModuleInstance& m, ModuleKind kind, const std::string& suffix) {
  const ModuleSpec* spec = find_module(kind, m.id);
  if (!spec) return;
  for (std::size_t p = 0; p < spec->parameters.size(); ++p)
    if (spec->parameter_active(p, m.parameters))
      out += " --" + spec->parameters[p].token + suffix + " " + format_number(m.parameters[p]);
}

int legacy_offset(const std::vector<double>& ids, Flavour flavour) {
  const bool legacy = !ids.empty() && std::all_of(ids.begin(), ids.end(), [](double v) { return v >= 0 && v < 10; });
  return legacy ? 10 * static_cast<int>(flavour) : 0;
}

}  // namespace sd::config
