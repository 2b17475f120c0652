#pragma once
// What the FSM and behaviour-tree grammars share: `--<name> <number>` pairs read into a
// table by token name, module reading against the catalogue, and the error messages that
// name the offending token.
#include <functional>
#include <map>
#include <span>
#include <string>

#include "control/config_string.hpp"
#include "modules/catalogue.hpp"

namespace sd::config {

struct Entry {
  std::string text;   // "--att0 3.5", for messages
  double value = 0.0;
  bool used = false;
};

class TokenReader {
 public:
  /// Reads `--name value` pairs; `valid_name` accepts the token names of the grammar.
  TokenReader(std::span<const std::string> tokens, std::string grammar,
              const std::function<bool(const std::string&)>& valid_name);

  Entry* find(const std::string& name);
  Entry& require(const std::string& name, const std::string& why);
  /// Throws for the first token nothing asked for; `explain` says why it does not belong.
  void reject_unused(const std::function<std::string(const std::string& name)>& explain) const;
  /// Values of the tokens whose name satisfies `is_module_id` (for legacy detection).
  std::vector<double> values_where(const std::function<bool(const std::string&)>& is_module_id) const;

 private:
  std::string grammar_;
  std::map<std::string, Entry> entries_;
};

int integer_value(const Entry& e, int lo, int hi, const std::string& what);

/// Reads the parameters of module `id` from tokens `--<param><suffix>`.
ModuleInstance read_module(TokenReader& reader, ModuleKind kind, const Entry& id_entry, int id, const std::string& suffix);

/// Appends ` --<param><suffix> <value>` for every active parameter of the module.
void append_parameters(std::string& out, const ModuleInstance& module, ModuleKind kind, const std::string& suffix);

/// Offset to add to one-digit legacy ids (10 x flavour), or 0 if any id has two digits.
int legacy_offset(const std::vector<double>& ids, Flavour flavour);

/// "--" + letters + the rest.
bool split_name(const std::string& token, std::string& stem, std::string& index);

}  // namespace sd::config
