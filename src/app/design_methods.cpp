// The registry of design methods: every name of design/methods.hpp with its implementation.
#include "app/design_method.hpp"
#include "app/errors.hpp"

namespace sd::app {

const DesignMethod& automode_method();  // method_automode.cpp
const DesignMethod& evostick_method();  // method_evostick.cpp

const DesignMethod& design_method(std::string_view name) {
  static const DesignMethod* const kRegistry[] = {&automode_method(), &evostick_method()};
  for (const DesignMethod* method : kRegistry)
    if (method->info().name == name) return *method;
  throw InvalidRequest("unknown design method '" + std::string(name) + "' (" + design::method_names_text() + ")");
}

}  // namespace sd::app
