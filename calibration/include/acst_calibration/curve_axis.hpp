#pragma once
// What a fit compares with the lab: the axes of the measured series, and the stress measure of
// a curve's stress axis.
#include "acst_common/name_table.hpp"

namespace acst::calibration {

// stress: sigma1'/sigma3' or q against axial strain; volumetric: eps_v % against axial strain;
// phi: the peak friction angle (deg) of each row of a table test; closing: a gap_closing test's
// ratio gap(second strain) / gap(first strain) of the gap in sigma1'/sigma3' between two tests.
enum class Axis { stress, volumetric, phi, closing };

// The names in the fit description ("fit"), the reports and the figures' titles.
inline constexpr common::Named<Axis> axis_names[] = {
    {"stress", Axis::stress}, {"volumetric", Axis::volumetric}, {"phi", Axis::phi}, {"closing", Axis::closing}};

inline const char* name_of(Axis a) { return common::name_in(axis_names, a); }

// The stress axis of a curve: sigma1'/sigma3' (the lab files' stress_ratio) or q = sigma1' - sigma3'.
enum class StressMeasure { stress_ratio, q_kPa };

// The names in the fit description ("stress_measure"), which are also the lab files' and the
// fitted curves' columns.
inline constexpr common::Named<StressMeasure> stress_measure_names[] = {
    {"stress_ratio", StressMeasure::stress_ratio}, {"q_kPa", StressMeasure::q_kPa}};

inline const char* name_of(StressMeasure m) { return common::name_in(stress_measure_names, m); }

}  // namespace acst::calibration
