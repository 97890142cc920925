// libzip's error codes as text, for the messages of the X3P reader and writer (an X3P
// file is a zip archive).
#pragma once

#include <string>

namespace scallop {

// What libzip's error `code` (as zip_open reports it) means, in its own words.
std::string zipErrorText(int code);

}  // namespace scallop
