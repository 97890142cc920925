// InputError: bad user input. The message names the file, line or field and says
// what was expected; the CLI maps it to exit status 1 (CONVENTIONS.md).
#pragma once

#include <stdexcept>
#include <string>

namespace scallop {

class InputError : public std::runtime_error {
 public:
  // `where` is a field path ("tool.corner_radius"), or "file:line"; it leads the message.
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(where.empty() ? what : where + ": " + what), where_(where) {}
  const std::string& where() const { return where_; }

 private:
  std::string where_;
};

}  // namespace scallop
