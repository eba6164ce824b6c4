/* The C ABI (acst.h) as a plain C99 host sees it: model creation, state layout, initial state,
 * a strain-controlled path with physical checks, wave speed, and bad inputs that must come back
 * as status codes with messages, leaving stress and state untouched.
 *
 * Convention at this interface: tension positive, engineering shear, Voigt 11 22 33 12 13 23.
 * Exit 0 when every check passes; otherwise each failure is printed and the exit code is 1. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "acst.h"

static int passed = 0, failed = 0;

#define CHECK(cond, ...)                                          \
  do {                                                            \
    if (cond) {                                                   \
      ++passed;                                                   \
    } else {                                                      \
      ++failed;                                                   \
      fprintf(stderr, "FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stderr, __VA_ARGS__);                               \
      fprintf(stderr, "\n");                                      \
    }                                                             \
  } while (0)

/* |a - b| <= tol * max(|b|, floor) */
static int close_rel(double a, double b, double tol, double floor_value) {
  const double scale = fabs(b) > floor_value ? fabs(b) : floor_value;
  return fabs(a - b) <= tol * scale;
}

static char* read_file(const char* path) {
  FILE* f = fopen(path, "rb");
  long n;
  char* text;
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  n = ftell(f);
  fseek(f, 0, SEEK_SET);
  text = (char*)malloc((size_t)n + 1);
  if (text && fread(text, 1, (size_t)n, f) != (size_t)n) {
    free(text);
    text = NULL;
  }
  if (text) text[n] = '\0';
  fclose(f);
  return text;
}

/* The JSON text with `insert` placed right after the opening brace of the "parameters" object. */
static char* insert_into_parameters(const char* json, const char* insert) {
  const char* key = strstr(json, "\"parameters\"");
  const char* brace = key ? strchr(key, '{') : NULL;
  size_t head, n;
  char* out;
  if (!brace) return NULL;
  head = (size_t)(brace - json) + 1;
  n = strlen(json) + strlen(insert) + 1;
  out = (char*)malloc(n);
  if (!out) return NULL;
  memcpy(out, json, head);
  strcpy(out + head, insert);
  strcat(out, json + head);
  return out;
}

static int state_index(const acst_model* model, const char* name) {
  int i;
  for (i = 0; i < acst_state_size(model); ++i) {
    const char* s = acst_state_name(model, i);
    if (s && strcmp(s, name) == 0) return i;
  }
  return -1;
}

static double mean_pressure(const double* s) { return -(s[0] + s[1] + s[2]) / 3.0; }

