// File-name helpers shared by the readers and writers that choose a format by extension.
#pragma once

#include <cctype>
#include <filesystem>
#include <string>

namespace scallop {

// The extension of `path` with its dot, lower-cased: "part.NC" -> ".nc".
inline std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace scallop
