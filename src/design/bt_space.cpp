#include "design/bt_space.hpp"

#include <stdexcept>

namespace sd::design {

namespace {
Parameter constant(std::string name, std::string switch_, std::string value, Condition condition) {
  return Parameter{std::move(name), std::move(switch_), ParamType::Categorical, {std::move(value)}, {}, {}, false,
                   std::move(condition)};
}
std::vector<std::string> ids_of(const std::vector<Module>& modules) {
  std::vector<std::string> ids;
  ids.reserve(ids.size() + modules.size());
  for (const Module& m : modules) ids.push_back(std::to_string(m.id));
  return ids;
}
}  // namespace

void add_bt_parameters(ParameterSpace& space, const FsmModules& modules, const BtSpaceOptions& o,
                       bool conditioned_on_arch) {
  if (modules.behaviours.empty() || modules.conditions.empty())
    throw std::invalid_argument("a behaviour-tree space needs at least one behaviour and one condition");
  if (o.max_branches < 1 || o.max_branches > 9) throw std::invalid_argument("a tree has 1 to 9 branches");
  const Condition arch = conditioned_on_arch ? Condition{Clause{"ARCH", Clause::Op::In, {"bt-config"}, 0.0}} : Condition{};

  space.add(constant("RootNode", "--nroot ", "3", arch));  // Sequence*
  space.add(Parameter{"NumChildsRoot", "--nchildroot ", ParamType::Integer, {}, Bound::fixed(1),
                      Bound::fixed(o.max_branches), false, arch});
  const auto behaviours = ids_of(modules.behaviours), conditions = ids_of(modules.conditions);
  for (int i = 0; i < o.max_branches; ++i) {
    const std::string si = std::to_string(i);
    const Condition branch{Clause{"NumChildsRoot", Clause::Op::Gt, {}, static_cast<double>(i)}};
    space.add(constant("N" + si, "--n" + si + " ", "0", branch));             // Selector
    space.add(constant("NumChild" + si, "--nchild" + si + " ", "2", branch));
    space.add(constant("N" + si + "0", "--n" + si + "0 ", "6", branch));      // condition leaf
    space.add(Parameter{"C" + si + "0", "--c" + si + "0 ", ParamType::Categorical, conditions, {}, {}, false, branch});
    add_module_parameters(space, modules.conditions, si + "0", "C" + si + "0");
    space.add(constant("N" + si + "1", "--n" + si + "1 ", "5", branch));      // action leaf
    space.add(Parameter{"A" + si + "1", "--a" + si + "1 ", ParamType::Categorical, behaviours, {}, {}, false, branch});
    add_module_parameters(space, modules.behaviours, si + "1", "A" + si + "1");
    space.add(constant("P" + si + "1", "--p" + si + "1 ", "0", branch));      // Maple actions never succeed
  }
}

}  // namespace sd::design
