// The project's glue for CalculiX's ccx (docs/c-abi.md, "CalculiX"): the two user routines ccx calls by
// Fortran name, linked into ccx in place of its dummies by build-ccx.
//   umat_    acst_umat, plus what only a host may do: print the reason of a failed update and
//            write its reproducer (acst_umat_reproducer) into the job's folder;
//   sdvini_  the initial state variables, from acst_initial_state on the state described in
//            acst_sdvini.json (the job's folder) or the file named by $ACST_SDVINI.
// This is host code: unlike the library, it prints, and it stops ccx on a bad acst_sdvini.json
// (ccx's own user routines stop it the same way).
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "acst.h"

namespace {

constexpr int reported_failures = 10;  // printed and written, so a failing mesh cannot flood the log
std::atomic<int> failures{0};

void write_reproducer(const double* stress, const double* statev, const double* dstran, int ntens,
                      const double* props, int nprops, const double* drot, int noel, int npt) {
  size_t length = 0;
  if (acst_umat_reproducer(nullptr, &length, stress, statev, dstran, ntens, props, nprops, drot).code != ACST_OK) return;
  std::string text(length, '\0');
  if (acst_umat_reproducer(text.data(), &length, stress, statev, dstran, ntens, props, nprops, drot).code != ACST_OK)
    return;
  text.resize(length - 1);
  // Element and point numbers are integers from ccx: the name cannot leave the job's folder.
  const std::string name = "acst_umat_failure_e" + std::to_string(noel) + "_p" + std::to_string(npt) + ".json";
  const std::string temporary = name + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.flush()) return;
  }
  std::rename(temporary.c_str(), name.c_str());
}

[[noreturn]] void stop(const std::string& file, const std::string& what) {
  std::fprintf(stderr, "*ERROR in acst sdvini_: %s: %s\n", file.c_str(), what.c_str());
  std::exit(2);
}

std::string read_file(const std::filesystem::path& path, const std::string& context) {
  std::ifstream in(path, std::ios::binary);
  if (!in) stop(context, "cannot open " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<double> numbers(const nlohmann::json& j, const char* key, size_t count, const std::string& file) {
  if (!j.contains(key)) stop(file, std::string("missing key /") + key);
  const nlohmann::json& v = j.at(key);
  if (!v.is_array() || v.size() != count) stop(file, "/" + std::string(key) + " must be an array of " + std::to_string(count) + " numbers");
  std::vector<double> out;
  for (const auto& x : v) {
    if (!x.is_number()) stop(file, "/" + std::string(key) + " must hold numbers only");
    out.push_back(x.get<double>());
  }
  return out;
}

// The state variables every integration point starts from (one homogeneous initial state).
std::vector<double> initial_state_from_file() {
  const char* env = std::getenv("ACST_SDVINI");
  const std::filesystem::path path = env && *env ? env : "acst_sdvini.json";
  const std::string file = path.string();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_file(path, file));
  } catch (const nlohmann::json::exception& e) {
    stop(file, std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) stop(file, "must hold a JSON object");
  for (const auto& item : j.items())
    if (item.key() != "material_file" && item.key() != "stress" && item.key() != "void_ratio" &&
        item.key() != "deposition_direction")
      stop(file, "unknown key /" + item.key() +
                     " (allowed: material_file, stress, void_ratio, deposition_direction)");
  if (!j.contains("material_file") || !j.at("material_file").is_string())
    stop(file, "/material_file must be a string: the material's JSON file, relative to this file's folder");
  if (!j.contains("void_ratio") || !j.at("void_ratio").is_number()) stop(file, "/void_ratio must be a number");
  const std::vector<double> stress = numbers(j, "stress", 6, file);
  const std::vector<double> direction = numbers(j, "deposition_direction", 3, file);
  const std::filesystem::path material = path.parent_path() / j.at("material_file").get<std::string>();
  const std::string material_text = read_file(material, file + ": /material_file");

  acst_model* model = nullptr;
  acst_status st = acst_model_create(&model, material_text.c_str());
  if (st.code != ACST_OK) stop(file, material.string() + ": " + st.message);
  std::vector<double> statev(ACST_NSTATV);
  double stress_out[6];
  st = acst_initial_state(statev.data(), stress_out, model, stress.data(), j.at("void_ratio").get<double>(),
                          direction.data());
  acst_model_destroy(model);
  if (st.code != ACST_OK) stop(file, st.message);
  return statev;
}

}  // namespace

extern "C" void umat_(double* stress, double* statev, double* ddsdde, double*, double*, double*, double*, double*,
                      double*, double*, const double*, const double* dstran, const double*, const double*,
                      const double*, const double*, const double*, const double*, const char*, const int*,
                      const int*, const int* ntens, const int* nstatv, const double* props, const int* nprops,
                      const double*, const double* drot, double* pnewdt, const double*, const double*, const double*,
                      const int* noel, const int* npt, const int*, const int*, const int*, const int* kinc, size_t) {
  const acst_status st = acst_umat(stress, statev, ddsdde, dstran, *ntens, *nstatv, props, *nprops, drot, pnewdt);
  if (st.code == ACST_OK) return;
  const int n = failures.fetch_add(1);
  if (n >= reported_failures) return;
  std::fprintf(stderr, "acst umat_: element %d, integration point %d, increment %d: %s (PNEWDT %g)%s\n", *noel, *npt,
               *kinc, st.message, *pnewdt,
               n + 1 == reported_failures ? "; further failures are not reported" : "");
  write_reproducer(stress, statev, dstran, *ntens, props, *nprops, drot, *noel, *npt);
}

extern "C" void sdvini_(double* statev, const double*, const int* nstatv, const int*, const int*, const int*,
                        const int*, const int*) {
  static const std::vector<double> initial = initial_state_from_file();  // once, thread-safe
  if (*nstatv < ACST_NSTATV)
    stop("*DEPVAR", "the ACST umat_ needs at least " + std::to_string(ACST_NSTATV) + " state variables, the deck gives " +
                        std::to_string(*nstatv));
  for (int i = 0; i < *nstatv; ++i) statev[i] = i < ACST_NSTATV ? initial[i] : 0.0;
}
