// The CSV table of an element test.
#include <charconv>
#include <cstdio>
#include <stdexcept>

#include "acst/fabric.hpp"
#include "acst/integration/options.hpp"
#include "acst_common/one_line.hpp"
#include "acst_driver/number_format.hpp"
#include "acst_driver/output.hpp"
#include "acst/scene_units.hpp"

namespace acst::driver {

namespace {

void put(std::string& out, double v) {
  append_number(out, v);
  out += ',';
}

void put(std::string& out, long v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
  out += ',';
}

std::string vec(const Sym& v) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "[%g, %g, %g, %g, %g, %g]", v[0], v[1], v[2], v[3], v[4], v[5]);
  return buf;
}

}  // namespace

std::string csv_comments(const ElementScene& scene) {
  const Parameters& par = scene.material->parameters();
  const integration::Options& opt = scene.material->options();
  std::string out;
  // Names and messages from outside stay on their comment line: a line break would start a
  // line that readers take for the header row or data.
  using common::one_line;
  out += "# acst_element: element test '" + scene.output.name + "'" +
         (scene.source.empty() ? std::string() : " from " + one_line(scene.source)) + "\n";
  char buf[512];
  // The file name apart: a long one must not cut the line's end off in the fixed buffer.
  std::snprintf(buf, sizeof buf, ", model %s, integrator %s stol %g\n", par.variant == Variant::isotropic ? "isotropic" : "ACST",
                integration::scheme_name(opt.scheme), opt.stol);
  out += "# material: " + one_line(scene.material_source) + buf;
  Eigen::Vector3d b = unit_direction(scene.initial.deposition_direction);  // as the fabric takes it
  for (int i = 0; i < 3; ++i) b[i] = std::abs(b[i]) < 1e-12 ? 0.0 : b[i];  // cos(90 deg) prints as 0
  std::snprintf(buf, sizeof buf,
                "# initial state: sigma = %s kPa, e0 = %.4f, bedding angle %.4g deg (deposition direction [%.4g, %.4g, %.4g])%s\n",
                vec(scene.initial.stress).c_str(), scene.initial.void_ratio, scene.initial.bedding_angle_deg, b[0], b[1],
                b[2], scene.initial.fabric ? ", fabric given" : "");
  out += buf;
  for (const auto& lab : scene.lab_data) out += "# lab data: " + one_line(lab) + "\n";
  out +=
      "# convention: geotechnical, COMPRESSION POSITIVE for stresses and strains; test frame: axis 1 = axial (major "
      "loading), 2 = intermediate (eps_22 = 0 in plane strain), 3 = minor lateral\n"
      "# units: stresses in kPa (effective); strains in percent; shear strains are ENGINEERING gamma_ij = 2 eps_ij; "
      "numbers to 10 significant digits\n"
      "# p = (sigma_11 + sigma_22 + sigma_33)/3; q = sqrt(3/2 s:s), signed: negative when sigma_11 < (sigma_22 + "
      "sigma_33)/2 (extension); stress_ratio = q/p\n"
      "# e_v = eps_11 + eps_22 + eps_33; e_q = sqrt(2/3 e:e), e the strain deviator; eps_a = eps_11 (axial strain)\n"
      "# psi = e - e_c(p); zeta = psi - e_A (A - 1); A = F:n; F_norm = |F| (fabric)\n"
      "# u_excess_kPa: excess pore pressure accumulated over undrained steps = change of total minus effective mean "
      "stress with the total lateral stress held: du = -(d sigma_22 + d sigma_33)/2 (0 in drained steps)\n"
      "# time: each step takes one unit; step: index in /steps; cycle: cycle of a repeat block (1 otherwise); stage: "
      "step within the repeat block\n"
      "# substeps: accepted material substeps; iterations: Newton iterations (all cut-back pieces); cutbacks: "
      "halvings of the increment; status: start | ok | cutback | exit:<condition>\n";
  return out;
}

std::string csv_failure_line(const std::string& message) { return "# RUN FAILED: " + common::one_line(message) + "\n"; }

const std::string& csv_column_names() {
  static const std::string names =
      "increment,time,step,cycle,stage,eps_11_pct,eps_22_pct,eps_33_pct,gamma_12_pct,gamma_13_pct,gamma_23_pct,"
      "sigma_11_kPa,sigma_22_kPa,sigma_33_kPa,sigma_12_kPa,sigma_13_kPa,sigma_23_kPa,p_kPa,q_kPa,stress_ratio,"
      "e_v_pct,e_q_pct,eps_a_pct,void_ratio,psi,zeta,A,F_norm,u_excess_kPa,substeps,iterations,cutbacks,status\n";
  return names;
}

void append_csv_row(std::string& out, const Record& r) {
  put(out, r.increment);
  put(out, r.time);
  put(out, static_cast<long>(r.step));
  put(out, static_cast<long>(r.cycle));
  put(out, static_cast<long>(r.stage));
  for (int i = 0; i < 6; ++i) put(out, units::strain_to_scene(r.strain[i], i));
  for (int i = 0; i < 6; ++i) put(out, r.stress[i]);
  put(out, mean_stress(r.stress));
  put(out, signed_q(r.stress));
  put(out, stress_ratio_of(r.stress));
  put(out, volumetric_strain_pct(r.strain));
  put(out, deviatoric_strain_pct(r.strain));
  put(out, axial_strain_pct(r.strain));
  put(out, r.void_ratio);
  put(out, r.psi);
  put(out, r.zeta);
  put(out, r.A);
  put(out, r.fabric_norm);
  put(out, r.u_excess);
  put(out, static_cast<long>(r.substeps));
  put(out, static_cast<long>(r.iterations));
  put(out, static_cast<long>(r.cutbacks));
  out += r.status;
  out += '\n';
}

std::string csv_text(const ElementScene& scene, const RunResult& result) {
  std::string out = csv_comments(scene);
  out.reserve(out.size() + 400 * (result.records.size() + 2));
  if (!result.ok) out += csv_failure_line(result.message);
  out += csv_column_names();
  for (const Record& r : result.records) append_csv_row(out, r);
  return out;
}

}  // namespace acst::driver
