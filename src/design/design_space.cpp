#include "design/design_space.hpp"

#include <algorithm>

#include "design/bt_space.hpp"
#include <sstream>
#include <stdexcept>

namespace sd::design {

namespace {

constexpr Flavour kAllFlavours[] = {Flavour::Chocolate, Flavour::TuttiFrutti, Flavour::Coconut, Flavour::Maple,
                                    Flavour::Arlequin};

bool has_modules(Flavour f) {
  for (const ModuleSpec& m : modules(ModuleKind::Behaviour))
    if (m.flavour() == f) return true;
  return false;
}

std::string display_name(Flavour f) {
  switch (f) {
    case Flavour::Chocolate: return "Chocolate";
    case Flavour::TuttiFrutti: return "TuttiFrutti";
    case Flavour::Coconut: return "Coconut";
    case Flavour::Maple: return "Maple";
    case Flavour::Arlequin: return "Arlequin";
  }
  return "unknown";
}


// Appends rather than `a + "," + b`: GCC 12 warns falsely (-Wrestrict) on such sums.
std::string join(const std::vector<std::string>& parts) {
  std::string out;
  for (const auto& part : parts) {
    if (!out.empty()) out.push_back(',');
    out.append(part);
  }
  return out;
}

}  // namespace

std::string DesignSpaceChoice::architectures_text() const { return join(architectures); }

std::string DesignSpaceChoice::flavours_text() const {
  std::vector<std::string> names;
  for (Flavour f : flavours) names.emplace_back(flavour_name(f));
  return join(names);
}

DesignSpaceChoice resolve_design_space(const DesignSpaceRequest& request) {
  DesignSpaceChoice choice;
  // No architecture flag means both, and the architecture becomes a tuned parameter.
  if (request.fsm || !request.bt) choice.architectures.push_back("fsm");
  if (request.bt || !request.fsm) choice.architectures.push_back("bt");

  if (request.flavours.empty()) {
    for (Flavour f : kAllFlavours)
      if (has_modules(f)) choice.flavours.push_back(f);
  } else {
    for (Flavour f : kAllFlavours) {
      if (std::find(request.flavours.begin(), request.flavours.end(), f) == request.flavours.end()) continue;
      if (!has_modules(f)) throw std::invalid_argument("no " + display_name(f) + " modules are available yet");
      choice.flavours.push_back(f);
    }
  }
  if (choice.flavours.empty()) throw std::invalid_argument("no modules are available in this build");
  return choice;
}

ParameterSpace build_design_space(const DesignSpaceChoice& choice) {
  const bool fsm = std::find(choice.architectures.begin(), choice.architectures.end(), "fsm") != choice.architectures.end();
  const bool bt = std::find(choice.architectures.begin(), choice.architectures.end(), "bt") != choice.architectures.end();
  if (!fsm && !bt) throw std::invalid_argument("no architecture chosen");
  const FsmModules modules = catalogue_fsm_modules(choice.flavours);
  FsmSpaceOptions options;
  options.architectures.clear();
  if (fsm) options.architectures.push_back("fsm-config");
  if (bt) options.architectures.push_back("bt-config");
  ParameterSpace space(options.digits);
  // ARCH "--" c("fsm-config", "bt-config"): the first token of every string, as in the
  // unified Demiurge grammar (Demiurge_grammar.txt).
  space.add(Parameter{"ARCH", "--", ParamType::Categorical, options.architectures, {}, {}, false, {}});
  if (fsm) add_fsm_parameters(space, modules, options);
  if (bt) add_bt_parameters(space, modules, BtSpaceOptions{}, fsm);
  space.finalize();
  return space;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

DesignSpaceRequest request_from_text(const std::string& architectures, const std::string& flavours) {
  return request_from_names(split_list(architectures), split_list(flavours));
}

DesignSpaceRequest request_from_names(const std::vector<std::string>& architectures,
                                      const std::vector<std::string>& flavours) {
  DesignSpaceRequest request;
  for (const auto& a : architectures) {
    if (a == "fsm") request.fsm = true;
    else if (a == "bt") request.bt = true;
    else throw std::invalid_argument("unknown architecture '" + a + "'");
  }
  for (const auto& f : flavours) {
    const auto flavour = flavour_from_name(f);
    if (!flavour) throw std::invalid_argument("unknown flavour '" + f + "'");
    request.flavours.push_back(*flavour);
  }
  return request;
}

}  // namespace sd::design
