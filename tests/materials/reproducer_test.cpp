// Reproducers from every host (acst/reproducer.hpp, acst_reproducer, acst_umat_reproducer): the
// scene they write is an element test that replays the update. Proven on a good update (the
// replay ends at the stress acst_update / umat_ gives) and on a failing one (the replay fails
// too); buffer rules and refusals as acst.h states them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "acst.h"
#include "driver_scenes.hpp"
#include "test_materials.hpp"

namespace {

const std::string guide = "data/parameters/toyoura_acst_guide.json";

struct Handle {
  acst_model* model = nullptr;
  explicit Handle(const std::string& text) { EXPECT_EQ(acst_model_create(&model, text.c_str()).code, ACST_OK); }
  ~Handle() { acst_model_destroy(model); }
};

std::string reproducer_text(const acst_model* m, const double* stress, const double* statev, const double* d) {
  size_t length = 0;
  EXPECT_EQ(acst_reproducer(nullptr, &length, m, stress, statev, d).code, ACST_OK);
  std::string text(length, '\0');
  EXPECT_EQ(acst_reproducer(text.data(), &length, m, stress, statev, d).code, ACST_OK);
  text.resize(length - 1);  // the terminating NUL
  return text;
}

// The end stress of the replayed scene in the ABI's convention (tension positive).
std::vector<double> replayed_stress(const std::string& scene, bool& ok) {
  const acst::driver::RunResult r = acst::test::run(scene);
  ok = r.ok;
  std::vector<double> s;
  for (int i = 0; i < 6; ++i) s.push_back(-r.records.back().stress[i]);
  return s;
}

// A dense point loaded into plastic shear, with a tilted deposition direction (all six
// fabric components non-zero).
struct LoadedPoint {
  double stress[6], statev[ACST_NSTATV];
  LoadedPoint(const acst_model* m) {
    const double s0[6] = {-100, -100, -100, 0, 0, 0}, b[3] = {1.0, 0.4, -0.3};
    EXPECT_EQ(acst_initial_state(statev, stress, m, s0, 0.7, b).code, ACST_OK);
    const double d[6] = {-1e-3, 4e-4, 3e-4, 2e-4, -1e-4, 1e-4};
    for (int k = 0; k < 5; ++k) EXPECT_EQ(acst_update(stress, statev, nullptr, nullptr, m, d).code, ACST_OK);
  }
};

}  // namespace

TEST(Reproducer, AGoodUpdateReplaysToTheSameStress) {
  Handle h(acst::test::read_text(guide));
  LoadedPoint p(h.model);
  const double d[6] = {-2e-3, 8e-4, 6e-4, 5e-4, -3e-4, 2e-4};
  const std::string text = reproducer_text(h.model, p.stress, p.statev, d);
  double s[6], q[ACST_NSTATV];
  std::copy(p.stress, p.stress + 6, s);
  std::copy(p.statev, p.statev + ACST_NSTATV, q);
  ASSERT_EQ(acst_update(s, q, nullptr, nullptr, h.model, d).code, ACST_OK);
  bool ok = false;
  const std::vector<double> replay = replayed_stress(text, ok);
  ASSERT_TRUE(ok) << text;
  double scale = 0.0;
  for (double v : s) scale = std::max(scale, std::abs(v));
  // 1e-8: the replay goes through the driver's Newton solve of six strain rows, which is exact
  // for strain control up to its stress tolerance (1e-8 relative).
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(replay[i], s[i], 1e-8 * scale) << "component " << i;
}

TEST(Reproducer, AFailingUpdateReplaysAsAFailure) {
  std::string text = acst::test::read_text(guide);
  // The pressure floor policy "fail": a huge volumetric expansion is then a step reduction.
  const std::string key = "\"integrator\": {";
  text.replace(text.find(key), key.size(), key + "\"pressure_floor\": \"fail\", ");
  Handle h(text);
  LoadedPoint p(h.model);
  const double d[6] = {0.2, 0.2, 0.2, 0, 0, 0};
  double s[6], q[ACST_NSTATV];
  std::copy(p.stress, p.stress + 6, s);
  std::copy(p.statev, p.statev + ACST_NSTATV, q);
  ASSERT_NE(acst_update(s, q, nullptr, nullptr, h.model, d).code, ACST_OK);
  bool ok = true;
  replayed_stress(reproducer_text(h.model, p.stress, p.statev, d), ok);
  EXPECT_FALSE(ok) << "the replay of a failing update must fail as well";
}