/* q = sqrt(3/2 s:s) from an engineering Voigt stress (shear stresses are tensor components). */
static double deviatoric_q(const double* s) {
  const double p = (s[0] + s[1] + s[2]) / 3.0;
  const double a = s[0] - p, b = s[1] - p, c = s[2] - p;
  return sqrt(1.5 * (a * a + b * b + c * c + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
}

/* Guide set constants (data/parameters/toyoura_acst_guide.json), used for closed forms. */
static const double G0 = 125.0, NU = 0.1, F0 = 0.43, E_GAMMA = 0.934, LAMBDA_C = 0.019, XI = 0.7;
static const double PA = 101.0; /* atmospheric pressure of the model, kPa */

/* G = G0 pa (2.97 - e)^2 / (1 + e) sqrt(p / pa); K = G 2(1 + nu) / (3(1 - 2 nu)). */
static double shear_modulus(double e, double p) { return G0 * PA * (2.97 - e) * (2.97 - e) / (1.0 + e) * sqrt(p / PA); }
static double bulk_modulus(double G) { return G * 2.0 * (1.0 + NU) / (3.0 * (1.0 - 2.0 * NU)); }

static void test_state_layout(const acst_model* model) {
  int i, j;
  CHECK(acst_state_size(model) == ACST_NSTATV, "state size %d, header says %d", acst_state_size(model), ACST_NSTATV);
  for (i = 0; i < acst_state_size(model); ++i) {
    const char* name = acst_state_name(model, i);
    CHECK(name != NULL && name[0] != '\0', "state variable %d has no name", i);
    for (j = 0; name && j < i; ++j) {
      const char* other = acst_state_name(model, j);
      CHECK(other == NULL || strcmp(name, other) != 0, "state names %d and %d are both '%s'", i, j, name);
    }
  }
  CHECK(acst_state_name(model, -1) == NULL, "name of index -1 must be NULL");
  CHECK(acst_state_name(model, acst_state_size(model)) == NULL, "name past the end must be NULL");
  CHECK(state_index(model, "void_ratio") >= 0, "a state variable named void_ratio");
  CHECK(acst_diagnostic_name(0) != NULL && strcmp(acst_diagnostic_name(0), "p") == 0, "diagnostic 0 is p");
  CHECK(acst_diagnostic_name(ACST_NDIAGNOSTICS - 1) != NULL && strcmp(acst_diagnostic_name(ACST_NDIAGNOSTICS - 1), "K") == 0,
        "last diagnostic is K");
  CHECK(acst_diagnostic_name(ACST_NDIAGNOSTICS) == NULL, "diagnostic name past the end must be NULL");
}

/* Index of a diagnostic by its name, so the test does not rely on the order in the header. */
static int diagnostic_index(const char* name) {
  int i;
  for (i = 0; i < ACST_NDIAGNOSTICS; ++i)
    if (acst_diagnostic_name(i) && strcmp(acst_diagnostic_name(i), name) == 0) return i;
  return -1;
}

/* Initial state: stress passes through, fabric F0 (3 b b - I)/sqrt(6), void ratio stored, and the
 * diagnostics and wave speed equal their closed forms. */
static void test_initial_state(const acst_model* model, double* stress, double* statev) {
  const double stress0[6] = {-100, -100, -100, 0, 0, 0}, b[3] = {1, 0, 0};
  const double rho = 1900.0; /* kg/m^3 */
  const int ie = state_index(model, "void_ratio"), iF11 = state_index(model, "F11"), iF22 = state_index(model, "F22"),
            iF33 = state_index(model, "F33");
  double d[ACST_NDIAGNOSTICS], speed = 0.0, alias[6], alias_statev[ACST_NSTATV];
  acst_status st;
  int i;
  st = acst_initial_state(statev, stress, model, stress0, 0.67, b);
  CHECK(st.code == ACST_OK && st.message[0] == '\0', "initial state: code %d '%s'", st.code, st.message);
  for (i = 0; i < 6; ++i) CHECK(stress[i] == stress0[i], "initial stress[%d] = %g", i, stress[i]);
  CHECK(ie >= 0 && statev[ie] == 0.67, "stored void ratio");
  /* Closed form of the initial fabric; 1e-15 relative: one multiplication and a division apart. */
  CHECK(iF11 >= 0 && close_rel(statev[iF11], F0 * 2.0 / sqrt(6.0), 1e-15, 0.0), "F11 = %.17g", statev[iF11]);
  CHECK(iF22 >= 0 && close_rel(statev[iF22], -F0 / sqrt(6.0), 1e-15, 0.0), "F22 = %.17g", statev[iF22]);
  CHECK(iF33 >= 0 && close_rel(statev[iF33], -F0 / sqrt(6.0), 1e-15, 0.0), "F33 = %.17g", statev[iF33]);

  /* stress_out may alias stress0. */
  memcpy(alias, stress0, sizeof alias);
  st = acst_initial_state(alias_statev, alias, model, alias, 0.67, b);
  CHECK(st.code == ACST_OK, "aliased initial state: %s", st.message);
  CHECK(memcmp(alias, stress, sizeof alias) == 0 && memcmp(alias_statev, statev, sizeof alias_statev) == 0,
        "aliased stress gives the same initial state");

  st = acst_diagnostics(d, model, stress, statev);
  CHECK(st.code == ACST_OK, "diagnostics: %s", st.message);
  {
    const double G = shear_modulus(0.67, 100.0), K = bulk_modulus(G);
    const double ec = E_GAMMA - LAMBDA_C * pow(100.0 / PA, XI);
    /* 1e-13 relative: a few operations of round-off in both closed forms. */
    CHECK(close_rel(d[diagnostic_index("p")], 100.0, 1e-14, 0.0), "p = %.17g", d[diagnostic_index("p")]);
    CHECK(fabs(d[diagnostic_index("q")]) < 1e-12, "q = %g at an isotropic state", d[diagnostic_index("q")]);
    CHECK(close_rel(d[diagnostic_index("G")], G, 1e-13, 0.0), "G = %.17g, closed form %.17g", d[diagnostic_index("G")], G);
    CHECK(close_rel(d[diagnostic_index("K")], K, 1e-13, 0.0), "K = %.17g, closed form %.17g", d[diagnostic_index("K")], K);
    CHECK(close_rel(d[diagnostic_index("e_c")], ec, 1e-13, 0.0), "e_c = %.17g, closed form %.17g",
          d[diagnostic_index("e_c")], ec);
    CHECK(close_rel(d[diagnostic_index("psi")], 0.67 - ec, 1e-12, 0.0), "psi = %.17g", d[diagnostic_index("psi")]);
    /* |F| = F0 for the initial fabric. */
    CHECK(close_rel(d[diagnostic_index("fabric_norm")], F0, 1e-14, 0.0), "|F| = %.17g", d[diagnostic_index("fabric_norm")]);
    st = acst_wave_speed(&speed, model, stress, statev, rho);
    CHECK(st.code == ACST_OK, "wave speed: %s", st.message);
    /* kPa -> Pa is the factor 1000; 1e-14 relative: a sqrt of the same few operations. */
    CHECK(close_rel(speed, sqrt((K + 4.0 * G / 3.0) * 1000.0 / rho), 1e-13, 0.0), "wave speed %.17g m/s", speed);
    /* Sanity of magnitude: dense sand at 100 kPa has a P-wave speed of a few hundred m/s. */
    CHECK(speed > 100.0 && speed < 2000.0, "wave speed %g m/s out of the plausible range", speed);
  }
}

/* Strain-controlled path: axial compression with a fixed lateral expansion (a simple mixed path
 * with net volumetric compression). Stresses stay compressive, q grows, the void ratio follows
 * the volumetric strain exactly, and the wave speed matches K and G from the diagnostics. */
static void test_compression_path(const acst_model* model, double* stress, double* statev) {
  const double de[6] = {-1e-4, 3e-5, 3e-5, 0, 0, 0}; /* tension positive: axial compression */
  const double rho = 1950.0;
  const int steps = 150, ie = state_index(model, "void_ratio");
  const double e0 = statev[ie];
  double q_prev = deviatoric_q(stress), eps_v = 0.0, tangent[36], d[ACST_NDIAGNOSTICS], speed = 0.0;
  int i, k, all_negative = 1, q_grows = 1, all_finite = 1, any_plastic = 0;
  acst_counters counters;
  acst_status st;
  for (i = 0; i < steps; ++i) {
    st = acst_update(stress, statev, tangent, &counters, model, de);
    if (st.code != ACST_OK) {
      CHECK(0, "update %d failed: %s", i, st.message);
      return;
    }
    eps_v += de[0] + de[1] + de[2];
    for (k = 0; k < 3; ++k) all_negative &= stress[k] < 0.0;
    for (k = 0; k < 6; ++k) all_finite &= isfinite(stress[k]);
    for (k = 0; k < 36; ++k) all_finite &= isfinite(tangent[k]);
    if (!(deviatoric_q(stress) > q_prev)) q_grows = 0;
    q_prev = deviatoric_q(stress);
    any_plastic |= counters.plastic;
  }
  CHECK(all_negative, "normal stresses must stay negative (compressive) on a compressive path");
  CHECK(all_finite, "stress and tangent finite");
  CHECK(q_grows, "q must grow on every increment of this monotonic shearing path");
  CHECK(any_plastic, "shearing from an isotropic state must be plastic");
  /* Axial stress is the most compressive: the sample is loaded along 1. */
  CHECK(stress[0] < stress[1] && stress[0] < stress[2], "sigma_11 = %g is the most compressive", stress[0]);
  /* Lateral symmetry: identical lateral strains and a fabric symmetric about axis 1. 1e-10 relative: round-off. */
  CHECK(close_rel(stress[1], stress[2], 1e-10, 1.0), "sigma_22 = %.17g, sigma_33 = %.17g", stress[1], stress[2]);
  CHECK(fabs(stress[3]) < 1e-9 && fabs(stress[4]) < 1e-9 && fabs(stress[5]) < 1e-9, "no shear stress on a shear-free path");
  /* de = (1 + e) d eps_v (tension positive) integrates to 1 + e = (1 + e0) exp(eps_v); the
   * integrator's local error is O(deps^3) per increment, far below 1e-10 relative. */
  CHECK(close_rel(1.0 + statev[ie], (1.0 + e0) * exp(eps_v), 1e-10, 0.0), "void ratio %.17g, expected %.17g", statev[ie],
        (1.0 + e0) * exp(eps_v) - 1.0);
  CHECK(statev[ie] < e0, "net compression densifies: e = %g < e0 = %g", statev[ie], e0);

  st = acst_diagnostics(d, model, stress, statev);
  CHECK(st.code == ACST_OK, "diagnostics: %s", st.message);
  {
    const double G = d[diagnostic_index("G")], K = d[diagnostic_index("K")], p = d[diagnostic_index("p")];
    CHECK(close_rel(p, mean_pressure(stress), 1e-14, 0.0), "p = %.17g from diagnostics", p);
    CHECK(close_rel(d[diagnostic_index("q")], deviatoric_q(stress), 1e-12, 0.0), "q = %.17g from diagnostics",
          d[diagnostic_index("q")]);
    /* The elastic moduli at the current e and p, written here independently (1e-12 relative). */
    CHECK(close_rel(G, shear_modulus(statev[ie], p), 1e-12, 0.0), "G = %.17g", G);
    CHECK(close_rel(K, bulk_modulus(G), 1e-13, 0.0), "K = %.17g", K);
    CHECK(d[diagnostic_index("R")] > 0.3 && d[diagnostic_index("R")] < 2.0, "stress ratio R = %g after 1.5 %% shear",
          d[diagnostic_index("R")]);
    st = acst_wave_speed(&speed, model, stress, statev, rho);
    CHECK(st.code == ACST_OK, "wave speed: %s", st.message);
    CHECK(close_rel(speed, sqrt((K + 4.0 * G / 3.0) * 1000.0 / rho), 1e-13, 0.0), "wave speed %.17g m/s", speed);
  }
}

/* Every failure: the right code, a non-empty message, and stress and state as they were. */
static void test_bad_inputs(const acst_model* model, const char* json, const double* stress_in, const double* statev_in) {
  double stress[6], statev[ACST_NSTATV], tangent[36], out[ACST_NDIAGNOSTICS], speed = 0.0;
  const double nan_strain[6] = {-1e-4, NAN, 0, 0, 0, 0}, inf_strain[6] = {INFINITY, 0, 0, 0, 0, 0};
  const double good_strain[6] = {-1e-4, 0, 0, 0, 0, 0}, b[3] = {1, 0, 0}, zero_b[3] = {0, 0, 0};
  const int ie = state_index(model, "void_ratio");
  acst_model* bad = (acst_model*)&passed; /* a non-NULL sentinel that creation must overwrite */
  acst_status st;
  char* text;

#define EXPECT_FAILURE(call, expected_code, what)                                                           \
  do {                                                                                                      \
    st = (call);                                                                                            \
    CHECK(st.code == (expected_code), "%s: code %d, expected %d ('%s')", what, st.code, expected_code, st.message); \
    CHECK(st.message[0] != '\0', "%s: empty message", what);                                                \
  } while (0)

  /* Creation. */
  EXPECT_FAILURE(acst_model_create(NULL, json), ACST_INVALID_INPUT, "NULL model pointer");
  EXPECT_FAILURE(acst_model_create(&bad, NULL), ACST_INVALID_INPUT, "NULL JSON text");
  CHECK(bad == NULL, "a failed creation sets *model to NULL");
  bad = (acst_model*)&passed;
  EXPECT_FAILURE(acst_model_create(&bad, "{\"model\": \"ACST\", \"parameters\": {"), ACST_INVALID_INPUT, "invalid JSON");
  CHECK(bad == NULL, "invalid JSON leaves no model");
  text = insert_into_parameters(json, "\"bogus_key\": 1, ");
  CHECK(text != NULL, "building the unknown-key JSON");
  if (text) {
    bad = (acst_model*)&passed;
    EXPECT_FAILURE(acst_model_create(&bad, text), ACST_INVALID_INPUT, "unknown parameter key");
    CHECK(bad == NULL, "unknown key leaves no model");
    CHECK(strstr(st.message, "bogus_key") != NULL, "the message names the unknown key: '%s'", st.message);
    free(text);
  }
  /* An out-of-range value (nu = 0.7 > 0.5) is rejected with a message that names it. */
  text = (char*)malloc(strlen(json) + 1);
  if (text) {
    char* nu;
    strcpy(text, json);
    nu = strstr(text, "\"nu\": 0.1");
    CHECK(nu != NULL, "the guide file spells \"nu\": 0.1");
    if (nu) {
      nu[strlen("\"nu\": 0.")] = '7';
      bad = (acst_model*)&passed;
      EXPECT_FAILURE(acst_model_create(&bad, text), ACST_INVALID_INPUT, "nu out of range");
      CHECK(bad == NULL && strstr(st.message, "nu") != NULL, "the message names nu: '%s'", st.message);
    }
    free(text);
  }

  /* Initial state. */
  {
    double sv[ACST_NSTATV], s[6];
    const double s0[6] = {-100, -100, -100, 0, 0, 0}, tensile[6] = {10, 10, 10, 0, 0, 0};
    EXPECT_FAILURE(acst_initial_state(NULL, s, model, s0, 0.67, b), ACST_INVALID_INPUT, "initial state, NULL statev");
    EXPECT_FAILURE(acst_initial_state(sv, s, NULL, s0, 0.67, b), ACST_INVALID_INPUT, "initial state, NULL model");
    EXPECT_FAILURE(acst_initial_state(sv, s, model, s0, 0.67, NULL), ACST_INVALID_INPUT, "initial state, NULL direction");
    EXPECT_FAILURE(acst_initial_state(sv, s, model, s0, -0.1, b), ACST_INVALID_INPUT, "negative void ratio");
    EXPECT_FAILURE(acst_initial_state(sv, s, model, s0, 0.67, zero_b), ACST_INVALID_INPUT, "zero deposition direction");
    EXPECT_FAILURE(acst_initial_state(sv, s, model, tensile, 0.67, b), ACST_INVALID_INPUT, "tensile initial stress");
  }

#define EXPECT_UNTOUCHED(what)                                                                   \
  CHECK(memcmp(stress, stress_in, sizeof stress) == 0, "%s: stress changed on failure", what); \
  CHECK(memcmp(statev, statev_in, sizeof statev) == 0, "%s: state changed on failure", what)

/* A refusal (as EXPECT_FAILURE) that leaves the stress and the state as they were. */
#define EXPECT_REFUSED_UNTOUCHED(call, expected_code, what) \
  do {                                                       \
    EXPECT_FAILURE(call, expected_code, what);               \
    EXPECT_UNTOUCHED(what);                                  \
  } while (0)

  /* Update: NULL pointers and non-finite strain. */
  memcpy(stress, stress_in, sizeof stress);
  memcpy(statev, statev_in, sizeof statev);
  EXPECT_REFUSED_UNTOUCHED(acst_update(stress, statev, tangent, NULL, model, nan_strain), ACST_INVALID_INPUT, "NaN strain");
  EXPECT_REFUSED_UNTOUCHED(acst_update(stress, statev, NULL, NULL, model, inf_strain), ACST_INVALID_INPUT, "infinite strain");
  EXPECT_REFUSED_UNTOUCHED(acst_update(NULL, statev, NULL, NULL, model, good_strain), ACST_INVALID_INPUT, "NULL stress");
  EXPECT_REFUSED_UNTOUCHED(acst_update(stress, NULL, NULL, NULL, model, good_strain), ACST_INVALID_INPUT, "NULL statev");
  EXPECT_REFUSED_UNTOUCHED(acst_update(stress, statev, NULL, NULL, NULL, good_strain), ACST_INVALID_INPUT, "NULL model");
  EXPECT_REFUSED_UNTOUCHED(acst_update(stress, statev, NULL, NULL, model, NULL), ACST_INVALID_INPUT, "NULL strain");

  /* The same refusals from the turned update, and a NaN stress stays unturned. */
  {
    const double turn[9] = {0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1};
    EXPECT_REFUSED_UNTOUCHED(acst_update_rotated(stress, statev, tangent, NULL, model, turn, nan_strain),
                             ACST_INVALID_INPUT, "turned update, NaN strain");
    EXPECT_REFUSED_UNTOUCHED(acst_update_rotated(stress, statev, NULL, NULL, model, NULL, good_strain),
                             ACST_INVALID_INPUT, "turned update, NULL rotation");
    stress[1] = NAN;
    EXPECT_FAILURE(acst_update_rotated(stress, statev, NULL, NULL, model, turn, good_strain), ACST_NONPHYSICAL_STATE,
                   "turned update, NaN stress");
    CHECK(isnan(stress[1]) && stress[0] == stress_in[0] && stress[3] == stress_in[3],
          "turned update, NaN stress: stress changed on failure");
    memcpy(stress, stress_in, sizeof stress);
  }

  /* Non-physical entry state: NaN stress, negative void ratio. */
  stress[1] = NAN;
  {
    double before[6];
    memcpy(before, stress, sizeof before);
    EXPECT_FAILURE(acst_update(stress, statev, NULL, NULL, model, good_strain), ACST_NONPHYSICAL_STATE, "NaN stress");
    CHECK(memcmp(stress, before, sizeof before) == 0, "NaN stress: stress changed on failure");
    CHECK(memcmp(statev, statev_in, sizeof statev) == 0, "NaN stress: state changed on failure");
  }
  memcpy(stress, stress_in, sizeof stress);
  statev[ie] = -0.5;
  EXPECT_FAILURE(acst_update(stress, statev, NULL, NULL, model, good_strain), ACST_NONPHYSICAL_STATE, "negative void ratio");
  CHECK(statev[ie] == -0.5 && memcmp(stress, stress_in, sizeof stress) == 0, "negative void ratio: arrays changed");
  memcpy(statev, statev_in, sizeof statev);

  /* Batch: a stride below the point size is refused before anything is touched. */
  EXPECT_FAILURE(acst_update_batch(stress, 5, statev, ACST_NSTATV, NULL, NULL, model, 1, good_strain, 6),
                 ACST_INVALID_INPUT, "batch stress stride 5");
  EXPECT_FAILURE(acst_update_batch(stress, 6, statev, ACST_NSTATV - 1, NULL, NULL, model, 1, good_strain, 6),
                 ACST_INVALID_INPUT, "batch state stride below ACST_NSTATV");
  EXPECT_UNTOUCHED("bad batch strides");
  {
    int code = -1;
    EXPECT_FAILURE(acst_update_batch(stress, 6, statev, ACST_NSTATV, &code, NULL, model, 1, nan_strain, 6),
                   ACST_INVALID_INPUT, "batch NaN strain");
    CHECK(code == ACST_INVALID_INPUT, "point status %d", code);
    CHECK(strstr(st.message, "point 0") != NULL, "the batch message names the point: '%s'", st.message);
    EXPECT_UNTOUCHED("batch NaN strain");
  }

  /* Diagnostics and wave speed. */
  EXPECT_FAILURE(acst_diagnostics(NULL, model, stress, statev), ACST_INVALID_INPUT, "diagnostics NULL out");
  EXPECT_FAILURE(acst_diagnostics(out, NULL, stress, statev), ACST_INVALID_INPUT, "diagnostics NULL model");
  EXPECT_FAILURE(acst_wave_speed(&speed, model, stress, statev, 0.0), ACST_INVALID_INPUT, "zero density");
  EXPECT_FAILURE(acst_wave_speed(&speed, model, stress, statev, -1.0), ACST_INVALID_INPUT, "negative density");
  EXPECT_FAILURE(acst_wave_speed(&speed, model, stress, statev, NAN), ACST_INVALID_INPUT, "NaN density");
  EXPECT_FAILURE(acst_wave_speed(NULL, model, stress, statev, 1900.0), ACST_INVALID_INPUT, "wave speed NULL out");

  /* Destroying NULL is allowed, as free(NULL). */
  acst_model_destroy(NULL);
#undef EXPECT_FAILURE
#undef EXPECT_UNTOUCHED
#undef EXPECT_REFUSED_UNTOUCHED
}

int main(void) {
  char* json = read_file(ACST_SOURCE_DIR "/data/parameters/toyoura_acst_guide.json");
  acst_model* model = NULL;
  double stress[6], statev[ACST_NSTATV];
  acst_status st;
  if (!json) {
    fprintf(stderr, "cannot read " ACST_SOURCE_DIR "/data/parameters/toyoura_acst_guide.json\n");
    return 2;
  }
  st = acst_model_create(&model, json);
  CHECK(st.code == ACST_OK && model != NULL, "create: %s", st.message);
  CHECK(st.message[0] == '\0' && st.suggested_step_factor == 1.0, "an OK status has an empty message and factor 1");
  if (model) {
    test_state_layout(model);
    test_initial_state(model, stress, statev);
    test_compression_path(model, stress, statev);
    test_bad_inputs(model, json, stress, statev);
    acst_model_destroy(model);
  }
  free(json);
  printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
