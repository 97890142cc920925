// JSON <-> Python: nlohmann::json documents (report.json, `interval --json`, ...) as
// Python dicts, lists and numbers, and Python job dicts as JSON. Doubles pass through
// unchanged both ways (no text in between), so a dict equals json.loads of the CLI's
// output.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>

namespace scallop::python {

pybind11::object toPython(const nlohmann::json& value);

// A dict of str keys, lists or tuples, bool, int, float, str and None as JSON. Throws
// InputError naming the field (`where`, e.g. "job: tool.radius") of a value JSON cannot
// hold: a non-finite number, a key that is not a str, another type.
nlohmann::json fromPython(const pybind11::handle& value, const std::string& where);

}  // namespace scallop::python