TEST(Reproducer, BufferRulesAndRefusals) {
  Handle h(acst::test::read_text(guide));
  LoadedPoint p(h.model);
  const double d[6] = {-1e-4, 0, 0, 0, 0, 0};
  size_t needed = 0;
  ASSERT_EQ(acst_reproducer(nullptr, &needed, h.model, p.stress, p.statev, d).code, ACST_OK);
  ASSERT_GT(needed, 100u);
  std::string small(needed - 1, 'x');
  size_t length = small.size();
  const acst_status st = acst_reproducer(small.data(), &length, h.model, p.stress, p.statev, d);
  EXPECT_EQ(st.code, ACST_INVALID_INPUT);
  EXPECT_NE(std::string(st.message).find("too small"), std::string::npos) << st.message;
  EXPECT_EQ(length, needed);
  EXPECT_EQ(small, std::string(needed - 1, 'x')) << "nothing may be written into a buffer too small";
  EXPECT_EQ(acst_reproducer(nullptr, nullptr, h.model, p.stress, p.statev, d).code, ACST_INVALID_INPUT);

  Handle elastic(R"({"model": "linear_elastic", "parameters": {"E": 1000, "nu": 0.3}})");
  const double s0[6] = {-10, -10, -10, 0, 0, 0};
  const acst_status refused = acst_reproducer(nullptr, &length, elastic.model, s0, nullptr, d);
  EXPECT_EQ(refused.code, ACST_INVALID_INPUT);
  EXPECT_NE(std::string(refused.message).find("linear_elastic"), std::string::npos) << refused.message;
}

// umat_ hosts: the scene from acst_umat_reproducer replays what umat_ computed, DROT included.
TEST(Reproducer, UmatReproducerReplaysTheUmatUpdate) {
  const std::string text = acst::test::read_text(guide);
  const nlohmann::json j = nlohmann::json::parse(text);
  std::vector<double> props;
  for (int i = 0; i < acst::parameter_count; ++i) props.push_back(j["parameters"][acst::parameter_names[i]].get<double>());
  props.push_back(1.0);  // ME
  props.push_back(j["integrator"]["stol"].get<double>());
  Handle h(text);
  LoadedPoint p(h.model);
  const double c = std::cos(0.3), s = std::sin(0.3);
  const double drot[9] = {c, s, 0, -s, c, 0, 0, 0, 1};  // column-major rotation about axis 3
  const double dstran[6] = {-1e-3, 3e-4, 2e-4, 4e-4, -2e-4, 1e-4};
  size_t length = 0;
  ASSERT_EQ(acst_umat_reproducer(nullptr, &length, p.stress, p.statev, dstran, 6, props.data(),
                                 static_cast<int>(props.size()), drot).code,
            ACST_OK);
  std::string scene(length, '\0');
  ASSERT_EQ(acst_umat_reproducer(scene.data(), &length, p.stress, p.statev, dstran, 6, props.data(),
                                 static_cast<int>(props.size()), drot).code,
            ACST_OK);
  scene.resize(length - 1);

  double stress[6], statev[ACST_NSTATV], ddsdde[36], rpl = 0, sse = 0, spd = 0, scd = 0, ddsddt[6], drplde[6],
      drpldt = 0, stran[6] = {}, time[2] = {}, dtime = 1, temp = 0, dtemp = 0, predef = 0, dpred = 0, coords[3] = {},
      pnewdt = 1, celent = 1, f0[9] = {}, f1[9] = {};
  int ndi = 3, nshr = 3, ntens = 6, nstatv = ACST_NSTATV, nprops = static_cast<int>(props.size()), one = 1;
  std::copy(p.stress, p.stress + 6, stress);
  std::copy(p.statev, p.statev + ACST_NSTATV, statev);
  umat_(stress, statev, ddsdde, &sse, &spd, &scd, &rpl, ddsddt, drplde, &drpldt, stran, dstran, time, &dtime, &temp,
        &dtemp, &predef, &dpred, "ACST", &ndi, &nshr, &ntens, &nstatv, props.data(), &nprops, coords, drot, &pnewdt,
        &celent, f0, f1, &one, &one, &one, &one, &one, &one, 4);
  ASSERT_EQ(pnewdt, 1.0);
  bool ok = false;
  const std::vector<double> replay = replayed_stress(scene, ok);
  ASSERT_TRUE(ok);
  double scale = 0.0;
  for (double v : stress) scale = std::max(scale, std::abs(v));
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(replay[i], stress[i], 1e-8 * scale) << "component " << i;
}
