#pragma once
// The element tests an experiment of a fit description can be (docs/calibration.md).
#include "acst_common/name_table.hpp"

namespace acst::calibration {

// In the alphabetical order of the names: the type weights are a map over these, normalised by
// their sum in this order, as they were when the map was keyed by name (the same bits).
enum class TestType { drained_triaxial_compression, gap_closing, peak_friction, plane_strain_compression, true_triaxial };

// The names in the fit description and the reports, the curve tests first (as the messages
// list them). A curve test runs the driver preset of the same name; peak_friction, the one table
// test, runs one true-triaxial test (sigma3' held, b fixed) per selected row of a friction-angle
// table; gap_closing runs two lab curves' tests and compares how the gap in sigma1'/sigma3'
// between them closes from one axial strain to another (docs/calibration.md, "Gap closings").
inline constexpr common::Named<TestType> test_type_names[] = {
    {"drained_triaxial_compression", TestType::drained_triaxial_compression},
    {"plane_strain_compression", TestType::plane_strain_compression},
    {"true_triaxial", TestType::true_triaxial},
    {"peak_friction", TestType::peak_friction},
    {"gap_closing", TestType::gap_closing}};

inline const char* name_of(TestType t) { return common::name_in(test_type_names, t); }

inline bool is_table_test(TestType t) { return t == TestType::peak_friction; }

// A test whose one measured value derives from two lab curves (the curves are not fitted by it).
inline bool is_gap_closing(TestType t) { return t == TestType::gap_closing; }

}  // namespace acst::calibration
