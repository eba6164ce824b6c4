#include "acst_footing_tool/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/one_line.hpp"
#include "acst_common/plain_stem.hpp"
#include "acst_footing_tool/fields.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;

namespace {

void put(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v + 0.0);  // + 0.0: -0 is written 0
  out += buf;
}

void scalar_array(std::string& out, const char* name, const std::vector<double>& v) {
  out += "<DataArray type=\"Float64\" Name=\"";
  out += name;
  out += "\" format=\"ascii\">\n";
  for (double x : v) put(out, x), out += ' ';
  out += "\n</DataArray>\n";
}

}  // namespace

bool is_run_output_name(const std::string& name) {
  const auto starts = [&](const std::string& p) { return name.compare(0, p.size(), p) == 0; };
  const auto ends = [&](const std::string& s) {
    return name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
  };
  const auto middle = [&](std::size_t head, std::size_t tail, const char* allowed) {
    return name.size() > head + tail && name.find_first_not_of(allowed, head) >= name.size() - tail;
  };
  for (const char* stem : {"load_settlement", "load_settlement.partial", "load_settlement.failed"})
    for (const char* ext : {".csv", ".png", ".gp"})
      if (name == std::string(stem) + ext) return true;
  for (const char* fixed : {"particles.pvd", "summary.json", "checkpoint.bin", "failure_reproducer.json",
                            "particle_histories.png", "particle_histories.gp"})
    if (name == fixed) return true;
  if (starts("particles_") && ends(".vtp") && middle(10, 4, "0123456789")) return true;
  if (starts("particle_") && ends(".csv") && common::is_plain_stem(name.substr(9, name.size() - 13))) return true;
  for (const char* figure : {"shear_strain_", "displacement_", "fabric_norm_", "N_", "void_ratio_"})
    for (const char* ext : {".png", ".gp", ".csv"})
      if (starts(figure) && ends(ext) &&
          middle(std::string(figure).size(), std::string(ext).size(),
                 "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789._-"))
        return true;
  return common::is_temporary_name(name);
}

std::string load_csv_text(const Scene& scene, const std::vector<LoadRecord>& history) {
  std::string out = "# acst_mpm load-settlement record of scene '" + common::one_line(scene.name) + "'\n";
  out += "# loads per metre out of plane, averaged over each period of " + std::to_string(scene.solver.xpic_every) +
         " steps (one row per step with every_step_csv); V: vertical load of the footing on the soil (positive "
         "downward), H: horizontal (positive toward +x), q = V/B; M: moment of the footing's load on the soil about "
         "the centre of its base (counter-clockwise positive); S: settlement of the footing (positive downward); "
         "penetration: deepest overlap of a particle with the contact footing\n";
  out += "step,time_s,S_m,S_over_B,V_kN_per_m,H_kN_per_m,M_kNm_per_m,q_kPa,penetration_m,kinetic_J_per_m,"
         "footing_work_J_per_m,kinetic_over_work\n";
  for (const LoadRecord& r : history) {
    out += std::to_string(r.step) + ',';
    for (double v : {r.time, r.settlement, r.S_over_B, r.V_kN_per_m, r.H_kN_per_m, r.M_kNm_per_m, r.q_kPa,
                     r.penetration_m, r.kinetic_J_per_m, r.footing_work_J_per_m})
      put(out, v), out += ',';
    put(out, r.footing_work_J_per_m > 0.0 ? r.kinetic_J_per_m / r.footing_work_J_per_m : 0.0);
    out += '\n';
  }
  return out;
}

