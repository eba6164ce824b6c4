#include "acst/parameters.hpp"

#include <cmath>
#include <sstream>

namespace acst {

namespace {

std::string range_text(double lo, bool lo_open, double hi, bool hi_open) {
  std::ostringstream os;
  os << (lo_open ? "(" : "[") << lo << ", ";
  if (std::isinf(hi))
    os << "inf)";
  else
    os << hi << (hi_open ? ")" : "]");
  return os.str();
}

void check(const char* name, double v, double lo, bool lo_open, double hi, bool hi_open) {
  const bool ok = std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  if (!ok) {
    std::ostringstream os;
    os << "parameter '" << name << "' = " << v << " is outside its allowed range " << range_text(lo, lo_open, hi, hi_open);
    throw ParameterRangeError(os.str(), name);
  }
}

}  // namespace

void validate(const Parameters& p) {
  // The Lode form first: it sets the range of c (Li's g is convex from 0.7 only).
  check("lode_form", p.lode_form, 0.0, false, 1.0, false);
  if (p.lode_form != 0.0 && p.lode_form != 1.0) {
    std::ostringstream os;
    os << "parameter 'lode_form' = " << p.lode_form << " must be 0 (Li 2002) or 1 (Willam & Warnke 1975)";
    throw ParameterRangeError(os.str(), "lode_form");
  }
  if (p.lode_form == 0.0 && !(p.c >= 0.7 && p.c <= 1.0)) {
    std::ostringstream os;
    os << "parameter 'c' = " << p.c << " is outside its allowed range [0.7, 1] with lode_form 0 (Li's g is convex"
       << " from 0.7; lode_form 1, Willam & Warnke, allows (0.5, 1])";
    throw ParameterRangeError(os.str(), "c");
  }
  for (const ParameterInfo& info : parameter_table)
    check(info.name, p.*info.member, info.lo, info.lo_open, info.hi, info.hi_open);
  check("e_max", p.e_max, p.e_min, true, 2.97, true);  // the one range set by another parameter
  if (p.variant == Variant::isotropic)
    for (const ParameterInfo& info : parameter_table)
      if (info.fabric && p.*info.member != 0.0)
        throw ParameterRangeError("the isotropic model has no fabric: parameter '" + std::string(info.name) +
                                      "' must be 0 or absent",
                                  info.name);
}

double& parameter_by_index(Parameters& p, int i) {
  if (i < 0 || i >= parameter_count) throw InputError("parameter index out of range");
  return p.*parameter_table[i].member;
}

double parameter_by_index(const Parameters& p, int i) { return parameter_by_index(const_cast<Parameters&>(p), i); }

std::string parameter_table_markdown() {
  std::ostringstream os;
  os << "| name | allowed | unit | meaning | in the JSON | umat_ PROPS |\n|---|---|---|---|---|---|\n";
  int prop = 0;
  for (const ParameterInfo& info : parameter_table) {
    os << "| `" << info.name << "` | " << range_text(info.lo, info.lo_open, info.hi, info.hi_open) << " | "
       << info.unit << " | " << info.meaning << " | "
       << (info.optional ? (info.fabric ? "optional (isotropic: 0 or absent)" : "optional")
                         : (info.fabric ? "required (isotropic: 0 or absent)" : "required"))
       << " | ";
    if (info.props) os << ++prop;
    os << " |\n";
  }
  return os.str();
}

}  // namespace acst
