/* Drained triaxial compression of Toyoura sand through the C ABI only (as any host code would
 * use the library). Prints p, q and the volumetric strain at a few axial strains, in the
 * geotechnical convention (compression positive), for dense and loose sand.
 *
 * Usage: drained_triaxial_c_abi PARAMETER_JSON [confining_pressure_kPa]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "acst.h"

static char* read_file(const char* path) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char* text = malloc((size_t)n + 1);
  if (text && fread(text, 1, (size_t)n, f) != (size_t)n) {
    free(text);
    text = NULL;
  }
  if (text) text[n] = '\0';
  fclose(f);
  return text;
}

/* One increment of axial strain de1 (ABI sign: compression negative) with the lateral stresses
 * held: Newton on the two lateral strains with the tangent of the library. */
static int drained_increment(double* stress, double* statev, const acst_model* model, double de1, double* de_lat,
                             double* strain) {
  const double s_lat = stress[1];
  for (int it = 0; it < 30; ++it) {
    double s[6], q[ACST_NSTATV], D[36];
    const double de[6] = {de1, de_lat[0], de_lat[1], 0, 0, 0};
    memcpy(s, stress, sizeof s);
    memcpy(q, statev, sizeof q);
    acst_status st = acst_update(s, q, D, NULL, model, de);
    if (st.code != ACST_OK) {
      fprintf(stderr, "update failed: %s\n", st.message);
      return 1;
    }
    const double r1 = s[1] - s_lat, r2 = s[2] - s_lat;
    const double a = D[7], b = D[8], c = D[13], d = D[14], det = a * d - b * c;
    const double x1 = (d * r1 - b * r2) / det, x2 = (a * r2 - c * r1) / det;
    if (fabs(r1) < 1e-9 * fabs(s_lat) && fabs(r2) < 1e-9 * fabs(s_lat)) {
      memcpy(stress, s, sizeof s);
      memcpy(statev, q, sizeof q);
      strain[0] += de[0];
      strain[1] += de[1];
      strain[2] += de[2];
      return 0;
    }
    de_lat[0] -= x1;
    de_lat[1] -= x2;
  }
  fprintf(stderr, "lateral stress iteration did not converge\n");
  return 1;
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s PARAMETER_JSON [confining_pressure_kPa]\n", argv[0]);
    return 2;
  }
  const double sigma3 = argc > 2 ? atof(argv[2]) : 100.0;
  if (!(sigma3 > 0.0)) {
    fprintf(stderr, "confining pressure must be a positive number of kPa\n");
    return 2;
  }
  char* json = read_file(argv[1]);
  if (!json) {
    fprintf(stderr, "cannot read parameter file '%s'\n", argv[1]);
    return 2;
  }
  acst_model* model = NULL;
  acst_status st = acst_model_create(&model, json);
  free(json);
  if (st.code != ACST_OK) {
    fprintf(stderr, "%s: %s\n", argv[1], st.message);
    return 2;
  }
  const double report_at[] = {0.5, 1, 2, 5, 10, 20};
  const double void_ratios[] = {0.67, 0.93};
  const char* labels[] = {"dense", "loose"};
  int rc = 0;
  for (int k = 0; k < 2 && rc == 0; ++k) {
    double stress0[6] = {-sigma3, -sigma3, -sigma3, 0, 0, 0}, stress[6], statev[ACST_NSTATV];
    const double deposition[3] = {1, 0, 0};
    st = acst_initial_state(statev, stress, model, stress0, void_ratios[k], deposition);
    if (st.code != ACST_OK) {
      fprintf(stderr, "initial state: %s\n", st.message);
      rc = 1;
      break;
    }
    printf("%s sand, e0 = %.2f, sigma3 = %g kPa (compression positive)\n", labels[k], void_ratios[k], sigma3);
    printf("  eps_a[%%]      p[kPa]      q[kPa]   e_v[%%]\n");
    double strain[3] = {0, 0, 0}, de_lat[2] = {0, 0};
    const double de1 = -1e-4;
    int next = 0;
    for (int i = 1; i <= 2000 && rc == 0; ++i) {
      rc = drained_increment(stress, statev, model, de1, de_lat, strain);
      const double eps_a = -100.0 * strain[0];
      if (rc == 0 && next < 6 && eps_a >= report_at[next] - 1e-9) {
        const double p = -(stress[0] + stress[1] + stress[2]) / 3.0, q = stress[1] - stress[0];
        const double ev = -100.0 * (strain[0] + strain[1] + strain[2]);
        printf("  %7.2f  %10.2f  %10.2f  %7.3f\n", eps_a, p, q, ev);
        ++next;
      }
    }
  }
  acst_model_destroy(model);
  return rc;
}