std::string track_csv_text(const Scene& scene, int k, const std::vector<TrackRecord>& rows) {
  const ParticleTrack& t = scene.output.particle_histories[static_cast<std::size_t>(k)];
  std::string out = "# acst_mpm history of particle '" + common::one_line(t.name) + "' of scene '" +
                    common::one_line(scene.name) + "', the one nearest (" + std::to_string(t.x) + ", " +
                    std::to_string(t.y) + ") m at the start\n";
  out += "# material frame (the particle's frame at the start, turned with it), test-frame axes of acst_element: "
         "1 = vertical (y), 2 = out of plane (z), 3 = horizontal (x); compression positive, kPa, strains in % "
         "since the start (engineering shear); x_m, y_m: the particle's position now; rotation_deg: its "
         "accumulated rotation (counter-clockwise)\n";
  out += "step,time_s,S_over_B,x_m,y_m,rotation_deg,eps_11_pct,eps_22_pct,eps_33_pct,gamma_12_pct,gamma_13_pct,"
         "gamma_23_pct,sigma_11_kPa,sigma_22_kPa,sigma_33_kPa,sigma_12_kPa,sigma_13_kPa,sigma_23_kPa,void_ratio,"
         "F11,F22,F33,F12,F13,F23,H,p_kPa,q_kPa,eps_v_pct,fabric_norm,N\n";
  // (x, y, z) -> (3, 1, 2): test 11 = yy, 22 = zz, 33 = xx, 12 = yz, 13 = yx, 23 = zx.
  constexpr int from[6] = {1, 2, 0, 5, 3, 4};
  for (const TrackRecord& r : rows) {
    if (r.track != k) continue;
    out += std::to_string(r.step);
    for (double v : {r.time, r.S_over_B, r.x, r.y, r.rotation_rad * 180.0 / M_PI}) out += ',', put(out, v);
    const double strain[6] = {-100.0 * r.strain[1], 0.0, -100.0 * r.strain[0], 0.0, -200.0 * r.strain[2], 0.0};
    for (double v : strain) out += ',', put(out, v);
    for (int i : from) out += ',', put(out, -r.stress[i]);
    out += ',', put(out, r.void_ratio);
    for (int i : from) out += ',', put(out, r.fabric[i]);
    out += ',', put(out, r.H);
    // p and q from the stress (invariants: any frame), compression positive; N as in the maps.
    const double* t = r.stress;
    const double p = -(t[0] + t[1] + t[2]) / 3.0;
    const double J2 = ((t[0] - t[1]) * (t[0] - t[1]) + (t[1] - t[2]) * (t[1] - t[2]) + (t[2] - t[0]) * (t[2] - t[0])) / 6.0 +
                      t[3] * t[3] + t[4] * t[4] + t[5] * t[5];
    for (double v : {p, std::sqrt(3.0 * J2), strain[0] + strain[1] + strain[2], r.fabric_norm,
                     r.fabric_norm > 0.0 ? r.A / r.fabric_norm : 0.0})
      out += ',', put(out, v);
    out += '\n';
  }
  return out;
}

std::string vtp_text(const Simulation& sim) {
  const Particles& P = sim.particles();
  const ParticleFields f = particle_fields(sim);
  std::string out;
  out.reserve(P.n * 400);
  out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n";
  out += "<Piece NumberOfPoints=\"" + std::to_string(P.n) + "\" NumberOfVerts=\"" + std::to_string(P.n) +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  out += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < P.n; ++i) put(out, P.x[i]), out += ' ', put(out, P.y[i]), out += " 0 ";
  out += "\n</DataArray>\n</Points>\n<Verts>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < P.n; ++i) out += std::to_string(i) + ' ';
  out += "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < P.n; ++i) out += std::to_string(i + 1) + ' ';
  out += "\n</DataArray>\n</Verts>\n<PointData Scalars=\"shear_strain\">\n";
  // ParaView's symmetric-tensor order: XX YY ZZ XY YZ XZ (ours: xx yy zz xy xz yz), kPa, tension positive.
  out += "<DataArray type=\"Float64\" Name=\"stress_kPa\" NumberOfComponents=\"6\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < P.n; ++i)
    for (int k : {0, 1, 2, 3, 5, 4}) put(out, P.stress[6 * i + k]), out += ' ';
  out += "\n</DataArray>\n<DataArray type=\"Float64\" Name=\"displacement_m\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < P.n; ++i)
    put(out, P.x[i] - P.x_initial[i]), out += ' ', put(out, P.y[i] - P.y_initial[i]), out += " 0 ";
  out += "\n</DataArray>\n<DataArray type=\"Float64\" Name=\"velocity_m_per_s\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < P.n; ++i) put(out, P.vx[i]), out += ' ', put(out, P.vy[i]), out += " 0 ";
  out += "\n</DataArray>\n";
  scalar_array(out, "p_kPa", f.p);
  scalar_array(out, "q_kPa", f.q);
  scalar_array(out, "shear_strain", f.shear_strain);
  scalar_array(out, "displacement_magnitude_m", f.displacement);
  if (f.sand) {
    scalar_array(out, "void_ratio", f.void_ratio);
    scalar_array(out, "fabric_norm", f.fabric_norm);
    scalar_array(out, "A", f.A);
    scalar_array(out, "N", f.N);
  }
  out += "<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < P.n; ++i) out += std::to_string(P.material[i]) + ' ';
  out += "\n</DataArray>\n</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return out;
}

std::string pvd_text(const std::string& stem, const std::vector<double>& times) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (std::size_t k = 0; k < times.size(); ++k) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "<DataSet timestep=\"%.10g\" part=\"0\" file=\"%s_%04zu.vtp\"/>\n", times[k],
                  stem.c_str(), k);
    out += buf;
  }
  return out + "</Collection>\n</VTKFile>\n";
}

