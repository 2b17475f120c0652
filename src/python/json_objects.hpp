#pragma once
// The engine's JSON documents (what `--json` prints) as Python objects: dict, list, str, int,
// float, bool, None. Numbers keep every bit (a double stays the same double).
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace sd::python {

pybind11::object to_python(const nlohmann::json& value);

}  // namespace sd::python
