// The umat_ in a real finite-element host: CalculiX's ccx, built by materials/calculix/build-ccx
// with the project's glue, runs the decks of data/calculix/ and is compared with the element
// driver on the same path (docs/c-abi.md, "CalculiX"). CalculiX speaks the Abaqus convention (tension
// positive, tensor shear in its printed strains); the driver the model's (compression positive):
// the one conversion here is the sign.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "acst/parameters.hpp"
#include "acst_driver/runner.hpp"
#include "acst_driver/scene.hpp"
#include "scratch.hpp"
#include "test_materials.hpp"

namespace {

namespace fs = std::filesystem;
using Voigt = std::array<double, 6>;

const fs::path decks = fs::path(ACST_SOURCE_DIR) / "data" / "calculix";

// What one ccx job left: its exit status, its log, and the printed blocks of its .dat file.
struct CcxJob {
  int exit_code = -1;
  std::string log;
  fs::path folder;
  std::string name;
  fs::path file(const std::string& extension) const { return folder / (name + extension); }
};

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

CcxJob run_ccx(const std::string& deck, const fs::path& sdvini = decks / "acst_sdvini.json") {
  CcxJob job;
  job.name = deck;
  job.folder = acst::test::scratch_folder("calculix_" + deck);
  for (const auto& entry : fs::directory_iterator(decks))
    if (entry.path().extension() == ".inp") fs::copy_file(entry.path(), job.folder / entry.path().filename());
  // Deck names are the test's own constants; the folder is a scratch folder of plain names.
  const std::string command = "cd '" + job.folder.string() + "' && ACST_SDVINI='" + sdvini.string() +
                              "' OMP_NUM_THREADS=1 '" + std::string(ACST_CCX) + "' -i " + deck + " > ccx.log 2>&1";
  const int status = std::system(command.c_str());
  job.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  job.log = read_all(job.folder / "ccx.log");
  return job;
}

// The blocks ccx prints for `what` ("stresses", "strains"): time -> one row per integration point.
std::map<double, std::vector<Voigt>> printed(const CcxJob& job, const std::string& what) {
  std::map<double, std::vector<Voigt>> blocks;
  std::istringstream in(read_all(job.file(".dat")));
  std::string line;
  std::vector<Voigt>* block = nullptr;
  while (std::getline(in, line)) {
    if (line.find(" (elem") != std::string::npos || line.find(" for set ") != std::string::npos) {
      block = line.find(" " + what + " (elem") != std::string::npos ? &blocks[std::stod(line.substr(line.rfind(' ') + 1))]
                                                                     : nullptr;
      continue;
    }
    std::istringstream row(line);
    int element, point;
    Voigt v;
    if (block && row >> element >> point >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5]) block->push_back(v);
  }
  return blocks;
}

// The .sta summary: increments, Newton iterations and attempts beyond the first (cut-backs).
struct Increments {
  int increments = 0, iterations = 0, cutbacks = 0;
  double final_time = 0.0;
};

Increments increment_summary(const CcxJob& job) {
  Increments s;
  std::istringstream in(read_all(job.file(".sta")));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    int step, inc, iterations;
    std::string attempt;
    double total;
    if (!(row >> step >> inc >> attempt >> iterations >> total)) continue;
    ++s.increments;
    s.iterations += iterations;
    s.cutbacks += std::stoi(attempt) - 1;  // "2U": the second attempt, after one cut-back
    s.final_time = total;
  }
  return s;
}

// The umat_ PROPS of an included material file: the numbers after *USER MATERIAL.
std::vector<double> deck_props(const std::string& include) {
  std::istringstream in(read_all(decks / include));
  std::string line;
  std::vector<double> props;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("**", 0) == 0) continue;
    if (line.rfind("*", 0) == 0) {
      inside = line.rfind("*USER MATERIAL", 0) == 0;
      continue;
    }
    if (!inside) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    for (double v; row >> v;) props.push_back(v);
  }
  return props;
}

// The driver's material for exactly the deck's PROPS (the integrator options as umat_ reads them).
nlohmann::json material_of(const std::vector<double>& props) {
  nlohmann::json parameters;
  for (int i = 0; i < acst::parameter_count; ++i) parameters[acst::parameter_table[i].name] = props.at(i);
  if (props.size() > 22) parameters["lode_form"] = props[22];  // PROPS(23)
  return {{"model", "ACST"}, {"parameters", parameters}, {"integrator", {{"scheme", "ME"}, {"stol", props.at(19)}}}};
}

