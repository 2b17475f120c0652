#include "app/design_spaces.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>

#include "app/design_job.hpp"
#include "app/design_method.hpp"
#include "app/errors.hpp"

namespace sd::app {

design::DesignSpaceRequest design_space_request(const std::string& architectures, const std::string& flavours) {
  try {
    return design::request_from_text(architectures, flavours);
  } catch (const std::invalid_argument& e) {
    throw InvalidRequest(e.what());
  }
}

design::DesignSpaceRequest design_space_request(const std::vector<std::string>& architectures,
                                                const std::vector<std::string>& flavours) {
  try {
    return design::request_from_names(architectures, flavours);
  } catch (const std::invalid_argument& e) {
    throw InvalidRequest(e.what());
  }
}

nlohmann::json design_space_document(const std::string& architectures, const std::string& flavours,
                                     const std::string& method) {
  const design::MethodInfo& searcher = method.empty() ? design::kAutoMoDe : search_method(method);
  design::DesignSpaceChoice choice;
  try {
    choice = design::resolve_design_space(design_space_request(architectures, flavours));
  } catch (const std::invalid_argument& e) {
    throw InvalidRequest(e.what());
  }
  nlohmann::json methods = nlohmann::json::array();
  for (const nlohmann::json& m : design_methods_document())
    if (m.at("has_design_space").get<bool>()) methods.push_back(m);
  nlohmann::json names = nlohmann::json::array();
  for (const Flavour f : choice.flavours) names.push_back(std::string(flavour_name(f)));
  return {{"architectures", choice.architectures},
          {"flavours", names},
          {"notes", choice.notes},
          {"method", searcher.name},
          {"minimum_budget", minimum_design_budget(searcher, design::build_design_space(choice))},
          {"methods", methods}};
}

}  // namespace sd::app
