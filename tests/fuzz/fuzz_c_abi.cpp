// The C ABI under random models, states and strain increments (docs/c-abi.md, docs/testing.md).
// From the fuzzer's bytes: a model (a bundled parameter set of data/parameters, or a linear
// elastic or von Mises material with moduli over many decades), a state (from acst_initial_state
// or raw doubles) and a sequence of calls: acst_update with increments from 1e-12 to 10 (or any
// double), acst_rotate_state, acst_update_rotated (and acst_update_rotated_batch on the same
// point, which must give the same bits, and acst_rotate_state then acst_update, its documented
// equivalent, which must go on where it goes on, to the same bits, and fail where it fails),
// acst_diagnostics, acst_wave_speed.
// Checked after every call:
//   - on any status but ACST_OK the stress and state passed in are unchanged (always);
//   - ACST_OK means every output is finite and physical: stress, state, tangent, diagnostics and
//     wave speed finite, and for the sand models void ratio > 0 and p >= 0 (with the CMake
//     option ACST_FUZZ_OK_RULE, or ACST_FUZZ_OK_RULE=1 in the environment, which overrides it
//     either way; off until the ABI keeps this rule).
// A violation aborts, so libFuzzer reports it with the input that caused it.
// An input picks its parameter set by its index in name order: adding a set to data/parameters
// changes what the stored inputs of corpus/fuzz_c_abi mean (they still run, on other models).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acst.h"
#include "fuzz_bytes.hpp"

namespace {

// The bundled parameter sets, in name order, created once (handles are immutable) and destroyed
// at exit, before the leak check runs.
struct Models {
  std::vector<acst_model*> sand;
  ~Models() {
    for (acst_model* m : sand) acst_model_destroy(m);
  }
};

Models bundled;
bool ok_rule = false;
// ACST_FUZZ_SKIP="text;text": violations whose "call: what" contains one of the texts are
// passed over, to look past one that is known (e.g. "acst_update: OK with a non-finite").
std::vector<std::string> skipped;
// The arguments of the call being checked, printed with a finding.
std::string arguments;

[[noreturn]] void setup_failed(const char* what, const acst_status& s) {
  std::fprintf(stderr, "fuzz_c_abi: %s (code %d, message '%.256s')\n%s", what, s.code, s.message, arguments.c_str());
  std::abort();
}

std::string numbers(const char* name, const double* v, int n) {
  std::string s = std::string(name) + " [";
  char buf[32];
  for (int i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, "%s%.17g", i ? ", " : "", v[i]);
    s += buf;
  }
  return s + "]\n";
}

void finding(const char* call, const char* what, const acst_status& s) {
  const std::string id = std::string(call) + ": " + what;
  for (const std::string& text : skipped)
    if (id.find(text) != std::string::npos) return;
  std::fprintf(stderr, "fuzz_c_abi: %s (code %d, message '%.256s')\n%s", id.c_str(), s.code, s.message,
               arguments.c_str());
  std::abort();
}