// Runs the driver on `steps` from the state of acst_sdvini.json; records by time (one unit per step).
std::map<double, acst::driver::Record> driver_run(const nlohmann::json& steps, const std::string& include) {
  const nlohmann::json sdvini = nlohmann::json::parse(read_all(decks / "acst_sdvini.json"));
  std::vector<double> stress = sdvini.at("stress");
  for (double& s : stress) s = -s;  // the ABI's tension positive -> the scene's compression positive
  const nlohmann::json scene = {
      {"material", material_of(deck_props(include))},
      {"initial_state",
       {{"stress", stress}, {"void_ratio", sdvini.at("void_ratio")}, {"deposition_direction", sdvini.at("deposition_direction")}}},
      {"steps", steps},
      {"output", {{"plot", false}}}};
  const acst::driver::RunResult r =
      acst::driver::run_scene(acst::driver::parse_scene(scene.dump(), fs::temp_directory_path().string(), "calculix"));
  EXPECT_TRUE(r.ok) << r.message;
  std::map<double, acst::driver::Record> by_time;
  for (const auto& rec : r.records) by_time[rec.time] = rec;
  return by_time;
}

const acst::driver::Record* at_time(const std::map<double, acst::driver::Record>& records, double t) {
  const auto it = records.lower_bound(t - 1e-9);
  return it != records.end() && std::abs(it->first - t) < 1e-9 ? &it->second : nullptr;
}

// 1e-5 of the largest stress, the goal for homogeneous tests: the integrator and the Newton
// iterations of the two codes differ only by their tolerances (1e-10 in the decks, 1e-8 in the
// driver), and ccx prints seven digits (5e-7 relative).
constexpr double relative = 1e-5;

// Every printed point of a homogeneous one-element deck against the driver on the same path.
void expect_homogeneous_match(const CcxJob& job, const nlohmann::json& steps, int expected_increments,
                              const std::string& include = "acst_material.inp",
                              const std::function<Voigt(const Voigt&, double)>& to_material_frame = {}) {
  ASSERT_EQ(job.exit_code, 0) << job.log;
  const auto stresses = printed(job, "stresses");
  ASSERT_EQ(static_cast<int>(stresses.size()), expected_increments);
  const auto driver = driver_run(steps, include);
  int compared = 0;
  double worst = 0.0;  // the largest difference relative to the largest stress, printed
  for (const auto& [time, points] : stresses) {
    const acst::driver::Record* rec = at_time(driver, time);
    ASSERT_NE(rec, nullptr) << "the driver has no row at time " << time;
    const double scale = rec->stress.cwiseAbs().maxCoeff();
    ASSERT_EQ(points.size(), 8u);
    for (const Voigt& printed_stress : points) {
      const Voigt s = to_material_frame ? to_material_frame(printed_stress, time) : printed_stress;
      for (int i = 0; i < 6; ++i) {
        ASSERT_NEAR(-s[i], rec->stress[i], relative * scale) << "stress " << i << " at time " << time;
        worst = std::max(worst, std::abs(-s[i] - rec->stress[i]) / scale);
      }
    }
    ++compared;
  }
  EXPECT_EQ(compared, expected_increments);
  std::printf("%s: %d increments, largest difference from the driver %.1e of the largest stress\n", job.name.c_str(),
              compared, worst);
}

TEST(CalculixDecks, PropsAreTheCalibratedSet) {
  const nlohmann::json set =
      nlohmann::json::parse(acst::test::read_text("data/parameters/toyoura_acst_calibrated.json")).at("parameters");
  for (const char* include : {"acst_material.inp", "acst_material_nl.inp"}) {
    const std::vector<double> props = deck_props(include);
    ASSERT_EQ(props.size(), 23u) << include;
    for (int i = 0; i < acst::parameter_count; ++i) {
      const double v = set.at(acst::parameter_table[i].name).get<double>();
      EXPECT_NEAR(props[i], v, 1e-11 * std::abs(v)) << include << " PROPS(" << i + 1 << ")";  // 12 printed digits
    }
    EXPECT_EQ(props[21], std::string(include) == "acst_material.inp" ? 0.0 : 1.0) << include << " PROPS(22)";
    EXPECT_EQ(props[22], set.value("lode_form", 0.0)) << include << " PROPS(23): the set's Lode form";
  }
}

