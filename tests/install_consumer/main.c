/* Consumer of the installed library through the C ABI: create a model from a parameter file,
 * initialise a state and run one compressive update. Exit 0 when the update behaves. */
#include <acst.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  FILE* f;
  long n;
  char* json;
  acst_model* model = NULL;
  acst_status st;
  double stress[6], statev[ACST_NSTATV];
  const double s0[6] = {-100, -100, -100, 0, 0, 0}, b[3] = {0, 0, 1};
  const double de[6] = {0, 0, -1e-4, 0, 0, 0}; /* tension positive: compression along 3 */
  if (argc < 2 || !(f = fopen(argv[1], "rb"))) {
    fprintf(stderr, "usage: consumer_c PARAMETER_JSON\n");
    return 2;
  }
  fseek(f, 0, SEEK_END);
  n = ftell(f);
  fseek(f, 0, SEEK_SET);
  json = (char*)malloc((size_t)n + 1);
  if (!json || fread(json, 1, (size_t)n, f) != (size_t)n) return 2;
  json[n] = '\0';
  fclose(f);

  st = acst_model_create(&model, json);
  free(json);
  if (st.code != ACST_OK) {
    fprintf(stderr, "create: %s\n", st.message);
    return 1;
  }
  st = acst_initial_state(statev, stress, model, s0, 0.7, b);
  if (st.code == ACST_OK) st = acst_update(stress, statev, NULL, NULL, model, de);
  acst_model_destroy(model);
  if (st.code != ACST_OK) {
    fprintf(stderr, "update: %s\n", st.message);
    return 1;
  }
  /* Compression along 3 makes sigma_33 the most compressive (most negative) component. */
  if (!(stress[2] < -100.0 && stress[2] < stress[0] && stress[2] < stress[1])) {
    fprintf(stderr, "unexpected stress after compression: %g %g %g\n", stress[0], stress[1], stress[2]);
    return 1;
  }
  printf("consumer_c: sigma = (%g, %g, %g) kPa\n", stress[0], stress[1], stress[2]);
  return 0;
}