bool all_finite(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// Sand state rule: the void ratio (statev slot 6) positive and p >= 0 (tension positive here).
bool physical_sand(const double* stress, const double* statev) {
  return statev[6] > 0.0 && -(stress[0] + stress[1] + stress[2]) / 3.0 >= 0.0;
}

double magnitude(acst::fuzz::Bytes& in, double lo_exp, double hi_exp) {
  return std::pow(10.0, in.in_range(lo_exp, hi_exp));
}

// A double over many decades, or (one time in eight) any bit pattern: NaN, infinity, denormals.
double wide(acst::fuzz::Bytes& in, double lo_exp, double hi_exp) {
  if (in.pick(0, 7) == 0) return in.any();
  const double sign = in.flag() ? -1.0 : 1.0;
  return sign * magnitude(in, lo_exp, hi_exp);
}

acst_model* verification_kind(acst::fuzz::Bytes& in) {
  char json[320];
  const double E = magnitude(in, -3.0, 9.0), nu = in.in_range(-0.99, 0.49);
  const int kind = in.pick(0, 2);
  if (kind == 0) {
    std::snprintf(json, sizeof json, R"({"model":"linear_elastic","parameters":{"E":%.17g,"nu":%.17g}})", E, nu);
  } else if (kind == 1) {
    const double phi = in.in_range(0.0, 59.9), psi = in.in_range(0.0, 1.0) * phi;
    const double c = in.flag() ? 0.0 : magnitude(in, -3.0, 5.0);
    std::snprintf(json, sizeof json,
                  R"({"model":"drucker_prager","parameters":{"E":%.17g,"nu":%.17g,"friction_angle_deg":%.17g,"cohesion":%.17g,"dilation_angle_deg":%.17g}})",
                  E, nu, phi == 0.0 && c == 0.0 ? 1.0 : phi, c, psi);
  } else {
    const char* key = in.flag() ? "yield_stress" : "undrained_shear_strength";
    std::snprintf(json, sizeof json, R"({"model":"von_mises","parameters":{"E":%.17g,"nu":%.17g,"%s":%.17g}})", E, nu,
                  key, magnitude(in, -3.0, 7.0));
  }
  acst_model* m = nullptr;
  arguments = std::string(json) + "\n";
  const acst_status s = acst_model_create(&m, json);
  if (s.code != ACST_OK) setup_failed("a valid verification material was refused", s);
  return m;
}

struct Point {
  double stress[6] = {};
  double statev[ACST_NSTATV] = {};
};

void check_unchanged(const char* call, const acst_status& s, const Point& before, const Point& after) {
  if (std::memcmp(&before, &after, sizeof before) != 0) finding(call, "not OK but the stress or state changed", s);
}

void check_ok_point(const char* call, const acst_status& s, const Point& p, int nstatv, bool sand) {
  if (!ok_rule) return;
  if (!all_finite(p.stress, 6) || !all_finite(p.statev, nstatv))
    return finding(call, "OK with a non-finite stress or state", s);
  if (sand && !physical_sand(p.stress, p.statev)) finding(call, "OK with void ratio <= 0 or p < 0", s);
}

void initial_state(acst::fuzz::Bytes& in, const acst_model* m, Point& p, bool sand) {
  const double pc = wide(in, -2.0, 5.0);
  double stress0[6];
  for (int i = 0; i < 6; ++i) stress0[i] = (i < 3 ? -pc : 0.0) + pc * in.in_range(-0.9, 0.9);
  const double e = in.flag() ? in.in_range(0.3, 1.3) : wide(in, -3.0, 3.0);
  double b[3];
  for (double& x : b) x = in.flag() ? in.in_range(-1.0, 1.0) : wide(in, -300.0, 300.0);
  const Point before = p;
  arguments = numbers("stress0", stress0, 6) + numbers("void ratio", &e, 1) + numbers("direction", b, 3);
  const acst_status s = acst_initial_state(p.statev, p.stress, m, stress0, e, b);
  if (s.code != ACST_OK) return check_unchanged("acst_initial_state", s, before, p);
  check_ok_point("acst_initial_state", s, p, acst_state_size(m), sand);
}

void raw_state(acst::fuzz::Bytes& in, Point& p, int nstatv) {
  for (double& x : p.stress) x = wide(in, -3.0, 6.0);
  for (int i = 0; i < nstatv; ++i) p.statev[i] = wide(in, -3.0, 3.0);
}

// From 1e-12 to 10 in size, or (one time in sixteen) with one component any double.
void strain_increment(acst::fuzz::Bytes& in, double* d) {
  const double size = wide(in, -12.0, 1.0);
  for (int i = 0; i < 6; ++i) d[i] = size * in.in_range(-1.0, 1.0);
  if (in.pick(0, 15) == 0) d[in.pick(0, 5)] = in.any();
}

void update(acst::fuzz::Bytes& in, const acst_model* m, Point& p, bool sand) {
  double d[6];
  strain_increment(in, d);
  double tangent[36];
  acst_counters counters;
  const Point before = p;
  arguments = numbers("stress", p.stress, 6) + numbers("statev", p.statev, acst_state_size(m)) + numbers("dstrain", d, 6);
  const acst_status s = acst_update(p.stress, p.statev, tangent, &counters, m, d);
  if (s.code != ACST_OK) return check_unchanged("acst_update", s, before, p);
  check_ok_point("acst_update", s, p, acst_state_size(m), sand);
  if (ok_rule && !all_finite(tangent, 36)) finding("acst_update", "OK with a non-finite tangent", s);
}

void update_rotated(acst::fuzz::Bytes& in, const acst_model* m, Point& p, bool sand, const double* Q) {
  double d[6];
  strain_increment(in, d);
  double tangent[36];
  acst_counters counters;
  const Point before = p;
  arguments = numbers("stress", p.stress, 6) + numbers("statev", p.statev, acst_state_size(m)) + numbers("Q", Q, 9) +
              numbers("dstrain", d, 6);
  const acst_status s = acst_update_rotated(p.stress, p.statev, tangent, &counters, m, Q, d);
  // The batch form must give the same point, bit for bit (it may take SIMD lanes).
  Point batch = before;
  int code = -1;
  acst_update_rotated_batch(batch.stress, 6, batch.statev, ACST_NSTATV, &code, nullptr, m, 1, Q, d);
  if (code != s.code || std::memcmp(&batch, &p, sizeof batch) != 0)
    finding("acst_update_rotated_batch", "differs from acst_update_rotated", s);
  // Its documented equivalent, acst_rotate_state then acst_update, with which a host retries after
  // a step reduction: where the one call goes on (OK, a step reduction) the two give the same status
  // and, on OK, the same bits; where it fails otherwise the two fail too (with a wrong state and a
  // wrong strain at once, which of the two each names first may differ).
  Point two = before;
  acst_status t = acst_rotate_state(two.stress, two.statev, m, Q);
  if (t.code == ACST_OK) t = acst_update(two.stress, two.statev, nullptr, nullptr, m, d);
  const auto goes_on = [](int code) { return code == ACST_OK || code == ACST_STEP_REDUCTION; };
  const bool same = goes_on(s.code) || goes_on(t.code) ? t.code == s.code : true;
  if (!same || (s.code == ACST_OK && std::memcmp(&two, &p, sizeof two) != 0))
    finding("acst_update_rotated", "differs from acst_rotate_state then acst_update", s);
  if (s.code != ACST_OK) return check_unchanged("acst_update_rotated", s, before, p);
  check_ok_point("acst_update_rotated", s, p, acst_state_size(m), sand);
  if (ok_rule && !all_finite(tangent, 36)) finding("acst_update_rotated", "OK with a non-finite tangent", s);
}

// A proper rotation from three angles, or (one time in eight) nine arbitrary numbers; half the
// time the point is turned and updated in one call (acst_update_rotated).
void rotate(acst::fuzz::Bytes& in, const acst_model* m, Point& p, bool sand) {
  double Q[9];
  if (in.pick(0, 7) == 0) {
    for (double& x : Q) x = wide(in, -3.0, 1.0);
  } else {
    const double a = in.in_range(-4.0, 4.0), b = in.in_range(-4.0, 4.0),
                 c = in.in_range(-4.0, 4.0);
    const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b), cc = std::cos(c), sc = std::sin(c);
    const double R[9] = {ca * cb, ca * sb * sc - sa * cc, ca * sb * cc + sa * sc,
                         sa * cb, sa * sb * sc + ca * cc, sa * sb * cc - ca * sc,
                         -sb,     cb * sc,                cb * cc};
    std::copy(R, R + 9, Q);
  }
  if (in.flag()) return update_rotated(in, m, p, sand, Q);
  const Point before = p;
  arguments = numbers("stress", p.stress, 6) + numbers("statev", p.statev, acst_state_size(m)) + numbers("Q", Q, 9);
  const acst_status s = acst_rotate_state(p.stress, p.statev, m, Q);
  if (s.code != ACST_OK) return check_unchanged("acst_rotate_state", s, before, p);
  check_ok_point("acst_rotate_state", s, p, acst_state_size(m), sand);
}

