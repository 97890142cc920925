// scallop: command-line entry point.
#include <cstdio>

int main() {
  std::puts("scallop: under construction");
  return 0;
}
