#include "tools/python/json_convert.h"

#include <cmath>

#include "base/input_error.h"

namespace scallop::python {

namespace py = pybind11;
using nlohmann::json;

py::object toPython(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return py::none();
    case json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case json::value_t::number_integer:
      return py::int_(value.get<int64_t>());
    case json::value_t::number_unsigned:
      return py::int_(value.get<uint64_t>());
    case json::value_t::number_float:
      return py::float_(value.get<double>());
    case json::value_t::string:
      return py::str(value.get_ref<const std::string&>());
    case json::value_t::array: {
      py::list list;
      for (const json& item : value) list.append(toPython(item));
      return std::move(list);
    }
    case json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = toPython(item);
      return std::move(dict);
    }
    default:
      return py::none();  // binary and discarded values never occur in scallop's documents
  }
}

json fromPython(const py::handle& value, const std::string& where) {
  const std::string place = where.empty() ? "job" : where;
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) return value.cast<int64_t>();
  if (py::isinstance<py::float_>(value)) {
    const double v = value.cast<double>();
    if (!std::isfinite(v))
      throw InputError(place, "is " + std::string(py::str(value)) + "; expected a finite number");
    return v;
  }
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    json object = json::object();
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key))
        throw InputError(place,
                         "has the key " + std::string(py::repr(key)) + "; expected str keys");
      const std::string name = key.cast<std::string>();
      object[name] = fromPython(item, where.empty() ? "job: " + name : where + "." + name);
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    json array = json::array();
    size_t k = 0;
    for (const py::handle item : value)
      array.push_back(fromPython(item, place + "[" + std::to_string(k++) + "]"));
    return array;
  }
  // NumPy scalars and arrays become Python numbers and lists; other integers (__index__)
  // and numbers (__float__) are taken as such.
  if (py::hasattr(value, "tolist")) return fromPython(value.attr("tolist")(), where);
  if (py::hasattr(value, "__index__")) return value.attr("__index__")().cast<int64_t>();
  if (py::hasattr(value, "__float__"))
    return fromPython(py::float_(value.attr("__float__")()), where);
  throw InputError(place, "is a " + std::string(py::str(value.get_type().attr("__name__"))) +
                              "; expected a dict, list, str, number, bool or None");
}

}  // namespace scallop::python
