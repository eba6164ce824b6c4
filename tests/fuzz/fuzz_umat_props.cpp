// umat_'s PROPS (docs/c-abi.md, "umat_ and its hosts"): a host's input deck gives them, and any
// double may arrive. From the fuzzer's bytes: NPROPS (0 to 30), each of PROPS the bundled guide
// set's value, that value scaled over many decades, or (one time in four) any double (NaN,
// infinities, 1e300); NTENS 6 or 4; a strain increment from 1e-12 to 10. The point starts from
// the guide set's state at 100 kPa. Through acst_umat (umat_'s work with its status) and
// acst_umat_reproducer on the same arguments. A finding is a crash or sanitizer report (PROPS(19)
// was converted to an int before it was checked), or a broken protocol:
//   - a failed call changed STRESS or STATEV, left DDSDDE non-finite, or PNEWDT outside (0, 1);
//   - an OK call returned a non-finite stress, state or DDSDDE, or a void ratio outside (0, 2.97).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "acst.h"
#include "fuzz_bytes.hpp"

namespace {

// PROPS as a host gives them: the guide set's constants (data/parameters/toyoura_acst_guide.json)
// in PROPS order (docs/model.md section 9), then PROPS(19..25): ME, STOL 1e-4, reset to p_min,
// the rotating frame, Li's g, no elastic anisotropy, no peak-pressure exponent.
const char* const constant_names[] = {"G0", "nu", "Mc", "c", "e_Gamma", "lambda_c", "xi", "d1", "m",
                                      "h1", "h2", "n", "e_A", "F0", "k_f", "e_max", "e_min", "p_min"};
std::vector<double> guide_props;
std::string guide_text;

double stress0[6], statev0[ACST_NSTATV];

[[noreturn]] void finding(const char* what, const acst_status& s, const std::vector<double>& props) {
  std::fprintf(stderr, "fuzz_umat_props: %s (code %d, message '%.256s')\nPROPS", what, s.code, s.message);
  for (double p : props) std::fprintf(stderr, " %.17g", p);
  std::fprintf(stderr, "\n");
  std::abort();
}

bool all_finite(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::ifstream in(ACST_DATA_DIR "/parameters/toyoura_acst_guide.json");
  std::stringstream text;
  text << in.rdbuf();
  guide_text = text.str();
  const nlohmann::json parameters = nlohmann::json::parse(guide_text).at("parameters");
  for (const char* name : constant_names) guide_props.push_back(parameters.at(name).get<double>());
  for (const double extra : {1.0, 1e-4, 0.0, 0.0, 0.0, 0.0, 0.0}) guide_props.push_back(extra);
  // The start state comes from the ABI itself, as a host's would.
  acst_model* m = nullptr;
  acst_status s = acst_model_create(&m, guide_text.c_str());
  const double s0[6] = {-100, -100, -100, 0, 0, 0}, b[3] = {1, 0, 0};
  if (s.code == ACST_OK) s = acst_initial_state(statev0, stress0, m, s0, 0.7, b);
  acst_model_destroy(m);
  if (s.code != ACST_OK) finding("the guide set's start state was refused", s, {});
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  acst::fuzz::Bytes in(data, size);
  const int nprops = in.pick(0, 30);
  std::vector<double> props(static_cast<std::size_t>(nprops));
  for (int i = 0; i < nprops; ++i) {
    const double guide = static_cast<std::size_t>(i) < guide_props.size() ? guide_props[static_cast<std::size_t>(i)] : 0.0;
    switch (in.pick(0, 3)) {
      case 0: props[i] = in.any(); break;
      case 1: props[i] = guide * std::pow(10.0, in.in_range(-6.0, 6.0)) * (in.flag() ? -1.0 : 1.0); break;
      default: props[i] = guide; break;
    }
  }
  const int ntens = in.flag() ? 6 : 4;
  const double magnitude = std::pow(10.0, in.in_range(-12.0, 1.0));
  double dstran[6];
  for (double& d : dstran) d = magnitude * in.in_range(-1.0, 1.0);
  double stress[6], statev[ACST_NSTATV], ddsdde[36];
  std::memcpy(stress, stress0, sizeof stress);
  std::memcpy(statev, statev0, sizeof statev);
  double pnewdt = in.flag() ? -1.0 : 1e36;  // as CalculiX and Abaqus pass it
  const double pnewdt_in = pnewdt;
  const acst_status st = acst_umat(stress, statev, ddsdde, dstran, ntens, ACST_NSTATV, props.data(), nprops, nullptr, &pnewdt);
  if (st.code != ACST_OK) {
    if (std::memcmp(stress, stress0, sizeof(double) * static_cast<std::size_t>(ntens)) != 0 ||
        std::memcmp(statev, statev0, sizeof statev) != 0)
      finding("a failed call changed STRESS or STATEV", st, props);
    if (!all_finite(ddsdde, ntens * ntens)) finding("a failed call left DDSDDE non-finite", st, props);
    if (!(pnewdt > 0.0 && pnewdt < 1.0)) finding("a failed call left PNEWDT outside (0, 1)", st, props);
  } else {
    if (!all_finite(stress, ntens) || !all_finite(statev, ACST_NSTATV) || !all_finite(ddsdde, ntens * ntens))
      finding("OK with a non-finite STRESS, STATEV or DDSDDE", st, props);
    if (!(statev[6] > 0.0 && statev[6] < 2.97)) finding("OK with a void ratio outside (0, 2.97)", st, props);
    if (pnewdt != pnewdt_in) finding("OK changed PNEWDT", st, props);
  }
  size_t length = 0;
  acst_umat_reproducer(nullptr, &length, stress0, statev0, dstran, ntens, props.data(), nprops, nullptr);
  return 0;
}