TEST(Calculix, DrainedTriaxialMatchesTheDriver) {
  const CcxJob job = run_ccx("triaxial_drained");
  expect_homogeneous_match(job, {{{"preset", "drained_triaxial_compression"}, {"axial_strain_pct", 15}, {"increments", 100}}},
                           100);
  // The strains too (tensor shear printed): the lateral strains are the driver's unknowns.
  const auto strains = printed(job, "strains");
  const auto driver = driver_run({{{"preset", "drained_triaxial_compression"}, {"axial_strain_pct", 15}, {"increments", 100}}},
                                 "acst_material.inp");
  for (const auto& [time, points] : strains)
    for (int i = 0; i < 3; ++i)
      ASSERT_NEAR(-points.front()[i], at_time(driver, time)->strain[i], relative * 0.15) << "strain " << i << " at " << time;
  const Increments inc = increment_summary(job);
  EXPECT_EQ(inc.cutbacks, 0);
  EXPECT_LE(inc.iterations, 3 * inc.increments) << "Newton should converge in a few iterations per increment";
}

// Plane (i, j): u_i = gamma x_j; the normal stress on x_j held, every other strain zero.
void simple_shear(const std::string& deck, const std::string& shear, const std::string& held) {
  nlohmann::json control;
  for (const char* c : {"11", "22", "33", "12", "13", "23"}) control[c] = {{"strain_pct", 0}};
  control[held] = {{"stress", 0}};
  control[shear] = {{"strain_pct", -10}};  // CalculiX's +10 % engineering shear, compression positive
  expect_homogeneous_match(run_ccx(deck), {{{"control", control}, {"increments", 100}}}, 100);
}

TEST(Calculix, SimpleShearIn12MatchesTheDriver) { simple_shear("simple_shear_12", "12", "22"); }
TEST(Calculix, SimpleShearIn23MatchesTheDriver) { simple_shear("simple_shear_23", "23", "33"); }
TEST(Calculix, SimpleShearIn31MatchesTheDriver) { simple_shear("simple_shear_31", "13", "11"); }

// NLGEOM through ABAQUSNL: umat_ sees ln U of F = I + gamma e1 (x) e2 and the stress R^T sigma R
// (docs/c-abi.md, "CalculiX"). The driver is fed the same logarithmic strains, increment by increment, as
// a strain path; the printed Cauchy stress is turned back into the material frame with R.
TEST(Calculix, NlgeomSimpleShearMatchesTheDriverInTheMaterialFrame) {
  constexpr double gamma_end = 0.4;
  constexpr int increments = 80;
  auto deformation = [](double gamma) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 1) = gamma;
    return F;
  };
  auto stretch = [](const Eigen::Matrix3d& F, bool logarithm) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(F.transpose() * F);
    const Eigen::Vector3d l = eig.eigenvalues();
    const Eigen::Vector3d f = logarithm ? Eigen::Vector3d(0.5 * l.array().log()) : Eigen::Vector3d(l.array().sqrt());
    return Eigen::Matrix3d(eig.eigenvectors() * f.asDiagonal() * eig.eigenvectors().transpose());
  };
  const fs::path csv = acst::test::scratch_folder("calculix_lnU") / "log_strain.csv";
  {
    std::ofstream out(csv);
    out << "eps_11_pct,eps_22_pct,eps_33_pct,gamma_12_pct,gamma_13_pct,gamma_23_pct\n";
    out.precision(17);
    for (int n = 1; n <= increments; ++n) {
      const Eigen::Matrix3d E = stretch(deformation(gamma_end * n / increments), true);
      // compression positive, percent, engineering shear
      out << -100 * E(0, 0) << ',' << -100 * E(1, 1) << ',' << -100 * E(2, 2) << ',' << -200 * E(0, 1) << ','
          << -200 * E(0, 2) << ',' << -200 * E(1, 2) << '\n';
    }
  }
  auto material_frame = [&](const Voigt& s, double time) {
    const Eigen::Matrix3d F = deformation(gamma_end * time);
    const Eigen::Matrix3d R = F * stretch(F, false).inverse();
    Eigen::Matrix3d sigma;
    sigma << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
    const Eigen::Matrix3d m = R.transpose() * sigma * R;
    return Voigt{m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2)};
  };
  expect_homogeneous_match(run_ccx("simple_shear_nlgeom"),
                           {{{"preset", "strain_path_csv"}, {"file", csv.string()}, {"increments_per_row", 1}}},
                           increments, "acst_material_nl.inp", material_frame);
}

