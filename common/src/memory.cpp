#include "acst_common/memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace acst::common {

double memory_limit_bytes(double cap_bytes) {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return cap_bytes;
  return std::min(cap_bytes, static_cast<double>(pages) * static_cast<double>(page));
}

std::string gib_text(double bytes) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return buf;
}

}  // namespace acst::common
