// InternalError: a broken invariant of scallop itself, never the user's input (heights
// that differ between thread counts, a writer used out of order). The CLI maps it to
// exit status 3, "internal error" (CONVENTIONS.md), as it maps any other exception that
// is not an InputError.
#pragma once

#include <stdexcept>
#include <string>

namespace scallop {

class InternalError : public std::logic_error {
 public:
  explicit InternalError(const std::string& what) : std::logic_error(what) {}
};

}  // namespace scallop
