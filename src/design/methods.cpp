#include "design/methods.hpp"

namespace sd::design {

const MethodInfo* find_method(std::string_view name) {
  for (const MethodInfo* m : kMethods)
    if (m->name == name) return m;
  return nullptr;
}

std::string method_names_text() {
  std::string text;
  for (std::size_t i = 0; i < kMethods.size(); ++i) {
    if (i > 0) text.append(i + 1 == kMethods.size() ? " or " : ", ");
    text.append(kMethods[i]->name);
  }
  return text;
}

}  // namespace sd::design
