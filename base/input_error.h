// InputError: bad user input. The message names the file, line or field and says
// what was expected; the CLI maps it to exit status 1 (CONVENTIONS.md).
#pragma once

#include <stdexcept>
#include <string>

namespace scallop {

class InputError : public std::runtime_error {
 public:
  // `where` is a field path ("tool.corner_radius"), or "file:line"; it leads the
  // message, what() = "where: reason".
  InputError(const std::string& where, const std::string& reason)
      : std::runtime_error(where.empty() ? reason : where + ": " + reason),
        where_(where),
        reason_(reason) {}
  const std::string& where() const { return where_; }
  // What is wrong there and what was expected, without the place.
  const std::string& reason() const { return reason_; }

 private:
  std::string where_, reason_;
};

}  // namespace scallop
