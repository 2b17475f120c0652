#include "design/methods.hpp"

#include <vector>

namespace sd::design {

const MethodInfo* find_method(std::string_view name) {
  for (const MethodInfo* m : kMethods)
    if (m->name == name) return m;
  return nullptr;
}

std::string method_names_text(bool design_space_only) {
  std::vector<std::string_view> names;
  for (const MethodInfo* m : kMethods)
    if (m->has_design_space || !design_space_only) names.push_back(m->name);
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text.append(i + 1 == names.size() ? " or " : ", ");
    text.append(names[i]);
  }
  return text;
}

}  // namespace sd::design
