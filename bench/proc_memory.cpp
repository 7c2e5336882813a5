#include "proc_memory.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

namespace talus::bench {

namespace {
std::size_t status_kib(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t len = std::strlen(field);
  while (std::getline(in, line))
    if (line.compare(0, len, field) == 0) return std::stoul(line.substr(len + 1));  // "VmRSS:   1234 kB"
  return 0;
}
}  // namespace

std::size_t resident_kib() { return status_kib("VmRSS"); }
std::size_t peak_resident_kib() { return status_kib("VmHWM"); }

bool reset_peak_resident() {
  std::FILE* f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  const bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

}  // namespace talus::bench
