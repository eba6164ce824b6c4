#pragma once
// Helpers shared by the acst_* functions and umat_.
#include <string>

#include "acst.h"
#include "acst/integration/report.hpp"
#include "acst/material.hpp"

namespace acst::abi {

acst_status make_status(int code, const std::string& message, double factor);
acst_status ok_status();
// Converts, updates one point, converts back; stress and statev untouched on failure.
acst_status update_point(double* stress, double* statev, double* tangent, const Material& mat, const double* dstrain,
                         integration::Report& rep);

}  // namespace acst::abi