std::string write_load_figure(const Scene& scene, const std::string& dir, const std::string& csv_file) {
  std::ostringstream gp;
  gp << "# gnuplot script written by acst_mpm for scene " << scene.name << "\n"
     << "set terminal pngcairo size 1100,800 font 'DejaVu Sans,12' noenhanced\n"
     << "if (!exists('png')) png = 'load_settlement.png'\nset output png\n"
     << "set datafile separator ','\nset datafile commentschars '#'\nset datafile columnheaders\n"
     << "set xlabel 'S/B'\nset ylabel 'q = V/B [kPa]'\nset grid\nset key top right\n"
     << "set title " << common::gp_quoted("Strip footing: " + scene.name) << "\n"
     << "plot " << common::gp_quoted(fs::absolute(fs::path(dir) / csv_file).string()) << " using 'S_over_B':'q_kPa' with lines lw 2 lc rgb '#1f3f9f' title 'MPM (ACST C ABI)'";
  if (!scene.output.lab_curve.empty())
    gp << ", " << common::gp_quoted(fs::absolute(scene.output.lab_curve).string())
       << " using 'S_over_B':'q_kPa' with points pt 7 ps 0.5 lc rgb '#c03020' title "
       << common::gp_quoted(scene.output.lab_label.empty() ? "lab data" : scene.output.lab_label);
  gp << "\n";
  return acst::common::run_gnuplot(gp.str(), (fs::path(dir) / "load_settlement.gp").string(),
                                   (fs::path(dir) / "load_settlement.png").string());
}

std::string write_history_figure(const Scene& scene, const std::string& dir) {
  std::ostringstream gp;
  gp << "# gnuplot script written by acst_mpm for scene " << scene.name << "\n"
     << "set terminal pngcairo size 1400,1000 font 'DejaVu Sans,11' noenhanced\n"
     << "if (!exists('png')) png = 'particle_histories.png'\nset output png\n"
     << "set datafile separator ','\nset datafile commentschars '#'\nset datafile columnheaders\n"
     << "set multiplot layout 2,2 title " << common::gp_quoted("Particle histories: " + scene.name) << "\n"
     << "set grid\nset xlabel 'S/B'\nset key top left\n";
  const std::pair<const char*, const char*> panels[] = {
      {"q_kPa", "q [kPa]"}, {"eps_v_pct", "e_v [%] (compression +)"}, {"fabric_norm", "|F|"}, {"N", "N = F:n / |F|"}};
  for (const auto& [column, label] : panels) {
    gp << "set ylabel " << common::gp_quoted(label) << "\nplot ";
    for (std::size_t k = 0; k < scene.output.particle_histories.size(); ++k) {
      const std::string& name = scene.output.particle_histories[k].name;
      gp << (k ? ", " : "") << common::gp_quoted(fs::absolute(fs::path(dir) / ("particle_" + name + ".csv")).string())
         << " using 'S_over_B':'" << column << "' with lines lw 2 title " << common::gp_quoted(name);
    }
    gp << "\n";
  }
  gp << "unset multiplot\n";
  return acst::common::run_gnuplot(gp.str(), (fs::path(dir) / "particle_histories.gp").string(),
                                   (fs::path(dir) / "particle_histories.png").string());
}

std::string write_contour_figure(const std::string& dir, const std::string& stem, const std::string& title,
                                 const std::string& label, double cell, const std::vector<double>& x,
                                 const std::vector<double>& y, const std::vector<double>& value, bool signed_unit) {
  std::string data = "x_m,y_m,value\n";
  for (std::size_t i = 0; i < x.size(); ++i) {
    put(data, x[i]), data += ',', put(data, y[i]), data += ',', put(data, value[i]);
    data += '\n';
  }
  const std::string csv = (fs::path(dir) / (stem + ".csv")).string();
  try {
    acst::common::write_file_atomically(csv, data);
  } catch (const std::exception& e) {
    return e.what();
  }
  double cap = 0.0;  // colour range to the 99th percentile so a few extreme particles don't wash it out
  if (!value.empty()) {
    std::vector<double> v(value);
    std::nth_element(v.begin(), v.begin() + static_cast<long>(0.99 * (v.size() - 1)), v.end());
    cap = v[static_cast<std::size_t>(0.99 * (v.size() - 1))];
  }
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1400,800 font 'DejaVu Sans,12' noenhanced\n"
     << "if (!exists('png')) png = " << common::gp_quoted(stem + ".png") << "\nset output png\n"
     << "set datafile separator ','\nset datafile columnheaders\nset size ratio -1\n"
     << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset cblabel " << common::gp_quoted(label) << "\n"
     << "set title " << common::gp_quoted(title) << "\nset palette rgb 33,13,10\n";
  if (signed_unit)
    gp << "set cbrange [-1:1]\n";
  else if (cap > 0.0)
    gp << "set cbrange [0:" << cap << "]\n";
  gp << "d = " << 0.5 * cell << "\nplot " << common::gp_quoted(fs::absolute(csv).string())
     << " using 1:2:($1-d):($1+d):($2-d):($2+d):3 with boxxyerror fs solid noborder fc palette notitle\n";
  return acst::common::run_gnuplot(gp.str(), (fs::path(dir) / (stem + ".gp")).string(),
                                   (fs::path(dir) / (stem + ".png")).string());
}

}  // namespace acst::mpm