// 27 elements between rough platens, automatic increments: the run finishes, and the platens'
// restraint makes the specimen carry more than the homogeneous element test at the same axial
// strain. The iterations and cut-backs are printed for docs/c-abi.md, "CalculiX".
TEST(Calculix, RoughPlatenMeshFinishesAboveTheHomogeneousTest) {
  const CcxJob job = run_ccx("rough_platen_mesh");
  ASSERT_EQ(job.exit_code, 0) << job.log;
  const Increments inc = increment_summary(job);
  EXPECT_NEAR(inc.final_time, 1.0, 1e-9);
  std::printf("rough platen mesh: %d increments, %d Newton iterations (%.2f per increment), %d cut-backs\n",
              inc.increments, inc.iterations, double(inc.iterations) / inc.increments, inc.cutbacks);
  // The last "total force" block: the platen's reaction (kN on the quarter's 1 m^2).
  std::istringstream in(read_all(job.file(".dat")));
  std::string line;
  double axial = 0.0;
  bool next = false;
  while (std::getline(in, line)) {
    if (line.find("total force") != std::string::npos) next = true;
    std::istringstream row(line);
    double fx;
    if (next && row >> fx) {
      axial = -fx;
      next = false;
    }
  }
  const auto driver =
      driver_run({{{"preset", "drained_triaxial_compression"}, {"axial_strain_pct", 10}, {"increments", 100}}},
                 "acst_material.inp");
  const double homogeneous = at_time(driver, 1.0)->stress[0];
  std::printf("platen stress %.1f kPa, homogeneous test %.1f kPa at 10 %% axial strain\n", axial, homogeneous);
  EXPECT_GT(axial, homogeneous);
}

// No step size fixes a void ratio of 0 (the deck leaves out the sdvini_ request): umat_ asks for
// PNEWDT = 1e-6 with a finite DDSDDE, ccx acts on it, cuts back below its minimum and stops with
// its own message; the glue names the reason and leaves a reproducer the driver can read.
TEST(Calculix, UnrecoverableStateStopsTheHostWithItsOwnMessage) {
  const CcxJob job = run_ccx("failure_unrecoverable");
  EXPECT_NE(job.exit_code, 0);
  EXPECT_NE(job.log.find("increment size decrease requested by a material user routine"), std::string::npos) << job.log;
  EXPECT_NE(job.log.find("increment size smaller than minimum"), std::string::npos) << job.log;
  EXPECT_NE(job.log.find("acst umat_: element 1, integration point 1"), std::string::npos) << job.log;
  EXPECT_NE(job.log.find("non-physical"), std::string::npos) << job.log;
  const fs::path reproducer = job.folder / "acst_umat_failure_e1_p1.json";
  ASSERT_TRUE(fs::exists(reproducer));
  const nlohmann::json scene = nlohmann::json::parse(read_all(reproducer));
  EXPECT_EQ(scene.at("initial_state").at("void_ratio").get<double>(), 0.0);
  EXPECT_THROW(acst::driver::parse_scene(scene.dump(), job.folder.string(), "replay"), std::exception)
      << "the driver must refuse the same state";
}

// A bad acst_sdvini.json stops ccx before the first increment with a message naming the key.
TEST(Calculix, BadSdviniFileStopsTheHostNamingTheKey) {
  const fs::path folder = acst::test::scratch_folder("calculix_bad_sdvini");
  nlohmann::json good = nlohmann::json::parse(read_all(decks / "acst_sdvini.json"));
  good["material_file"] = (decks / good.at("material_file").get<std::string>()).string();
  const std::pair<std::string, nlohmann::json> cases[] = {
      {"unknown key /density", [&] { auto j = good; j["density"] = 1.6; return j; }()},
      {"/stress must be an array of 6 numbers", [&] { auto j = good; j["stress"] = {1, 2, 3}; return j; }()},
      {"/void_ratio must be a number", [&] { auto j = good; j.erase("void_ratio"); return j; }()},
  };
  for (const auto& [message, content] : cases) {
    const fs::path file = folder / "sdvini.json";
    std::ofstream(file) << content.dump();
    const CcxJob job = run_ccx("triaxial_drained", file);
    EXPECT_NE(job.exit_code, 0) << message;
    EXPECT_NE(job.log.find("*ERROR in acst sdvini_"), std::string::npos) << job.log;
    EXPECT_NE(job.log.find(message), std::string::npos) << job.log;
  }
}

}  // namespace
