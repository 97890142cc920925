// Strict field access for job files (tools/io/job.h): every accessor names the field
// path it reads ("tool.radius") and says what was expected when the value is missing,
// of the wrong type or out of bounds (InputError). Every number of a job is a length
// in mm, an angle in degrees or a tolerance, bounded by kMaxMagnitudeMm (1 km).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "base/vec3.h"

namespace scallop::jobfield {

// parent[key] as an object; missing or another type is an error naming `field`.
const nlohmann::json& requireObject(const nlohmann::json& parent, const std::string& key,
                                    const std::string& field);

// The first key of `obj` not in `known` is an error naming `field`.key and the keys
// expected.
void rejectUnknownKeys(const nlohmann::json& obj, const std::set<std::string>& known,
                       const std::string& field);

// A finite number within +-1e6; `fallback` (when given) if the key is absent.
double number(const nlohmann::json& obj, const std::string& key, const std::string& field,
              const double* fallback = nullptr);

// A whole number within +-1e6 (JSON 2 or 2.0; not 2.5, "2" or true); `fallback` if the
// key is absent. `what` names the quantity in the message ("teeth"); the caller checks
// the range that means something.
int64_t wholeNumber(const nlohmann::json& obj, const std::string& key, const std::string& field,
                    int64_t fallback, const char* what);

// [x, y, z], three finite numbers within +-1e6 mm.
Vec3 point(const nlohmann::json& obj, const std::string& key, const std::string& field);

std::string text(const nlohmann::json& obj, const std::string& key, const std::string& field);

bool boolean(const nlohmann::json& obj, const std::string& key, const std::string& field,
             bool fallback);

}  // namespace scallop::jobfield