void diagnostics(const acst_model* m, const Point& p, bool sand) {
  double out[ACST_NDIAGNOSTICS];
  arguments = numbers("stress", p.stress, 6) + numbers("statev", p.statev, acst_state_size(m));
  const acst_status s = acst_diagnostics(out, m, p.stress, p.statev);
  if (s.code != ACST_OK || !ok_rule) return;
  // The verification kinds fill p, q, G and K only (the sand entries are NaN by design).
  const bool finite = sand ? all_finite(out, ACST_NDIAGNOSTICS)
                           : all_finite(out, 2) && std::isfinite(out[11]) && std::isfinite(out[12]);
  if (!finite) finding("acst_diagnostics", "OK with a non-finite diagnostic", s);
}

void wave_speed(acst::fuzz::Bytes& in, const acst_model* m, const Point& p) {
  double c = 0.0;
  const double density = wide(in, -1.0, 5.0);
  arguments = numbers("stress", p.stress, 6) + numbers("statev", p.statev, acst_state_size(m)) + numbers("density", &density, 1);
  const acst_status s = acst_wave_speed(&c, m, p.stress, p.statev, density);
  if (s.code == ACST_OK && ok_rule && !(std::isfinite(c) && c > 0.0))
    finding("acst_wave_speed", "OK with a speed that is not finite and positive", s);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* rule = std::getenv("ACST_FUZZ_OK_RULE");
  ok_rule = rule ? std::strcmp(rule, "1") == 0 : ACST_FUZZ_OK_RULE_DEFAULT;
  if (const char* skip = std::getenv("ACST_FUZZ_SKIP")) {
    std::stringstream list(skip);
    for (std::string text; std::getline(list, text, ';');)
      if (!text.empty()) skipped.push_back(text);
  }
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(ACST_DATA_DIR "/parameters"))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::ifstream is(f);
    std::stringstream text;
    text << is.rdbuf();
    acst_model* m = nullptr;
    const acst_status s = acst_model_create(&m, text.str().c_str());
    if (s.code != ACST_OK) setup_failed("a bundled parameter set was refused", s);
    bundled.sand.push_back(m);
  }
  if (bundled.sand.empty()) setup_failed("no parameter sets in " ACST_DATA_DIR "/parameters", {});
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  acst::fuzz::Bytes in(data, size);
  const int n_sand = static_cast<int>(bundled.sand.size());
  const int pick = in.pick(0, n_sand);  // n_sand: a verification kind
  acst_model* own = pick == n_sand ? verification_kind(in) : nullptr;
  const acst_model* m = own ? own : bundled.sand[pick];
  const bool sand = own == nullptr;
  Point p;
  if (in.pick(0, 3) == 0) raw_state(in, p, acst_state_size(m));
  else initial_state(in, m, p, sand);
  const int calls = in.pick(1, 12);
  for (int k = 0; k < calls && in.remaining() > 0; ++k) {
    switch (in.pick(0, 7)) {
      case 0: rotate(in, m, p, sand); break;
      case 1: diagnostics(m, p, sand); break;
      case 2: wave_speed(in, m, p); break;
      default: update(in, m, p, sand); break;
    }
  }
  acst_model_destroy(own);
  return 0;
}
