// The memory this process may still take: /proc/meminfo's MemAvailable, bytes (8 GiB
// when it cannot be read). Every memory refusal compares with it (tools/run/memory_limits.h,
// the path readers' growth check in tools/io/tool_path_file.h).
#pragma once

#include <fstream>
#include <string>

namespace scallop {

inline double availableMemoryBytes() {
  double available = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  double kb = 0;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") available = kb * 1024;
  return available > 0 ? available : 8.0 * (1ull << 30);
}

}  // namespace scallop
