#include "tools/io/job_fields.h"

#include <cmath>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop::jobfield {

using nlohmann::json;

const json& requireObject(const json& parent, const std::string& key, const std::string& field) {
  if (!parent.contains(key)) throw InputError(field, "missing; expected an object");
  const json& v = parent.at(key);
  if (!v.is_object()) throw InputError(field, "expected an object, got " + v.dump());
  return v;
}

void rejectUnknownKeys(const json& obj, const std::set<std::string>& known,
                       const std::string& field) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (known.count(it.key())) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError(field.empty() ? it.key() : field + "." + it.key(),
                     "unknown key; expected one of: " + list);
  }
}

double number(const json& obj, const std::string& key, const std::string& field,
              const double* fallback) {
  if (!obj.contains(key)) {
    if (fallback) return *fallback;
    throw InputError(field, "missing; expected a number");
  }
  const json& v = obj.at(key);
  if (!v.is_number()) throw InputError(field, "expected a number, got " + v.dump());
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw InputError(field, "expected a finite number");
  if (std::fabs(d) > kMaxMagnitudeMm)
    throw InputError(field, "must be within +-1e6 (mm: 1 km), got " + v.dump());
  return d;
}

int64_t wholeNumber(const json& obj, const std::string& key, const std::string& field,
                    int64_t fallback, const char* what) {
  if (!obj.contains(key)) return fallback;
  const json& v = obj.at(key);
  const std::string expected = std::string("expected a whole number of ") + what + ", got ";
  if (!v.is_number()) throw InputError(field, expected + v.dump());
  const double d = v.get<double>();
  if (!(std::fabs(d) <= kMaxMagnitudeMm) || d != std::floor(d))
    throw InputError(field, expected + v.dump());
  return int64_t(d);
}

Vec3 point(const json& obj, const std::string& key, const std::string& field) {
  if (!obj.contains(key)) throw InputError(field, "missing; expected [x, y, z] in mm");
  const json& v = obj.at(key);
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    throw InputError(field, "expected [x, y, z] (three numbers, mm), got " + v.dump());
  const Vec3 p{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  if (!isFinite(p)) throw InputError(field, "coordinates must be finite");
  if (std::fmax(std::fabs(p.x), std::fmax(std::fabs(p.y), std::fabs(p.z))) > kMaxMagnitudeMm)
    throw InputError(field, "coordinates must be within +-1e6 mm (1 km), got " + v.dump());
  return p;
}

std::string text(const json& obj, const std::string& key, const std::string& field) {
  if (!obj.contains(key)) throw InputError(field, "missing; expected a string");
  const json& v = obj.at(key);
  if (!v.is_string()) throw InputError(field, "expected a string, got " + v.dump());
  return v.get<std::string>();
}

bool boolean(const json& obj, const std::string& key, const std::string& field, bool fallback) {
  if (!obj.contains(key)) return fallback;
  const json& v = obj.at(key);
  if (!v.is_boolean()) throw InputError(field, "expected true or false, got " + v.dump());
  return v.get<bool>();
}

}  // namespace scallop::jobfield
