#pragma once
// The core's one unit conversion: stresses are kPa (the material ABI's unit), forces N per metre
// out of plane, so a stress times an area (m^2 per metre) takes this factor (docs/mpm.md).
namespace acst::mpm {

inline constexpr double kilo = 1000.0;  // kPa -> Pa

}  // namespace acst::mpm
