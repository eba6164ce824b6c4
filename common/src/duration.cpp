#include "acst_common/duration.hpp"

#include <cmath>
#include <cstdio>

namespace acst::common {

std::string duration_text(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  char buf[48];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s / 60), static_cast<int>(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%d h %02d min", static_cast<int>(s / 3600), static_cast<int>(s / 60) % 60);
  return buf;
}

}  // namespace acst::common
