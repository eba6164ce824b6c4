#pragma once
#include <string>

namespace acst::common {

// "12.3 s" below a minute, "4 min 05 s" above, "2 h 03 min" above an hour.
std::string duration_text(double seconds);

}  // namespace acst::common
