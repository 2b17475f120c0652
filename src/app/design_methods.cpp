// The registry of design methods: every name of design/methods.hpp with its implementation.
#include "app/design_method.hpp"

#include <nlohmann/json.hpp>

#include "app/documents.hpp"
#include "app/errors.hpp"
#include "storage/design_store.hpp"

namespace sd::app {

const DesignMethod& automode_method();       // method_automode.cpp, as the next two
const DesignMethod& random_search_method();
const DesignMethod& local_search_method();
const DesignMethod& evostick_method();       // method_evostick.cpp

const DesignMethod& design_method(std::string_view name) {
  static const DesignMethod* const kRegistry[] = {&automode_method(), &random_search_method(), &local_search_method(),
                                                  &evostick_method()};
  for (const DesignMethod* method : kRegistry)
    if (method->info().name == name) return *method;
  throw InvalidRequest("unknown design method '" + std::string(name) + "' (" + design::method_names_text() + ")");
}

nlohmann::json design_methods_document() {
  nlohmann::json out = nlohmann::json::array();
  for (const design::MethodInfo* m : design::kMethods)
    out.push_back({{"name", m->name}, {"title", m->title}, {"summary", m->summary}, {"has_design_space", m->has_design_space}});
  return out;
}

nlohmann::json design_folder_document(const std::filesystem::path& folder) {
  nlohmann::json out = {{"folder", std::filesystem::absolute(folder).lexically_normal().string()}};
  if (!std::filesystem::exists(storage::DesignStore::file_in(folder)) && std::filesystem::exists(folder / "evostick.json")) {
    const DesignMethod& method = design_method(design::kEvoStick.name);
    out["method"] = std::string(design::kEvoStick.name);
    out["document"] = method.document(folder);
    out["convergence"] = convergence_document(method.convergence(folder));
    return out;
  }
  out["method"] = storage::DesignStore::open(folder).meta().method;  // automode, random-search or local-search
  out["progress"] = stored_progress_document(storage::read_design_progress(folder));
  out["race_log"] = race_log_document(storage::read_race_log(folder));
  out["convergence"] = convergence_document(storage::read_convergence(folder));
  return out;
}

}  // namespace sd::app
