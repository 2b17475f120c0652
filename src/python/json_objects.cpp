#include "python/json_objects.hpp"

#include <cstdint>
#include <string>

namespace sd::python {

namespace py = pybind11;

py::object to_python(const nlohmann::json& value) {
  using Type = nlohmann::json::value_t;
  switch (value.type()) {
    case Type::boolean: return py::bool_(value.get<bool>());
    case Type::number_integer: return py::int_(value.get<std::int64_t>());
    case Type::number_unsigned: return py::int_(value.get<std::uint64_t>());
    case Type::number_float: return py::float_(value.get<double>());
    case Type::string: return py::str(value.get_ref<const std::string&>());
    case Type::array: {
      py::list list;
      for (const auto& element : value) list.append(to_python(element));
      return list;
    }
    case Type::object: {
      py::dict dict;
      for (const auto& [key, element] : value.items()) dict[py::str(key)] = to_python(element);
      return dict;
    }
    case Type::null:
    case Type::binary:
    case Type::discarded: break;
  }
  return py::none();
}

}  // namespace sd::python
