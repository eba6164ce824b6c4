#pragma once
// A C ABI model handle that destroys itself, and small helpers for tests of the C ABI
// (tension positive, engineering shear, Voigt 11 22 33 12 13 23).
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "acst.h"

namespace acst::test {

class AbiModel {
 public:
  explicit AbiModel(const std::string& json) {
    const acst_status st = acst_model_create(&model_, json.c_str());
    EXPECT_EQ(st.code, ACST_OK) << st.message;
  }
  ~AbiModel() { acst_model_destroy(model_); }
  AbiModel(const AbiModel&) = delete;
  AbiModel& operator=(const AbiModel&) = delete;
  const acst_model* get() const { return model_; }

 private:
  acst_model* model_ = nullptr;
};

// The status of a creation that is expected to fail; checks that no handle is left behind.
inline acst_status failed_creation(const std::string& json) {
  acst_model* model = nullptr;
  const acst_status st = acst_model_create(&model, json.c_str());
  EXPECT_EQ(model, nullptr) << json;
  acst_model_destroy(model);
  return st;
}

using Voigt = std::array<double, 6>;
using Tangent = std::array<double, 36>;

}  // namespace acst::test
